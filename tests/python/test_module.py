"""The hystbench Python module: the command line's work as Python objects,
the command line's numbers, and its error messages as exceptions."""
import json
import os
import subprocess
import tempfile
import unittest
from pathlib import Path

import numpy as np

import hystbench as hb

SOURCE = Path(os.environ["HYSTBENCH_SOURCE_DIR"])
BUILD = Path(hb.__file__).resolve().parents[2]
PROGRAM = BUILD / "hystbench"
DATA = SOURCE / "problems/hammerstein/data/default.csv"
CORPUS = SOURCE / "tests/bad_inputs"
QUICK_FIT = {"restarts": 1, "evaluations": 300, "seed": 2}


def program(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([str(PROGRAM), *map(str, args)], capture_output=True, text=True)


class ReadMeasurement(unittest.TestCase):
    def test_csv_gives_numpy_vectors(self):
        m = hb.read_measurement(DATA)
        self.assertIsInstance(m.t, np.ndarray)
        self.assertEqual(m.t.dtype, np.float64)
        self.assertEqual(m.t.shape, m.u.shape)
        self.assertEqual(m.y.shape, (11000,))
        self.assertAlmostEqual(m.sample_time, 0.001)
        self.assertEqual(len(m.segment), 11000)

    def test_mat_with_struct_paths(self):
        m = hb.read_measurement(CORPUS / "controldesk_record.mat",
                                columns={"t": "rec.X.Data", "u": "rec.Y(1).Data",
                                         "y": "rec.Y(2).Data"})
        np.testing.assert_array_equal(m.u, [0, 1, 2, 1, 0])
        np.testing.assert_array_equal(m.y, [0, 0.5, 1.5, 1, 0.25])

    def test_errors_are_the_command_lines(self):
        with self.assertRaises(hb.InputError) as caught:
            hb.read_measurement(CORPUS / "mat_complex_y.mat")
        self.assertIn("is complex", str(caught.exception))
        self.assertIsInstance(caught.exception, ValueError)
        with self.assertRaisesRegex(hb.InputError, "no column 'time'"):
            hb.read_measurement(CORPUS / "good.csv", columns="t=time")


    def test_lab_files_give_their_units(self):
        m = hb.read_measurement(CORPUS / "lab_german_ms.csv")
        np.testing.assert_array_equal(m.t, [0, 0.001, 0.002])
        np.testing.assert_array_equal(m.u, [0, 1.5, 2])
        self.assertEqual((m.u_unit, m.y_unit), ("V", "µm"))
        m = hb.read_measurement(CORPUS / "lab_tab.tsv", delimiter="tab")
        np.testing.assert_array_equal(m.y, [0, 0.5, 1.5])

    def test_the_namespace_lists_the_api_only(self):
        self.assertNotIn("np", dir(hb))
        self.assertNotIn("json", dir(hb))
        self.assertIn("fit", dir(hb))


class Commands(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.dir = Path(cls.tmp.name)
        cls.fit = hb.fit(DATA, "hysteresis,msd", out=cls.dir / "fit", **QUICK_FIT)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_fit_has_rmse_and_named_parameters(self):
        self.assertEqual(self.fit.model, "hysteresis,msd")
        self.assertGreater(self.fit.rmse, 0)
        self.assertIn("msd.period", self.fit.parameters)
        self.assertEqual(self.fit.parameters["gain"],
                         self.fit.record["parameters"][0]["value"])

    def test_fit_equals_the_programs_to_the_last_bit(self):
        out = self.dir / "program_fit"
        args = [f"--{k} {v}".split() for k, v in QUICK_FIT.items()]
        r = program("fit", "--data", DATA, "--model", "hysteresis,msd", "--out", out,
                    *[w for a in args for w in a])
        self.assertEqual(r.returncode, 0, r.stderr)
        record = json.loads((out / "fit.json").read_text())
        self.assertEqual(record["parameters"], self.fit.record["parameters"])
        self.assertEqual(record["errors"], self.fit.record["errors"])

    def test_compare_returns_the_model_output(self):
        c = hb.compare(DATA, self.fit)
        self.assertEqual(c.y_model.shape, (11000,))
        # The data as compare scored them, back from normalised units.
        np.testing.assert_allclose(c.y, hb.read_measurement(DATA).y, rtol=1e-15, atol=0)
        residual = c.y - c.y_model
        self.assertAlmostEqual(c.rmse, float(np.sqrt(np.mean(residual ** 2))), places=12)

    def test_arrays_are_taken_where_a_file_is(self):
        m = hb.read_measurement(DATA)
        from_arrays = hb.fit((m.t, m.u, m.y), "hysteresis,msd", **QUICK_FIT)
        from_step = hb.fit((m.sample_time, m.u, m.y), "hysteresis,msd", **QUICK_FIT)
        from_measurement = hb.fit(m, "hysteresis,msd", **QUICK_FIT)
        # A Measurement keeps its segments, so it is the file to the last bit
        # (the units of the file's truth file are not in it).
        def values(f):
            return [p["value"] for p in f.record["parameters"]]
        self.assertEqual(values(from_measurement), values(self.fit))
        # Bare arrays have none: they are a file of t, u, y to the last bit.
        plain = self.dir / "plain.csv"
        np.savetxt(plain, np.column_stack([m.t, m.u, m.y]), delimiter=",", header="t,u,y",
                   comments="", fmt="%.17g")
        self.assertEqual(values(from_arrays), values(hb.fit(plain, "hysteresis,msd", **QUICK_FIT)))
        self.assertEqual(from_step.record["holdout"], from_arrays.record["holdout"])
        self.assertGreater(from_step.rmse, 0)
        self.assertEqual(hb.compare(m, self.fit).rmse, hb.compare(DATA, self.fit).rmse)
        with self.assertRaisesRegex(hb.InputError, "u has 11000 samples but y has 3"):
            hb.fit((m.t, m.u, m.y[:3]), "msd")
        with self.assertRaisesRegex(hb.InputError, "give a file path, \\(t, u, y\\)"):
            hb.fit(42, "msd")

    def test_diagnose_has_a_verdict(self):
        d = hb.diagnose(DATA, fit=self.fit, candidates="arx,asymmetry", candidate_restarts=1)
        self.assertIn(d.verdict, {"arx", "asymmetry", "none"})
        self.assertIsInstance(d.complete, bool)
        self.assertIn("candidates", d.record)

    def test_simulate_writes_and_reads_back(self):
        bundled = DATA.parent
        data, truth = hb.simulate(self.dir / "sim.mat", params=bundled / "default.params.json",
                                  excitation=bundled / "default.excitation.json", seed=4)
        self.assertGreater(len(data.t), 1000)
        self.assertIn("noise_floor_sse", truth)
        self.assertTrue((self.dir / "sim.mat").exists())

    def test_run_returns_the_trials(self):
        r = hb.run(CORPUS / "good_experiment.json", trials=3)
        self.assertEqual(len(r.trials), 3)
        self.assertEqual(r.summary["experiment"]["name"], "good")
        self.assertEqual(len(r.best("de")), 3)

    def test_bad_input_raises_with_the_programs_message(self):
        with self.assertRaises(hb.InputError) as caught:
            hb.fit(DATA, "hysteresis,msdd")
        r = program("fit", "--data", DATA, "--model", "hysteresis,msdd", "--out", self.dir / "x")
        self.assertEqual(r.returncode, 2)
        self.assertEqual("hystbench: error: " + str(caught.exception), r.stderr.strip())

    def test_an_existing_folder_is_kept_without_force(self):
        with self.assertRaisesRegex(hb.InputError, "already holds"):
            hb.fit(DATA, "msd", out=self.dir / "fit", **QUICK_FIT)
        first = hb.run(CORPUS / "good_experiment.json", out=self.dir / "run", trials=2)
        with self.assertRaisesRegex(hb.InputError, "already holds"):
            hb.run(CORPUS / "good_experiment.json", out=self.dir / "run", trials=2)
        again = hb.run(CORPUS / "good_experiment.json", out=self.dir / "run", trials=2, force=True)
        self.assertEqual(again.best("de"), first.best("de"))

    def test_help_is_returned(self):
        text = hb.command("fit", "--help")
        self.assertIn("--model", text)
        self.assertIn("--data", text)


class Discover(unittest.TestCase):
    def test_discover_returns_the_ladder(self):
        d = hb.discover(DATA, "hysteresis,msd", max_steps=1, candidates="arx,offset",
                        candidate_restarts=1, refit_restarts=1, **QUICK_FIT)
        self.assertIsInstance(d.model, str)
        self.assertIsInstance(d.steps, list)
        self.assertGreaterEqual(len(d.steps), 1)


if __name__ == "__main__":
    unittest.main()

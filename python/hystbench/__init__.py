"""hystbench from Python: the commands of the `hystbench` program, run in
process, with their results as Python objects and numpy arrays.

Every function takes the command line's options as keyword arguments
(``restarts=2`` is ``--restarts 2``, ``force=True`` is ``--force``) and raises
``hystbench.InputError`` (a ``ValueError``) with the program's own message
when an input is wrong. Results go to ``out`` when it is given, else to a
temporary folder that is removed once they are read.

    import hystbench as hb
    m = hb.read_measurement("problems/hammerstein/data/default.csv")
    f = hb.fit(m.source, model="hysteresis,msd", restarts=2)
    f.rmse, f.parameters["hysteresis.A"]

Wherever a data file is taken, arrays are taken too: ``(t, u, y)``, a sample
time and ``(dt, u, y)``, or a ``Measurement``.
"""
from __future__ import annotations

import contextlib
import dataclasses
import json
import os
import tempfile
from pathlib import Path
from typing import Any, Iterator

try:
    import numpy as np
except ImportError as e:  # a python3 other than the one the module was built for
    raise ImportError("hystbench needs numpy: install python3-numpy and use Debian's "
                      "/usr/bin/python3, the interpreter the module is built for") from e

try:
    from ._core import InputError, read_mat_vector, version
    from ._core import read_measurement as _read_measurement
    from ._core import run_command as _run_command
except ImportError as e:  # the source folder python/, or a build without the module
    raise ImportError("hystbench's compiled part (hystbench._core) is missing: build it with "
                      "`make demo` (needs pybind11-dev python3-dev python3-numpy) and use "
                      "PYTHONPATH=build/python, not the source folder python/") from e

__all__ = ["InputError", "Measurement", "Fit", "Comparison", "Diagnosis", "Discovery", "Run",
           "read_measurement", "read_mat_vector", "fit", "simulate", "compare", "diagnose",
           "discover", "run", "command", "version"]
__version__ = version


def __dir__() -> list[str]:  # the API only, not the modules it imports
    return sorted([*__all__, "__version__"])


@dataclasses.dataclass
class Measurement:
    """A measurement as hystbench reads it (CSV or MAT file)."""
    t: np.ndarray
    u: np.ndarray
    y: np.ndarray
    segment: list[str]
    sample_time: float
    source: str
    u_unit: str = ""
    y_unit: str = ""


@dataclasses.dataclass
class Fit:
    """fit.json of `hystbench fit`: ``rmse`` on the estimation part,
    ``heldout_rmse`` on the held-out part, ``parameters`` by name."""
    model: str
    rmse: float
    heldout_rmse: float | None
    parameters: dict[str, float]
    record: dict[str, Any]
    folder: Path | None


@dataclasses.dataclass
class Comparison:
    """metrics.json of `hystbench compare`, with the model output."""
    metrics: dict[str, Any]
    t: np.ndarray
    y: np.ndarray
    y_model: np.ndarray
    folder: Path | None

    @property
    def rmse(self) -> float:
        return self.metrics["all"]["rmse"]


@dataclasses.dataclass
class Diagnosis:
    """diagnosis.json of `hystbench diagnose`: ``verdict`` is the effect to
    add, or "none"."""
    verdict: str
    complete: bool
    record: dict[str, Any]
    folder: Path | None


@dataclasses.dataclass
class Discovery:
    """ladder.json of `hystbench discover`: the final model and each step."""
    model: str
    complete: bool
    steps: list[dict[str, Any]]
    record: dict[str, Any]
    folder: Path | None


@dataclasses.dataclass
class Run:
    """summary.json and trials.jsonl of `hystbench run`; the trials in the
    order of algorithm and trial number (the file is in order of completion,
    which differs from one run with threads to the next)."""
    summary: dict[str, Any]
    trials: list[dict[str, Any]]
    folder: Path | None

    def best(self, label: str) -> list[float]:
        """The final best fitness of every trial of one algorithm, by trial."""
        return [t["best"] for t in self.trials if t["label"] == label]


def command(*args: str, echo: bool = False) -> str:
    """Runs ``hystbench ARGS...`` in process; returns what it printed (with
    ``echo=True`` it is printed instead, and "" returned). ``--help`` returns
    the help text."""
    return _run_command([str(a) for a in args], echo)


def read_measurement(path: str | os.PathLike, columns: str | dict[str, str] | None = None,
                     delimiter: str = "auto") -> Measurement:
    """Reads a measurement CSV or MAT file; ``columns`` maps t, u, y and
    segment to the file's names ("t=time,u=v_in" or a dict), when they are
    not t, u, y or a common name such as "Voltage [V]"; ``delimiter`` is
    "comma", "semicolon" or "tab" when the header's is not the one."""
    d = _read_measurement(str(path), _columns_text(columns), delimiter)
    return Measurement(t=d["t"], u=d["u"], y=d["y"], segment=list(d["segment"]),
                       sample_time=d["sample_time"], source=d["source"],
                       u_unit=d["u_unit"], y_unit=d["y_unit"])


def fit(data: Data, model: str, *, out: str | os.PathLike | None = None,
        echo: bool = False, **options: Any) -> Fit:
    """`hystbench fit --data DATA --model MODEL`."""
    with _folder(out) as folder, _data_file(data) as data:
        _run("fit", folder, out, echo, data=data, model=model, **options)
        record = _json(folder / "fit.json")
    return _fit_of(record, out)


def simulate(out: str | os.PathLike | None = None, *, echo: bool = False, **options: Any
             ) -> tuple[Measurement, dict[str, Any]]:
    """`hystbench simulate`: synthetic data and its truth file. ``out`` is
    the data file (.csv or .mat); without it the data live in a temporary
    folder until they are read."""
    with _folder(None) as folder:
        target = Path(out) if out is not None else folder / "simulated.csv"
        _run_command(["simulate", *_flags(dict(options, out=target))], echo)
        truth = _json(target.with_suffix(".truth.json"))
        return read_measurement(target), truth


def compare(data: Data, fit: str | os.PathLike | Fit, *,
            out: str | os.PathLike | None = None, echo: bool = False, **options: Any
            ) -> Comparison:
    """`hystbench compare --data DATA --fit FIT`, with the model output."""
    with _folder(out) as folder, _fit_file(fit) as fit_file, _data_file(data) as data:
        mat = folder / "model_output.mat"
        _run("compare", folder, out, echo, data=data, fit=fit_file, mat=mat, **options)
        vectors = {name: read_mat_vector(str(mat), name) for name in ("t", "y", "y_model")}
        return Comparison(metrics=_json(folder / "metrics.json"), folder=_kept(out), **vectors)


def diagnose(data: Data, model: str | None = None, *,
             out: str | os.PathLike | None = None, echo: bool = False, **options: Any
             ) -> Diagnosis:
    """`hystbench diagnose --data DATA --model MODEL` (or ``fit=`` a fit)."""
    with _folder(out) as folder, _fit_file(options.pop("fit", None)) as fit_file, \
            _data_file(data) as data:
        _run("diagnose", folder, out, echo, data=data, model=model, fit=fit_file, **options)
        record = _json(folder / "diagnosis.json")
    return Diagnosis(verdict=record["verdict"], complete=bool(record["complete"]),
                     record=record, folder=_kept(out))


def discover(data: Data, start: str, *, out: str | os.PathLike | None = None,
             echo: bool = False, **options: Any) -> Discovery:
    """`hystbench discover --data DATA --start START`."""
    with _folder(out) as folder, _data_file(data) as data:
        _run("discover", folder, out, echo, data=data, start=start, **options)
        record = _json(folder / "ladder.json")
    return Discovery(model=record["final_model"], complete=bool(record["complete"]),
                     steps=record["steps"], record=record, folder=_kept(out))


def run(experiment: str | os.PathLike, *, out: str | os.PathLike | None = None,
        echo: bool = False, **options: Any) -> Run:
    """`hystbench run EXPERIMENT` (trials=, seed=, threads=, ... as options)."""
    with _folder(out) as folder:
        _run(["run", str(experiment)], folder, out, echo, **options)
        summary = _json(folder / "summary.json")
        with open(folder / "trials.jsonl", encoding="utf-8") as f:
            trials = [json.loads(line) for line in f if line.strip()]
        trials.sort(key=lambda t: (t["algorithm_index"], t["trial"]))
    return Run(summary=summary, trials=trials, folder=_kept(out))


# --- the command line's options from keyword arguments ----------------------

def _flags(options: dict[str, Any]) -> list[str]:
    words: list[str] = []
    for key, value in options.items():
        flag = "--" + key.replace("_", "-")
        if value is None:
            continue
        if isinstance(value, (bool, np.bool_)):
            words += [flag] if value else []
        elif key == "plugin":  # repeatable: one library each
            paths = value if isinstance(value, (list, tuple)) else [value]
            for path in paths:
                words += [flag, str(path)]
        elif key == "columns":
            words += [flag, _columns_text(value)]
        elif isinstance(value, (list, tuple)):
            words += [flag, ",".join(str(v) for v in value)]
        else:
            words += [flag, str(value)]
    return words


def _columns_text(columns: str | dict[str, str] | None) -> str:
    if columns is None:
        return ""
    if isinstance(columns, dict):
        return ",".join(f"{role}={name}" for role, name in columns.items())
    return columns


def _run(command: str | list[str], folder: Path, out: str | os.PathLike | None, echo: bool,
         **options: Any) -> None:
    """Runs a command (its name, or name and positional arguments) into `folder`."""
    # A temporary folder of our own may be replaced; the caller's only with force=True.
    if out is None:
        options["force"] = True
    words = [command] if isinstance(command, str) else list(command)
    _run_command([*words, *_flags(dict(options, out=folder))], echo)


@contextlib.contextmanager
def _folder(out: str | os.PathLike | None) -> Iterator[Path]:
    if out is not None:
        yield Path(out)
        return
    with tempfile.TemporaryDirectory(prefix="hystbench_") as tmp:
        yield Path(tmp)


def _kept(out: str | os.PathLike | None) -> Path | None:
    return Path(out) if out is not None else None


def _json(path: Path) -> dict[str, Any]:
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def _fit_of(record: dict[str, Any], out: str | os.PathLike | None) -> Fit:
    errors = record["errors"]
    return Fit(model=record["model"], rmse=errors["rmse"],
               heldout_rmse=errors.get("heldout_rmse"),
               parameters={p["name"]: p["value"] for p in record["parameters"]},
               record=record, folder=_kept(out))


Data = Any  # a path, (t, u, y), (dt, u, y) or a Measurement


@contextlib.contextmanager
def _data_file(data: Data) -> Iterator[str]:
    """A data file's path: as given, or the arrays written to a CSV (17
    significant digits, so every value reads back exactly) for the command."""
    if isinstance(data, (str, os.PathLike)):
        yield str(data)
        return
    segment: list[str] = []
    names = ["t", "u", "y"]
    if isinstance(data, Measurement):
        t, u, y, segment = data.t, data.u, data.y, data.segment
        for i, unit in ((1, data.u_unit), (2, data.y_unit)):
            names[i] += f" [{unit}]" if unit else ""
    else:
        t, u, y = _arrays(data)
    with tempfile.TemporaryDirectory(prefix="hystbench_data_") as tmp:
        path = Path(tmp) / "data.csv"
        with open(path, "w", encoding="utf-8") as f:
            f.write(",".join(names + (["segment"] if segment else [])) + "\n")
            for k in range(len(t)):
                row = f"{t[k]:.17g},{u[k]:.17g},{y[k]:.17g}"
                f.write(row + (f",{_csv_text(segment[k])}\n" if segment else "\n"))
        yield str(path)


def _csv_text(text: str) -> str:
    return '"' + text.replace('"', '""') + '"' if any(c in text for c in ',"\n') else text


def _arrays(data: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    try:
        first, u, y = data
    except (TypeError, ValueError):
        raise InputError("data: give a file path, (t, u, y), (dt, u, y) or a Measurement, not "
                         f"{type(data).__name__}") from None
    u = np.asarray(u, dtype=float).ravel()
    y = np.asarray(y, dtype=float).ravel()
    if u.shape != y.shape:
        raise InputError(f"data: u has {u.size} samples but y has {y.size}; give one of each "
                         "per sample")
    if np.ndim(first) == 0:
        dt = float(first)
        if not dt > 0:
            raise InputError(f"data: the sample time {dt} must be positive")
        return dt * np.arange(u.size), u, y
    t = np.asarray(first, dtype=float).ravel()
    if t.shape != u.shape:
        raise InputError(f"data: t has {t.size} samples but u has {u.size}; give one of each "
                         "per sample")
    return t, u, y


@contextlib.contextmanager
def _fit_file(fit: str | os.PathLike | Fit | None) -> Iterator[str | None]:
    """A fit.json path: as given, or the record of a Fit written out for the command."""
    if not isinstance(fit, Fit):
        yield None if fit is None else str(fit)
        return
    with tempfile.TemporaryDirectory(prefix="hystbench_fit_") as tmp:
        path = Path(tmp) / "fit.json"
        path.write_text(json.dumps(fit.record), encoding="utf-8")
        yield str(path)

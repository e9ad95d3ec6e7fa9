#!/usr/bin/env python3
"""Tables of benchmarks/real.sh: summary.csv, README.md and <benchmark>/README.md.

    real_summary.py OUT_DIR BENCHMARK...

RMSE is read from each test record's compare metrics.json ("all": every
sample after the warm-up, simulated from u, on the tanks from the level the
warm-up sets) and given in the
benchmark's unit. The published numbers are those of the data's own
README files (nonlinear_benchmarks split).
"""
import csv
import json
import os
import sys

# unit, factor from V, published best per test record (value, source), linear anchor per test record.
BENCHMARKS = {
    "silverbox": {
        "title": "Silverbox (electronic Duffing oscillator, measured)",
        "unit": "mV",
        "factor": 1000.0,
        "published": {
            "test_arrow_full": (0.26, "Paduart et al., Automatica 46(4) 2010, PNLSS (figure as commonly cited)"),
        },
        "anchor": {"test_multisine": 7.8, "test_arrow_full": 15.6, "test_arrow_no_extrapolation": 7.1},
        "anchor_name": "ARX(2,2) by least squares, simulated",
        "goal": ("test_arrow_full", 0.3),
    },
    "cascaded_tanks": {
        "title": "Cascaded tanks (water levels with overflow, measured)",
        "unit": "V",
        "factor": 1.0,
        "published": {
            "test": (0.18, "Rogers et al. 2017, grey box with an overflow model (Forgione & Piga, Eur. J. Control 59, 2021, table CTS)"),
        },
        "anchor": {"test": 0.65},
        "anchor_name": "ARX(3,3) by least squares, simulated",
        "goal": ("test", 0.34),
    },
}


def load(path):
    with open(path) as f:
        return json.load(f)


def timings(directory):
    with open(os.path.join(directory, "timings.txt")) as f:
        return dict(line.strip().split("=", 1) for line in f if "=" in line)


def rows_of(out, name):
    spec = BENCHMARKS[name]
    directory = os.path.join(out, name)
    t = timings(directory)
    fit = load(os.path.join(directory, t["scored_fit"]))
    model = ",".join(e["name"] for e in fit["effects"])
    rows = []
    for test in sorted(d for d in os.listdir(directory) if d.startswith("test")):
        metrics_path = os.path.join(directory, test, "metrics.json")
        if not os.path.isfile(metrics_path):
            continue
        rmse = load(metrics_path)["all"]["rmse"] * spec["factor"]
        best, source = spec["published"].get(test, (None, ""))
        rows.append({"benchmark": name, "test": test, "model": model, "rmse": rmse, "unit": spec["unit"],
                     "warmup": int(t.get("score_warmup", warmup_of(fit))), "published_best": best, "published_source": source})
    return rows, t


def warmup_of(fit):
    """The warm-up a fit was made with: its hold-out text has "+warmup:N" (then "+held" for a held start)."""
    holdout = fit.get("holdout", "")
    return int(holdout.split("warmup:")[1].split("+")[0]) if "warmup:" in holdout else 0


def warmup_sentences(t, rows):
    """How long the fits warm up, and why, when the first ladder advised longer than the benchmark's own."""
    score = rows[0]["warmup"] if rows else "?"
    if "first_discover_seconds" not in t:
        return f"with a warm-up of {score} samples (simulated, never fitted or scored)", ""
    return (f"with a warm-up of {t['fit_warmup']} samples (simulated, never fitted)",
            f" The fits warm up longer than the {score} samples the test records are scored after: a first "
            f"`discover` with {score} ([discover_first/ladder.md](discover_first/ladder.md), "
            f"{t['first_discover_seconds']} s) found a start-up transient dominating its error and advised "
            f"{t['fit_warmup']}, and discover ran again with that.")


def transient_left(directory, t):
    """What discover's ladder (the one the fits start from) still says of a start-up transient, and why
    the script did not follow it. The advice is always longer than the warm-up used when the transient
    dominates (docs/discovery.md, "Start-up transients")."""
    s = load(os.path.join(directory, "discover", "ladder.json"))["startup_transient"]
    if not s["dominates"]:
        return ""
    advice = f"a start-up transient dominates its error and advises `--warmup {s['warmup']}`"
    if load(os.path.join(directory, "discover", "fit.json")).get("holdout", "").endswith("+held"):
        return (f" Its ladder says {advice}; the script does not follow that on a held start, whose warm-up "
                f"outputs set the level (a long warm-up would average a moving stretch into it).")
    return (f" The second ladder still says {advice}: the script follows the advice once, so the scored "
            f"fit keeps what is left of the transient; fit again with that warm-up by hand.")


def discover_seconds(t):
    """Both discover runs where the first ladder's advice made the script run it again."""
    first = t.get("first_discover_seconds")
    return f"{first} + {t['discover_seconds']}" if first else t["discover_seconds"]


def simulated_from(directory, t):
    """How a test record is simulated: from u alone, or also from the level its warm-up outputs set."""
    fit = load(os.path.join(directory, t["scored_fit"]))
    if fit.get("holdout", "").endswith("+held"):
        return ("simulated from u, starting where a long-held input leaves the model, at the level that "
                "matches the warm-up's outputs (`--initial-state held`; the benchmark lets its first outputs "
                "set the initial state)")
    return "simulated from u alone"


def number(v):
    return "" if v is None else f"{v:.4g}"


def grey_box_line(t, spec):
    """The benchmark's physical law as a user's effect, and how it fared against discovery on estimation."""
    example, model, *options = t["grey_box"].split()
    found = next(k for k in t if k.startswith("estimation_rmse_") and k != "estimation_rmse_grey_box")
    unit, factor = spec["unit"], spec["factor"]
    return (f"- Grey box: the benchmark's physical law written by hand as a user's effect "
            f"([{example}](../../../{example})), `fit --model {model} {' '.join(options)}` on the estimation "
            f"record ({t['grey_box_seconds']} s): estimation RMSE {factor * float(t['estimation_rmse_grey_box']):.4g} {unit}, "
            f"beside {factor * float(t[found]):.4g} {unit} for `{found.removeprefix('estimation_rmse_')}/fit.json`. The "
            f"lower estimation RMSE is scored on test ([estimation_grey_box](estimation_grey_box/report.md)); the "
            f"test records take no part in the choice.")


def hold_line(t, spec):
    """How the model to score held out when fitted afresh under the spline and the band-limited input hold,
    beside the fit it came from, and whether the band-limited fit replaced that one."""
    spline, band, found = (spec["factor"] * float(t[f"heldout_rmse_{h}"]) for h in ("spline", "bandlimited", "found"))
    chosen = "the band-limited fit replaces discovery's fit" if t["hold_fit"].startswith("hold_bandlimited/") else \
        "discovery's fit stays"
    return (f"- Input between samples: the model to score fitted afresh with the spline and with "
            f"`--input-hold bandlimited` ([docs/models.md](../../../docs/models.md#streaming-models), \"Input hold\") "
            f"holds out {spline:.4g} and {band:.4g} {spec['unit']} on the estimation record, discovery's fit "
            f"{found:.4g} ({t['hold_seconds']} s); {chosen}.")


def benchmark_readme(out, name, rows, t):
    spec = BENCHMARKS[name]
    directory = os.path.join(out, name)
    ladder = load(os.path.join(directory, "discover", "ladder.json"))
    unit = spec["unit"]
    fits, why = warmup_sentences(t, rows)
    lines = [f"# {spec['title']}\n",
             f"Made by `benchmarks/real.sh`. `discover` from `msd` on `estimation.csv` only, {fits}, then `compare` "
             f"of the scored fit on each test record, {simulated_from(directory, t)}. RMSE after the benchmark's "
             f"warm-up, its own way.{why}{transient_left(directory, t)}\n",
             f"- Ladder: [discover/ladder.md](discover/ladder.md); final model `{ladder['final_model']}`, "
             f"complete: {'yes' if ladder['complete'] else 'no'} ({ladder['completeness']['kind']}).",
             f"- Scored fit: `{t['scored_fit']}` (model `{rows[0]['model'] if rows else '?'}`)."]
    if os.path.isdir(os.path.join(directory, "with_effect")):
        lines.append("- The ladder ended beyond the catalog: [proposals/proposals.md](proposals/proposals.md), "
                     "the generated effect in `proposals/effect/`, and discovery offered it in "
                     "[with_effect/ladder.md](with_effect/ladder.md).")
    elif os.path.isdir(os.path.join(directory, "proposals")):
        said = [line.strip() for line in open(os.path.join(directory, "proposals.log"))
                if line.startswith("  1.") or line.startswith("no effect written")]
        lines.append("- The ladder ended beyond the catalog: [proposals/proposals.md](proposals/proposals.md). "
                     "propose said: " + " ".join(f"`{t}`" for t in said) + ".")
    if "grey_box" in t:
        lines.append(grey_box_line(t, spec))
    options = t.get("discover_options", "")
    if "heldout_rmse_spline" in t:
        lines.append(hold_line(t, spec))
    lines.append(f"- Run with `MAX_STEPS={t.get('max_steps', '?')}`" +
                 (f" and `DISCOVER_OPTIONS=\"{options}\"`" if options else "") +
                 f"; time on 2 cores: discover {discover_seconds(t)} s, proposal and its ladder "
                 f"{t['proposal_seconds']} s.\n")
    lines += [f"| test record | RMSE ({unit}) | {spec['anchor_name']} ({unit}) | published best ({unit}) | source |",
              "| :-- | --: | --: | --: | :-- |"]
    for r in rows:
        lines.append(f"| [{r['test']}]({r['test']}/report.md) | {r['rmse']:.4g} | "
                     f"{number(spec['anchor'].get(r['test']))} | {number(r['published_best'])} | "
                     f"{r['published_source']} |")
    goal_test, goal = spec["goal"]
    reached = [r for r in rows if r["test"] == goal_test]
    if reached:
        verdict = "reached" if reached[0]["rmse"] <= goal else "not reached"
        lines.append(f"\nGoal: at most {goal} {unit} on {goal_test}: {verdict} ({reached[0]['rmse']:.4g} {unit}).")
    with open(os.path.join(directory, "README.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    out, names = sys.argv[1], sys.argv[2:]
    all_rows = []
    for name in names:
        rows, t = rows_of(out, name)
        benchmark_readme(out, name, rows, t)
        all_rows += rows
    summary = os.path.join(out, "summary.csv")
    # Rows of benchmarks not run this time are kept.
    kept = []
    if os.path.isfile(summary):
        with open(summary) as f:
            kept = [r for r in csv.DictReader(f) if r["benchmark"] not in names]
    columns = ["benchmark", "test", "model", "rmse", "unit", "warmup", "published_best", "published_source"]
    with open(summary, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        for r in kept:
            w.writerow(r)
        for r in all_rows:
            w.writerow({**r, "rmse": f"{r['rmse']:.6g}", "published_best": number(r["published_best"])})
    with open(summary) as f:
        table = list(csv.DictReader(f))
    lines = ["# Measured benchmarks\n",
             "Made by `benchmarks/real.sh DATA_ROOT`: discovery on public measured records and, where a "
             "benchmark has one, its physical law written by hand as a user's effect (a grey box; the lower "
             "estimation error is scored), both on their official test records as the literature scores them. Each folder's README gives the ladder, the "
             "test RMSE beside a linear anchor and the published best; `summary.csv` has one row per benchmark "
             "and test record. What the runs show, and why a goal is not met where it is not: "
             "[docs/discovery.md](../../docs/discovery.md#measured-benchmarks).\n",
             "| benchmark | test | model | RMSE | published best |", "| :-- | :-- | :-- | --: | --: |"]
    for r in table:
        lines.append(f"| [{r['benchmark']}]({r['benchmark']}/README.md) | {r['test']} | `{r['model']}` | "
                     f"{float(r['rmse']):.4g} {r['unit']} | {r['published_best'] or '–'} |")
    with open(os.path.join(out, "README.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()

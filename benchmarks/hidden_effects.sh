#!/usr/bin/env bash
# Hidden-effect benchmark at full size: for every case of
# benchmarks/experiments/hidden_effects.json, simulate the data from the true
# model, diagnose the start model and run discover from it, all with the
# built `hystbench` command-line program; then write
# results/hidden_effects/README.md (a table: effect, verdict, ΔBIC of the
# winner, final model, held-out RMSE / true σ, seconds), summary.csv and each
# case's ladder.md.
#
#   benchmarks/hidden_effects.sh [HYSTBENCH_EXE] [OUT_DIR]
#
# HYSTBENCH_EXE defaults to build/hystbench, OUT_DIR to results/hidden_effects
# (both relative to the repository). Set CASES="creep offset" to run only
# some cases (the README then lists only those). Reading the JSON case file
# needs python3.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe="${1:-$repo/build/hystbench}"
out="${2:-$repo/results/hidden_effects}"
case_file="$repo/benchmarks/experiments/hidden_effects.json"

if ! command -v python3 >/dev/null 2>&1; then
  echo "hidden_effects.sh: python3 is needed to read $case_file (not found in PATH)" >&2
  exit 2
fi
if [[ ! -x "$exe" ]]; then
  echo "hidden_effects.sh: $exe is not an executable; build hystbench first or pass its path" >&2
  exit 2
fi
exe="$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")"
mkdir -p "$out"
out="$(cd "$out" && pwd)"

# json FILE EXPRESSION: prints a value of a JSON file (strings bare, others as JSON).
json() {
  python3 - "$1" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1], encoding="utf-8"))
v = eval(sys.argv[2], {"d": d})
print(v if isinstance(v, str) else json.dumps(v, ensure_ascii=False))
PY
}

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

all_cases="$(json "$case_file" '" ".join(c["effect"] for c in d["cases"])')"
cases="${CASES:-$all_cases}"
json "$case_file" 'd["excitation"]' > "$work/excitation.json"
u_unit="$(json "$case_file" 'd["units"]["u"]')"
y_unit="$(json "$case_file" 'd["units"]["y"]')"

summary="$out/summary.csv"
echo "effect,hidden,start,verdict,winner_delta_bic,final_model,heldout_rmse,true_sd,ratio,diagnose_s,discover_s,samples" > "$summary"

for effect in $cases; do
  sel="[c for c in d['cases'] if c['effect'] == '$effect'][0]"
  truth="$(json "$case_file" "$sel['truth']")"
  start="$(json "$case_file" "$sel['start']")"
  hidden="$(json "$case_file" "' '.join($sel['hidden']) or 'none'")"
  noise="$(json "$case_file" "$sel['noise']")"
  seed="$(json "$case_file" "$sel['seed']")"
  dir="$work/$effect"
  mkdir -p "$dir"
  json "$case_file" "$sel['values']" > "$dir/values.json"
  echo "== $effect: truth $truth, start $start" >&2
  # Relative paths only, so that nothing machine-specific lands in the reports.
  (
    cd "$dir"
    "$exe" simulate --model "$truth" --params values.json --excitation ../excitation.json \
      --noise "$noise" --seed "$seed" --input-unit "$u_unit" --output-unit "$y_unit" \
      --out data.csv > simulate.log
    t0=$(date +%s.%N)
    "$exe" diagnose --data data.csv --model "$start" --seed "$seed" --out diagnose > diagnose.log
    t1=$(date +%s.%N)
    "$exe" discover --data data.csv --start "$start" --seed "$seed" --out discover > discover.log
    t2=$(date +%s.%N)
    python3 -c "print(f'{$t1 - $t0:.1f} {$t2 - $t1:.1f}')" > seconds.txt
  )
  read -r diag_s disc_s < "$dir/seconds.txt"
  python3 - "$dir" "$effect" "$hidden" "$start" "$diag_s" "$disc_s" >> "$summary" <<'PY'
import csv, json, sys
dir_, effect, hidden, start, diag_s, disc_s = sys.argv[1:]
diag = json.load(open(f"{dir_}/diagnose/diagnosis.json", encoding="utf-8"))
ladder = json.load(open(f"{dir_}/discover/ladder.json", encoding="utf-8"))
truth = json.load(open(f"{dir_}/data.truth.json", encoding="utf-8"))
verdict = diag["verdict"]
winner = next((c for c in diag["candidates"] if c["effect"] == verdict), None)
dbic = winner["delta_bic"] if winner else diag["candidates"][0]["delta_bic"]
last = ladder["steps"][-1]
sd = truth["noise"]["sd"]
csv.writer(sys.stdout, lineterminator="\n").writerow([
    effect, hidden, start, verdict, f"{dbic:.1f}", ladder["final_model"],
    f"{last['heldout_rmse']:.4g}", f"{sd:.4g}", f"{last['heldout_rmse'] / sd:.3f}", diag_s, disc_s,
    sum(1 for _ in open(f"{dir_}/data.csv", encoding="utf-8") if _[:1].isdigit())])
PY
  mkdir -p "$out/$effect"
  cp "$dir/discover/ladder.md" "$out/$effect/ladder.md"
  cp "$dir/diagnose/diagnosis.json" "$out/$effect/diagnosis.json"
  tail -n 1 "$summary" >&2
done

python3 - "$summary" "$out/README.md" "$case_file" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1], encoding="utf-8")))
spec = json.load(open(sys.argv[3], encoding="utf-8"))
ex = spec["excitation"]
def seg(s):
    if s["type"] == "sine":
        return f"sine {s['frequency']} Hz, {s['amplitude']} V" + (f" + {s['offset']} V" if s.get("offset") else "") + f", {s['duration']} s"
    if s["type"] == "sweep":
        return f"sweep {s['f0']}–{s['f1']} Hz, {s['amplitude']} V, {s['duration']} s"
    return f"steps {s['levels']} V, hold {s['hold']} s"
lines = []
w = lines.append
w("# Hidden-effect benchmark (full size)\n")
w("Generated by `benchmarks/hidden_effects.sh` from `benchmarks/experiments/hidden_effects.json`: "
  "for each case the data are simulated from the true model (`hystbench simulate`, seeded relative "
  "noise), the start model is diagnosed (`hystbench diagnose`) and discovery runs from it "
  "(`hystbench discover`), all with the default fit options (jSO, 3 restarts, BOBYQA polish), the "
  "default hold-out (auto) and the case's seed.\n")
w(f"Excitation ({ex['sample_rate']} Hz): " + "; ".join(seg(s) for s in ex["segments"]) + ".\n")
w("| case (hidden) | start model | verdict | ΔBIC of the winner | final model | held-out RMSE / true σ | diagnose s | discover s |")
w("|---|---|---|---|---|---|---|---|")
ok = 0
for r in rows:
    hidden = r["hidden"].split()
    final = r["final_model"].split(",")
    found = (r["verdict"] == "none" and hidden == ["none"]) or (r["verdict"] in hidden)
    complete = all(h in final for h in hidden if h != "none") and float(r["ratio"]) <= 1.2
    ok += found and complete
    dbic = r["winner_delta_bic"] + ("" if r["verdict"] != "none" else " (best candidate, not significant)")
    w(f"| {r['effect']} | {r['start']} | {r['verdict']} | {dbic} | {r['final_model']} | "
      f"{r['ratio']} ({r['heldout_rmse']} / {r['true_sd']} µm) | {r['diagnose_s']} | {r['discover_s']} |")
total = sum(float(r["diagnose_s"]) + float(r["discover_s"]) for r in rows)
w("")
w(f"{ok} of {len(rows)} cases: verdict names the hidden effect (or `none`), the final model holds every "
  f"hidden effect and its held-out RMSE is within 1.2 σ. Samples per record: {rows[0]['samples'] if rows else 0}. "
  f"Total diagnose + discover time {total:.0f} s (2 cores, shared).\n")
w("Each case's discovery ladder is in `<case>/ladder.md`, its diagnosis in `<case>/diagnosis.json`; "
  "every run's numbers are in `summary.csv`.")
open(sys.argv[2], "w", encoding="utf-8").write("\n".join(lines) + "\n")
PY
echo "wrote $out/README.md" >&2

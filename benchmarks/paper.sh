#!/usr/bin/env bash
# Regenerates results/paper/: the seed papers' comparisons on the bundled
# data, each experiment's tables, statistics and figures in a folder of its
# own, and a Friedman ranking over six simulated data sets (see
# results/paper/README.md for what each one is).
#
#   benchmarks/paper.sh [HYSTBENCH_EXE] [OUT_DIR]
#
# HYSTBENCH_EXE defaults to build/hystbench, OUT_DIR to results/paper (both
# relative to the repository). `make paper` builds and runs it.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe="${1:-$repo/build/hystbench}"
out="${2:-$repo/results/paper}"

if [[ ! -x "$exe" ]]; then
  echo "paper.sh: $exe is not an executable; run \`make paper\` or build hystbench first" >&2
  exit 2
fi

# experiment file, then the algorithm the significance marks compare against
runs=(
  "mede_table1 MEDE"
  "mede_table1_fair MEDE"
  "amfmmde_convergence AmFMMDE"
  "league jSO"
)
cd "$repo"  # experiment files name their data relative to the repository
for run in "${runs[@]}"; do
  read -r name reference <<<"$run"
  echo "== $name (reference $reference)"
  "$exe" run "benchmarks/experiments/$name.json" --out "$out/$name" --reference "$reference" --force
done

# Friedman ranking over several data sets: each excitation at two noise
# levels, simulated from the bundled data's true parameters, one run each.
# Paths inside the repository are written relative to it: the data files
# record the command that made them.
friedman="$(realpath -m --relative-to="$repo" "$out/friedman")"
params=problems/hammerstein/data/default.params.json
seed=11
for excitation in multisine sweep steps; do
  for noise in 1 3; do
    data="$friedman/data/${excitation}_${noise}pct.csv"
    mkdir -p "$friedman/data"
    "$exe" simulate --params "$params" --excitation "benchmarks/experiments/friedman/$excitation.excitation.json" \
      --noise "0.0$noise" --seed "$seed" --input-unit V --output-unit µm --out "$data" >/dev/null
    seed=$((seed + 1))
    echo "== friedman on ${excitation}_${noise}pct"
    "$exe" run benchmarks/experiments/friedman.json --data "$data" \
      --out "$friedman/${excitation}_${noise}pct" --force >/dev/null
  done
done
"$exe" rank "$friedman"/{multisine,sweep,steps}_{1,3}pct --out "$friedman" --force

# Every LaTeX table in one document: proof that they compile, and a page to
# read them on. Typeset where pdflatex is installed (Debian:
# texlive-latex-recommended); make paper needs no TeX otherwise.
cd "$out"
{
  printf '%s\n' '% All tables of this folder; `pdflatex tables.tex` typesets them.' \
    '\documentclass{article}' '\usepackage[margin=2cm]{geometry}' '\usepackage{booktabs}' \
    '\begin{document}'
  for run in "${runs[@]}"; do
    read -r name _ <<<"$run"
    printf '\\input{%s}\n\\clearpage\n' "$name/table.tex" "$name/stats.tex"
  done
  printf '%s\n' '\input{friedman/ranks.tex}' '\end{document}'
} > tables.tex
if command -v pdflatex >/dev/null; then
  pdflatex -interaction=nonstopmode -halt-on-error tables.tex >/dev/null ||
    { echo "paper.sh: the LaTeX tables do not compile; see $out/tables.log" >&2; exit 1; }
  rm -f tables.aux tables.log
else
  echo "no pdflatex: tables.tex written but not typeset"
fi
echo "results in $out"

#!/usr/bin/env bash
# Physics the catalog lacks, end to end with the built command (docs/discovery.md,
# "Beyond the catalog" and "Proposing a missing term"), on short records
# written by tests/planted_data.cpp:
#   - rate-dependent gain: discover from the seed chain ends with complete: false
#     and the kind beyond_catalog; propose on its fit ranks v·|v'| first at the
#     static stage; the generated effect, built against the build tree, is
#     added by discover --plugin and brings the held-out RMSE within 1.2 × the
#     noise sd;
#   - cubic stiffness: propose on a fitted msd ranks x³ first in the dynamics;
#     discover --plugin puts the generated effect (msd with the force) in
#     msd's place, with the same result;
#   - a drive-dependent stiffness: propose on a fitted msd ranks |v|·x
#     first, a product of two signals; its generated force (written with w
#     = gain·v) takes msd's place with the same result;
#   - quadratic damping: propose on a fitted msd ranks x'·|x'| first; its
#     generated force takes msd's place with the same result; discover from
#     msd finds it in the catalog, as duffing's drag;
#   - dry friction: discover from msd refuses the catalog effects that stand
#     in for it (the stopping share) and propose given that discover folder
#     extends msd;
#   - a play operator beside the gain: propose on a fitted msd ranks
#     play(v, 25 %) first, and says why it writes no effect for it;
#   - a gain that drifts with time, dry (Coulomb) friction and a play
#     operator whose width grows with the drive rate: propose says that no
#     term of its library expresses what is missing, and why.
# benchmarks/beyond_catalog.sh runs the same at full size.
source "$(dirname "${BASH_SOURCE[0]}")/plugin_script.sh" || exit 1

hystbench="$build_dir/hystbench"
planted="$build_dir/tests/hystbench_planted_data"
# Reads the commands' own printed lines and JSON with grep, sed and awk.
below() { awk -v v="$1" -v bound="$2" 'BEGIN { exit !(v + 0 <= bound + 0) }'; }
noise=0.01
seed_chain=hysteresis,asymmetry,msd,arx
cd "$work"

# Builds the generated effect of proposal folder $1 against the build tree and
# checks its batched form in the model $2.
build_effect() {
  build_plugin "$1/effect" "$1/effect/build" -Dhystbench_DIR="$build_dir"
  [[ -f "$1/effect/build/proposed_term.so" ]] || fail "the effect proposed in $1 did not build"
  # Batched like the catalog's effects, and equal to its one-candidate values.
  "$build_dir/tests/hystbench_lane_check" "$1/effect/build/proposed_term.so" "$2" ||
    fail "the effect proposed in $1 is not batched, or its blocks differ from single candidates"
}

# The last ladder step printed in $1 must score within 1.2 x the noise sd
# held out; $2 names the case in the failure.
held_out_within_noise() {
  local rmse
  rmse=$(grep "^step" "$1" | tail -1 | sed -E 's/.*samples, ([0-9.e+-]+) +on .*held-out.*/\1/')
  below "$rmse" "$(awk -v s=$noise 'BEGIN { print 1.2 * s }')" ||
    fail "$2: the held-out RMSE is $rmse, more than 1.2 x $noise"
}

# Discovery from the model proposal $1 was made from ($3), offered only the
# generated effect: it must add it, and end within 1.2 x the noise sd held out.
discover_with_effect() {
  "$hystbench" discover --data "$2" --start "$3" --plugin "$1/effect/build/proposed_term.so" \
    --candidates proposed_term --out "$1/discover" > "$1/discover.txt"
  grep -q "^final model: .*proposed_term" "$1/discover.txt" ||
    fail "$2: discover --plugin did not add the proposed effect: $(cat "$1/discover.txt")"
  held_out_within_noise "$1/discover.txt" "$2 with the proposed effect"
}

# Rate-dependent gain.
"$planted" rate_gain rate.csv 4000
"$hystbench" discover --data rate.csv --start "$seed_chain" --out discover > discover.txt
grep -q '^  "complete": false' discover/ladder.json || fail "rate_gain: discover calls the seed chain complete"
grep -q '"kind": "beyond_catalog"' discover/ladder.json ||
  fail "rate_gain: the ladder does not say the missing physics is beyond the catalog"
grep -q "## Beyond the catalog" discover/ladder.md || fail "rate_gain: ladder.md has no Beyond the catalog section"
"$hystbench" propose --data rate.csv --fit discover/fit.json --out rate > rate.txt
grep -q "^  1\. static: v·|v'|  " rate.txt || fail "rate_gain: the first proposal is not static v·|v'|: $(cat rate.txt)"
build_effect rate hysteresis,msd,proposed_term
discover_with_effect rate rate.csv "$seed_chain"

# A planted force inside the dynamics ($1, in file $2): propose on a fitted
# msd ranks the dynamics term $3 first, and its generated force takes msd's
# place within 1.2 x the noise.
force_case() {
  "$planted" "$1" "$2.csv" 4000
  "$hystbench" fit --data "$2.csv" --model msd --out "$2-msd" >/dev/null
  "$hystbench" propose --data "$2.csv" --fit "$2-msd/fit.json" --out "$2" > "$2.txt"
  grep -qF "  1. dynamics: $3  " "$2.txt" || fail "$1: the first proposal is not dynamics $3: $(cat "$2.txt")"
  build_effect "$2" proposed_term
  discover_with_effect "$2" "$2.csv" msd
}
force_case cubic_stiffness cubic "x³"
# A spring that stiffens with the drive: a product of two signals, written
# as a force of the resonance's output and its input.
force_case drive_stiffness drive "|v|·x"
force_case quadratic_damping drag "x'·|x'|"
# The drag is also the catalog's own (duffing's drag): discover from msd
# replaces msd by duffing, reads the drag and ends within 1.2 x the noise.
"$hystbench" discover --data drag.csv --start msd --max-steps 1 --out drag-ladder > drag-ladder.txt
grep -q "^final model: duffing$" drag-ladder.txt || fail "quadratic_damping: discover did not find duffing: $(cat drag-ladder.txt)"
grep -q "duffing is .*; a quadratic drag" drag-ladder.txt || fail "quadratic_damping: the reading names no drag: $(cat drag-ladder.txt)"
held_out_within_noise drag-ladder.txt "quadratic_damping with duffing"
# The stopping share (docs/discovery.md, "Beyond the catalog"): for dry
# friction the catalog's stand-ins remove under 40 % of the excess error, so
# discover refuses them and stops at msd, beyond the catalog; propose given
# the discover folder extends that rung and says its library falls short.
"$planted" coulomb_friction friction.csv 4000
"$hystbench" discover --data friction.csv --start msd --max-steps 1 --out friction-ladder > friction-ladder.txt
grep -q "^final model: msd$" friction-ladder.txt ||
  fail "coulomb_friction: discover added a catalog effect: $(cat friction-ladder.txt)"
grep -q '"kind": "beyond_catalog"' friction-ladder/ladder.json ||
  fail "coulomb_friction: the ladder does not say the missing physics is beyond the catalog"
"$hystbench" propose --data friction.csv --fit friction-ladder --out friction-from-ladder > friction-from-ladder.txt
grep -q "^propose extends step 0 (msd)" friction-from-ladder.txt ||
  fail "coulomb_friction: propose given the discover folder does not say which rung it extends: $(cat friction-from-ladder.txt)"
grep -q "^The library cannot express what is missing" friction-from-ladder.txt ||
  fail "coulomb_friction: from the discover folder propose does not say the library falls short: $(cat friction-from-ladder.txt)"
# A play operator beside the gain: a term of the library that no generated
# effect has, proposed with no effect written, and said so.
"$planted" parallel_play play.csv 4000
"$hystbench" fit --data play.csv --model msd --out play-msd >/dev/null
"$hystbench" propose --data play.csv --fit play-msd/fit.json --out play > play.txt
grep -qF "  1. static: play(v, 25 %)  " play.txt || fail "parallel_play: the first proposal is not the play operator: $(cat play.txt)"
grep -q "^no effect written: the term .* write its effect by hand" play.txt ||
  fail "parallel_play: propose does not say why no effect was written: $(cat play.txt)"
grep -q "No effect was written" play/proposals.md || fail "parallel_play: proposals.md does not say no effect was written"
[[ ! -e play/effect ]] || fail "parallel_play: an effect folder was written for a term without a generated form"
# Physics no term of the library expresses ($1, in file $2): propose on a
# fitted msd says so, with the reason $3 among its words. A record written
# earlier in this script is used again.
beyond_case() {
  [[ -f "$2.csv" ]] || "$planted" "$1" "$2.csv" 4000
  "$hystbench" fit --data "$2.csv" --model msd --out "$2-msd" >/dev/null
  "$hystbench" propose --data "$2.csv" --fit "$2-msd/fit.json" --out "$2" > "$2.txt"
  grep -q "^The library cannot express what is missing" "$2.txt" ||
    fail "$1: propose does not say the library falls short: $(cat "$2.txt")"
  grep -qF "$3" "$2.txt" || fail "$1: propose does not say '$3': $(cat "$2.txt")"
  grep -q "Beyond the library" "$2/proposals.md" || fail "$1: proposals.md does not say the library falls short"
}
beyond_case gain_drift drift "a law that changes with time"
beyond_case coulomb_friction friction "a friction force that jumps with the direction of motion"
beyond_case rate_dependent_play rate-play "a loop whose width changes with the drive's rate"
echo "beyond_catalog: every planted case found and proposed; the generated effects fitted"

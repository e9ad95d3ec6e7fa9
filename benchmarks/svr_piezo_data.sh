#!/usr/bin/env bash
# The records of the simulated piezo stack of seed 002's protocol (the SVR
# work and the tracking work use them): training and test data of
# `hystbench simulate --model hysteresis,asymmetry,msd`, 0.5 % noise and a
# 0.1 µm sensor resolution, seeds 202 (training) and 203 (tests).
#
#   benchmarks/svr_piezo_data.sh [DATA_DIR]     # default results/svr/data
#
# Needs a built build/hystbench (or HYSTBENCH=path). A few seconds.
set -euo pipefail
data=${1:-results/svr/data}
hystbench=${HYSTBENCH:-build/hystbench}
spec=benchmarks/experiments/svr_piezo
mkdir -p "$data"
for record in train:202 test:203; do
  "$hystbench" simulate --model hysteresis,asymmetry,msd --params "$spec/actuator.params.json" \
    --excitation "$spec/${record%%:*}.excitation.json" --noise 0.005 --resolution 0.1 \
    --seed "${record##*:}" --input-unit V --output-unit µm --out "$data/${record%%:*}.csv"
done

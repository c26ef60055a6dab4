#!/usr/bin/env bash
# What the cloud layer costs: `urbis bench`'s 1 spp frame of the default generated city (from its
# default camera, the clouds' shadows over the city) under --clouds 0, 0.3, 0.7 and 1, each coverage
# once per round so that a drift of the clocks touches all alike.
# Usage: bench/clouds_bench.sh BUILD_DIR [DEVICE [WIDTH HEIGHT [ROUNDS]]]
#   DEVICE cuda (default; 1920x1080) or cpu; JSON and logs in $OUT (default ./clouds-out); prints
#   each coverage's median frame and its ratio to the clear frame.
set -uo pipefail
BUILD=${1:?build folder}
DEVICE=${2:-cuda}
WIDTH=${3:-1920}
HEIGHT=${4:-1080}
ROUNDS=${5:-3}
OUT=${OUT:-$PWD/clouds-out}
mkdir -p "$OUT"
status=0
for round in $(seq 1 "$ROUNDS"); do
  for coverage in 0 0.3 0.7 1; do
    "$BUILD"/urbis bench --device "$DEVICE" --width "$WIDTH" --height "$HEIGHT" --repeats 3 --clouds "$coverage" \
        --json "$OUT/clouds_${coverage}_${DEVICE}_${round}.json" > "$OUT/clouds_${coverage}_${DEVICE}_${round}.log" 2>&1 || status=1
  done
done
python3 - "$OUT" "$DEVICE" <<'PY'
import glob, json, statistics, sys
out, device = sys.argv[1], sys.argv[2]
clear = None
for coverage in ("0", "0.3", "0.7", "1"):
    frames = [json.load(open(f))["frame"]["median_ms"] for f in sorted(glob.glob(f"{out}/clouds_{coverage}_{device}_*.json"))]
    median = statistics.median(frames) if frames else float("nan")
    clear = clear or median
    print(f"--clouds {coverage:4s} frame median {median:9.2f} ms ({median / clear:.2f}x the clear frame) over rounds {[round(f, 1) for f in frames]}")
PY
exit $status

#!/usr/bin/env bash
# What the cloud layer costs: `urbis bench`'s 1 spp frame of the default generated city (from its
# default camera, the clouds' shadows over the city) under --clouds 0, 0.3, 0.7 and 1, each coverage
# once per round so that a drift of the clocks touches all alike.
# Usage: bench/clouds_bench.sh BUILD_DIR [DEVICE [WIDTH HEIGHT [ROUNDS]]]
#   DEVICE cuda (default; 1920x1080) or cpu; JSON and logs in $OUT (default ./clouds-out); prints
#   each coverage's median frame and its ratio to the clear frame.
set -uo pipefail
source "$(dirname "$0")/bench_variants.sh"
bench_arguments clouds "$@"
declare -A flags=([0]="--clouds 0" [0.3]="--clouds 0.3" [0.7]="--clouds 0.7" [1]="--clouds 1")
bench_variants clouds 0 0.3 0.7 1
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
exit $bench_status

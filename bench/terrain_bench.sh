#!/usr/bin/env bash
# The terrain's marches against the fixed-step reference: `urbis bench --terrain-accuracy`
# over the default fBm landscape and over San Francisco's DEM (the two osmnx tiles), printing each
# march's missed intersections, HDE, IDE and time.
# Usage: bench/terrain_bench.sh BUILD_DIR [DEVICE [WIDTH HEIGHT [REPEATS]]]
#   DEVICE cuda (default; 1920x1080) or cpu; JSON and logs in $OUT (default ./terrain-out).
set -uo pipefail
BUILD=${1:?build folder}
DEVICE=${2:-cuda}
WIDTH=${3:-1920}
HEIGHT=${4:-1080}
REPEATS=${5:-5}
OUT=${OUT:-$PWD/terrain-out}
DEM=/usr/share/doc/python-osmnx-doc/examples/tests/input_data/elevation1.tif
mkdir -p "$OUT"
status=0
declare -A flags=([fbm]="--terrain fbm" [sf_dem]="--dem $DEM")
for variant in fbm sf_dem; do
  # shellcheck disable=SC2086
  "$BUILD"/urbis bench --terrain-accuracy --device "$DEVICE" --width "$WIDTH" --height "$HEIGHT" --repeats "$REPEATS" \
      ${flags[$variant]} --json "$OUT/terrain_${variant}_${DEVICE}.json" > "$OUT/terrain_${variant}_${DEVICE}.log" 2>&1 || status=1
  cat "$OUT/terrain_${variant}_${DEVICE}.log"
done
exit $status

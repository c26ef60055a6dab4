#!/usr/bin/env bash
# Whole planets (docs/planets.md): `urbis bench`'s 1 spp frame of the default Earth-like planet from
# orbit (the whole disc), from 10 km up and from 2 m above the ground, by day and at sunset; from
# orbit and from 10 km by day under the cloud shell at 0.4 (docs/planets.md § Cloud shell).
# Usage: bench/planet_bench.sh BUILD_DIR [DEVICE [WIDTH HEIGHT]]
#   DEVICE cuda (default; 1920x1080) or cpu; JSON and logs in $OUT (default ./planet-out), one file
#   per view: bench_<view>_<device>.json; prints each view's median frame time.
set -uo pipefail
BUILD=${1:?build folder}
DEVICE=${2:-cuda}
WIDTH=${3:-1920}
HEIGHT=${4:-1080}
OUT=${OUT:-$PWD/planet-out}
mkdir -p "$OUT"
status=0
declare -A views=(
  [orbit_day]="--camera-orbit 12000,20,10 --sun 40,150"
  [orbit_dusk]="--camera-orbit 12000,20,10 --sun 2,90"
  [km10_day]="--camera-orbit 10,-45,180,200,-10 --sun 40,150"
  [km10_sunset]="--camera-orbit 10,-45,180,200,-10 --sun 3,200"
  [ground_day]="--camera-orbit 0.002,30,0,250,3 --sun 40,150"
  [ground_sunset]="--camera-orbit 0.002,30,0,250,3 --sun 3,250"
  [orbit_clouds]="--camera-orbit 12000,20,10 --sun 40,150 --clouds 0.4"
  [km10_clouds]="--camera-orbit 10,-45,180,200,-10 --sun 40,150 --clouds 0.4"
)
for view in orbit_day orbit_dusk km10_day km10_sunset ground_day ground_sunset orbit_clouds km10_clouds; do
  # shellcheck disable=SC2086
  "$BUILD"/urbis bench --planet ${views[$view]} --device "$DEVICE" --width "$WIDTH" --height "$HEIGHT" --repeats 3 \
      --json "$OUT/bench_${view}_${DEVICE}.json" > "$OUT/bench_${view}_${DEVICE}.log" 2>&1 || status=1
done
python3 - "$OUT" "$DEVICE" <<'PY'
import glob, json, sys
out, device = sys.argv[1], sys.argv[2]
for f in sorted(glob.glob(f"{out}/bench_*_{device}.json")):
    j = json.load(open(f))
    view = f.split("/")[-1][len("bench_"):-len(f"_{device}.json")]
    print(f"{view:14s} frame median {j['frame']['median_ms']:10.2f} ms")
PY
exit $status

#!/usr/bin/env bash
# GPU frames of one or more builds, interleaved by round, for the render kernel per scene content
# (docs/gpu_notes.md § One render kernel per scene content): `urbis bench`'s 1080p 1 spp frame of the
# default generated city (clear; without its trees, bench/no_trees.json; under clouds 0.3) and of
# San Francisco by day (procedural facades, default framing), and SF at night per sample (1080p,
# 64 spp, the light BVH: the command of BENCHMARKS.md § Many lights, `seconds_render` / 64).
# Usage: bench/scene_kernels_bench.sh BUILD_DIR... (each holding a `urbis`, named by its folder's
# name); ROUNDS (default 2); dependencies and data from $URBIS_DEPS (default ./.deps, as
# bench/gpu_deps.sh gathers them); JSON and logs in $OUT (default ./scene-kernels-out), and the
# medians in summary.md.
set -uo pipefail
(($# >= 1)) || { echo "usage: $0 BUILD_DIR..." >&2; exit 2; }
ROUNDS=${ROUNDS:-2}
OUT=${OUT:-$PWD/scene-kernels-out}
DEPS=${URBIS_DEPS:-$PWD/.deps}
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$OUT"
source "$HERE/deps_root.sh"
SF=$DEPS/data/sf_downtown_2023.osm.pbf
FRAME=(bench --device cuda --width 1920 --height 1080 --repeats 3)
NIGHT=(render --spp 64 --width 1920 --height 1080 --osm "$SF" --camera-geo -122.3940,37.7950,25,200,-25 --fov 60
       --time 2023-06-21T23:00-07:00 --exposure 11 --device cuda --light-sampler bvh)
status=0
for round in $(seq 1 "$ROUNDS"); do
  for dir in "$@"; do
    build=$(basename "$dir")
    run() {  # case urbis-args...
      local name=$1; shift
      "$dir"/urbis "$@" > "$OUT/${name}_${build}_${round}.log" 2>&1 || status=1
    }
    run city "${FRAME[@]}" --json "$OUT/city_${build}_${round}.json"
    run city_no_trees "${FRAME[@]}" --scene "$HERE/no_trees.json" --json "$OUT/city_no_trees_${build}_${round}.json"
    run city_clouds "${FRAME[@]}" --clouds 0.3 --json "$OUT/city_clouds_${build}_${round}.json"
    run sf_day "${FRAME[@]}" --osm "$SF" --json "$OUT/sf_day_${build}_${round}.json"
    run sf_night "${NIGHT[@]}" --out "$OUT/sf_night_${build}.png" --stats "$OUT/sf_night_${build}_${round}.json"
  done
done
python3 - "$OUT" "$@" <<'PY' | tee "$OUT/summary.md"
import glob, json, os, statistics, sys
out, builds = sys.argv[1], [os.path.basename(d.rstrip("/")) for d in sys.argv[2:]]
def ms(path):
    j = json.load(open(path))
    return j["frame"]["median_ms"] if "frame" in j else 1e3 * j["seconds_render"] / 64
print("| frame (ms, median of rounds) | " + " | ".join(builds) + " |\n|---|" + "---:|" * len(builds))
for case in ("city", "city_no_trees", "city_clouds", "sf_day", "sf_night"):
    cells = []
    for build in builds:
        runs = [ms(f) for f in sorted(glob.glob(f"{out}/{case}_{build}_*.json"))]
        cells.append(f"{statistics.median(runs):.2f} ({', '.join(f'{r:.2f}' for r in runs)})" if runs else "-")
    print(f"| {case} | " + " | ".join(cells) + " |")
PY
exit $status

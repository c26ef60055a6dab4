#!/usr/bin/env bash
# Nature together (BENCHMARKS.md § Nature together): `urbis bench`'s 1 spp frame of the forest under clouds
# (docs/examples/forest_clouds.json: the generated city of 200 buildings with its river on the fBm
# terrain, its parks' and streets' trees and 1.5 km of forest around it, the atmosphere, clouds at
# 0.3) with everything, then with each element removed (the Cambridge thesis's Figure 4.17: an
# element's share is what the frame loses without it), interleaved over the rounds; then a forest's
# trees from the ground to 30 km up, looking down over the forest ring at 45 degrees.
# Usage: bench/nature_bench.sh BUILD_DIR [DEVICE [WIDTH HEIGHT [ROUNDS]]]
#   DEVICE cuda (default; 1920x1080; the goal: under 16 ms) or cpu; JSON and logs in $OUT (default
#   ./nature-out): nature_<variant>_<device>_<round>.json and forest_<height>_<device>_<round>.json;
#   prints each variant's median frame and each element's share of the full frame.
set -uo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/bench_variants.sh"
bench_arguments nature "$@"
# The scene files of the variants: the example, less one element each.
python3 - "$HERE/../docs/examples/forest_clouds.json" "$OUT" <<'PY'
import copy, json, sys
full, out = json.load(open(sys.argv[1])), sys.argv[2]
less = {"all": {}, "no_terrain": {"terrain": {"kind": "none"}}, "no_trees": {"trees": {"enabled": False}},
        "no_water": {"water": {"enabled": False}}, "no_atmosphere": {"sky": {"model": "analytic"}},
        "no_clouds": {"clouds": {"coverage": 0}}}
for name, change in less.items():
    scene = copy.deepcopy(full)
    for section, keys in change.items():
        scene.setdefault(section, {}).update(keys)
    json.dump(scene, open(f"{out}/{name}.json", "w"))
PY
declare -A flags
for variant in all no_terrain no_trees no_water no_atmosphere no_clouds; do
  # --spp 1: else the scene file's integrator.spp (16 by default) would be the frame's.
  flags[$variant]="--buildings 200 --spp 1 --scene $OUT/$variant.json"
done
bench_variants nature all no_terrain no_trees no_water no_atmosphere no_clouds
# The forest ring lies beyond the city's box (some 400 m from the middle): cameras over it at 2 m
# (under the crowns' tops), 30 m, 300 m, 3 km and 30 km, each looking 45 degrees down towards the city.
for height in 2 30 300 3000 30000; do
  flags[h$height]="--buildings 200 --spp 1 --scene $OUT/all.json --camera 0,$height,$((1100 + height)),0,0,1100"
done
bench_variants forest h2 h30 h300 h3000 h30000
python3 - "$OUT" "$DEVICE" <<'PY'
import glob, json, statistics, sys
out, device = sys.argv[1], sys.argv[2]
def median(prefix, variant):
    frames = [json.load(open(f))["frame"]["median_ms"] for f in sorted(glob.glob(f"{out}/{prefix}_{variant}_{device}_*.json"))]
    return (statistics.median(frames) if frames else float("nan")), frames
full, _ = median("nature", "all")
for variant in ("all", "no_terrain", "no_trees", "no_water", "no_atmosphere", "no_clouds"):
    ms, frames = median("nature", variant)
    share = "" if variant == "all" else f"  share of the {variant[3:]} {full - ms:8.2f} ms ({(full - ms) / full:6.1%})"
    print(f"{variant:14s} frame median {ms:9.2f} ms over rounds {[round(f, 1) for f in frames]}{share}")
for height in (2, 30, 300, 3000, 30000):
    ms, frames = median("forest", f"h{height}")
    print(f"forest from {height:6d} m frame median {ms:9.2f} ms over rounds {[round(f, 1) for f in frames]}")
PY
exit $bench_status

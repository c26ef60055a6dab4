#!/usr/bin/env bash
# Frames with trees against without (bench/no_trees.json: trees.enabled false), on one build: GPU 1080p
# 1 spp frames of the default generated city (400 buildings, its parks' and streets' trees), of the
# Bavarian village and of San Francisco (its mapped trees and filled parks), each from the default
# framing and at street level in a park, trees sphere traced and as their triangle twin; then the CPU
# frame of the generated city and of SF (TREES_CPU=0 leaves them out). Usage: bench/trees_bench.sh
# BUILD_DIR (holding a `urbis`); dependencies and data from $URBIS_DEPS (default ./.deps, as
# bench/gpu_deps.sh gathers them); JSON in $OUT (default ./trees-out), one file per row:
# bench_<scene>_<view>_<trees>_<device>.json, <trees> one of procedural, triangles, none.
set -uo pipefail
(($# == 1)) || { echo "usage: $0 BUILD_DIR" >&2; exit 2; }
OUT=${OUT:-$PWD/trees-out}
DEPS=${URBIS_DEPS:-$PWD/.deps}
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$OUT"
source "$HERE/deps_root.sh"
SF=$DEPS/data/sf_downtown_2023.osm.pbf
VILLAGE=$DEPS/data/planet_10.068,48.135_10.071,48.137.osm
status=0
row() {  # scene view device scene-args...
  local scene=$1 view=$2 device=$3; shift 3
  for trees in procedural triangles none; do
    local extra=(--geometry "trees=$trees")
    [[ $trees == none ]] && extra=(--scene "$HERE/no_trees.json")
    "$BUILD"/urbis bench --device "$device" "$@" "${extra[@]}" --json "$OUT/bench_${scene}_${view}_${trees}_${device}.json" \
        > "$OUT/bench_${scene}_${view}_${trees}_${device}.log" 2>&1 || status=1
  done
}
BUILD=$1
# The generated city's central park is around the origin; SF's Union Square park, Yerba Buena Gardens.
row city framing cuda --buildings 400
row city street cuda --buildings 400 --camera -60,1.7,-40,0,4,0
row village framing cuda --osm "$VILLAGE"
row sf framing cuda --osm "$SF"
row sf street cuda --osm "$SF" --camera-geo -122.4020,37.7845,1.7,60,-2
if [[ ${TREES_CPU:-1} != 0 ]]; then
  row city framing cpu --buildings 400 --width 480 --height 270 --repeats 3
  row sf framing cpu --osm "$SF" --width 480 --height 270 --repeats 3
fi
exit $status

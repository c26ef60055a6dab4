#!/usr/bin/env bash
# Frames with streets against without (--no-streets), one build, one run of the GPU machine: GPU
# 1080p 1 spp frames of SF and of the 100k generated city (procedural and plain walls), and the CPU
# frame of SF. Usage: bench/streets_bench.sh BUILD_DIR (holds a `urbis`); dependencies and data from
# $URBIS_DEPS (default ./.deps, as bench/gpu_deps.sh gathers them); JSON in $OUT (default
# ./streets-out), one file per row: bench_<scene>_<geometry>_<device>_<streets|bare>.json.
set -uo pipefail
BUILD=${1:?build folder}
OUT=${OUT:-$PWD/streets-out}
DEPS=${URBIS_DEPS:-$PWD/.deps}
mkdir -p "$OUT"
source "$(dirname "$0")/deps_root.sh"
SF=$DEPS/data/sf_downtown_2023.osm.pbf
status=0
for scene in sf 100k; do
  src=(--osm "$SF"); [[ $scene == 100k ]] && src=(--buildings 100000)
  for geometry in procedural plain; do
    for streets in streets bare; do   # interleaved, so that a drift of the clocks touches both alike
      flag=(); [[ $streets == bare ]] && flag=(--no-streets)
      "$BUILD"/urbis bench --device cuda --geometry $geometry "${src[@]}" "${flag[@]}" \
          --json "$OUT/bench_${scene}_${geometry}_cuda_${streets}.json" > "$OUT/bench_${scene}_${geometry}_cuda_${streets}.log" 2>&1 || status=1
    done
  done
done
for streets in streets bare; do
  flag=(); [[ $streets == bare ]] && flag=(--no-streets)
  "$BUILD"/urbis bench --device cpu --osm "$SF" --repeats 3 "${flag[@]}" --json "$OUT/bench_sf_procedural_cpu_${streets}.json" \
      > "$OUT/bench_sf_procedural_cpu_${streets}.log" 2>&1 || status=1
done
exit $status

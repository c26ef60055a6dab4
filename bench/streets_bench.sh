#!/usr/bin/env bash
# Frames with streets against without (--no-streets), one or more builds, one run of the GPU machine:
# GPU 1080p 1 spp frames of SF and of the 100k generated city (procedural and plain walls), and the
# CPU frame of SF (STREETS_CPU=0 leaves it out). Usage: bench/streets_bench.sh BUILD_DIR... (each holds
# a `urbis`; several builds are interleaved by scene, so that a drift of the clocks touches all alike);
# dependencies and data from $URBIS_DEPS (default ./.deps, as bench/gpu_deps.sh gathers them); JSON in
# $OUT (default ./streets-out), one file per row: bench_<build>_<scene>_<geometry>_<device>_<streets|bare>.json,
# <build> the folder's name.
set -uo pipefail
(($# > 0)) || { echo "usage: $0 BUILD_DIR..." >&2; exit 2; }
OUT=${OUT:-$PWD/streets-out}
DEPS=${URBIS_DEPS:-$PWD/.deps}
mkdir -p "$OUT"
source "$(dirname "$0")/deps_root.sh"
SF=$DEPS/data/sf_downtown_2023.osm.pbf
status=0
for scene in sf 100k; do
  src=(--osm "$SF"); [[ $scene == 100k ]] && src=(--buildings 100000)
  for geometry in procedural plain; do
    for build in "$@"; do
      for streets in streets bare; do
        flag=(); [[ $streets == bare ]] && flag=(--no-streets)
        name=bench_$(basename "$build")_${scene}_${geometry}_cuda_${streets}
        "$build"/urbis bench --device cuda --geometry $geometry "${src[@]}" "${flag[@]}" \
            --json "$OUT/$name.json" > "$OUT/$name.log" 2>&1 || status=1
      done
    done
  done
done
if [[ ${STREETS_CPU:-1} != 0 ]]; then
  for build in "$@"; do
    for streets in streets bare; do
      flag=(); [[ $streets == bare ]] && flag=(--no-streets)
      name=bench_$(basename "$build")_sf_procedural_cpu_${streets}
      "$build"/urbis bench --device cpu --osm "$SF" --repeats 3 "${flag[@]}" --json "$OUT/$name.json" \
          > "$OUT/$name.log" 2>&1 || status=1
    done
  done
fi
exit $status

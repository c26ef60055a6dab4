#!/usr/bin/env bash
# Two builds of urbis measured side by side in one run of the GPU machine: GPU frames and ray rates
# (SF with facades, their triangle twin and plain walls; the 100k generated city procedural and plain),
# CPU ray rates of SF, and converged renders of the default world and of SF by each, compared by
# bench/compare_builds.py. Usage: bench/compare_builds.sh BEFORE_DIR AFTER_DIR (each holds a `urbis`);
# dependencies and data from $URBIS_DEPS (default ./.deps, as bench/gpu_deps.sh gathers them); results
# in $OUT (default ./compare-out): bench_<build>_<scene>_<geometry>_<device>.json, converged_<build>_<world>.png
# and compare.md. COMPARE_STEPS (default gpu,cpu,images) and COMPARE_GEOMETRIES (default "procedural
# triangles plain") choose a part: all of it takes longer than one device command may run (600 s), so run
# gpu with two geometries, then the rest, into the same $OUT.
set -uo pipefail
BEFORE=${1:?before build folder} AFTER=${2:?after build folder}
OUT=${OUT:-$PWD/compare-out}
DEPS=${URBIS_DEPS:-$PWD/.deps}
mkdir -p "$OUT"
source "$(dirname "$0")/deps_root.sh"
SF=$DEPS/data/sf_downtown_2023.osm.pbf
STEPS=",${COMPARE_STEPS:-gpu,cpu,images},"
status=0
build_dir() { [[ $1 == before ]] && echo "$BEFORE" || echo "$AFTER"; }
# Interleaved by scene, so that a drift of the machine's clocks touches both builds alike.
[[ $STEPS == *,gpu,* ]] && for scene in sf 100k; do
  for geometry in ${COMPARE_GEOMETRIES:-procedural triangles plain}; do
    [[ $scene == 100k && $geometry == triangles ]] && continue
    for build in before after; do
      dir=$(build_dir $build)
      src=(--osm "$SF"); [[ $scene == 100k ]] && src=(--buildings 100000)
      "$dir"/urbis bench --device cuda --geometry $geometry "${src[@]}" \
          --json "$OUT/bench_${build}_${scene}_${geometry}_cuda.json" > "$OUT/bench_${build}_${scene}_${geometry}_cuda.log" 2>&1 || status=1
    done
  done
done
for build in before after; do
  dir=$(build_dir $build)
  [[ $STEPS == *,cpu,* ]] && { "$dir"/urbis bench --device cpu --osm "$SF" --repeats 3 --json "$OUT/bench_${build}_sf_procedural_cpu.json" \
      > "$OUT/bench_${build}_sf_procedural_cpu.log" 2>&1 || status=1; }
  [[ $STEPS == *,images,* ]] || continue
  "$dir"/urbis render --device cuda --width 640 --height 360 --spp 4096 --out "$OUT/converged_${build}_default.png" >/dev/null 2>&1 || status=1
  "$dir"/urbis render --device cuda --osm "$SF" --width 640 --height 360 --spp 4096 --out "$OUT/converged_${build}_sf.png" >/dev/null 2>&1 || status=1
done
python3 "$(dirname "$0")/compare_builds.py" "$OUT" | tee "$OUT/compare.md" || status=1
exit $status

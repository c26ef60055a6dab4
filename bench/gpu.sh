#!/usr/bin/env bash
# GPU check and benchmark in one go: builds urbis with CUDA, runs the GPU tests (urbis_gpu_tests),
# benchmarks the GPU (and the CPU, for comparison) on downtown San Francisco and on a generated
# 100k-building city, and renders one image per backend. Logs and JSON go to $OUT (default
# ./gpu-out): gpu.log, bench_*.json, sf_gpu.png. Dependencies: $URBIS_DEPS (default ./.deps), as
# bench/gpu_deps.sh gathers them: debs/ (unpacked on first use; or root/, already unpacked) and data/
# (sf_downtown_2023.osm.pbf, the Bavarian village).
# Usage: bench/gpu.sh [steps], steps a comma list of build,test,bench,cpu (default all) and profile
# (not by default: Nsight Compute on one render kernel launch of each representation, generated city
# at 40 m, or at URBIS_PROFILE_HEIGHT metres, joined with the kernel's line table by bench/sass_lines.py;
# build with -lineinfo for it).
# Environment: URBIS_BUILD_DIR (build), URBIS_CUDA_FLAGS (extra nvcc flags, e.g.
# -lineinfo for Nsight Compute's source view), URBIS_TAG (suffix of the JSON names), JOBS.
# Building there takes minutes of device time; binaries built here run there as they are. So
# build here (cmake --build build --target urbis urbis_gpu_tests), copy build/urbis and
# build/urbis_gpu_tests into a git-ignored folder, carry it with .deps, and run the other steps on
# it: URBIS_BUILD_DIR=that-folder bench/gpu.sh test,bench (docs/gpu_notes.md § Measuring on the GPU machine).
set -uo pipefail
STEPS=",${1:-build,test,bench,cpu},"
OUT=${OUT:-$PWD/gpu-out}
DEPS=${URBIS_DEPS:-$PWD/.deps}
JOBS=${JOBS:-$(nproc)}
mkdir -p "$OUT"
LOG=$OUT/gpu.log
source "$(dirname "$0")/deps_root.sh"
export URBIS_OSMNX_DATA=$DEPS/data URBIS_SHARED_DATA=$DEPS/data
SF=$DEPS/data/sf_downtown_2023.osm.pbf
BUILD=${URBIS_BUILD_DIR:-build}
TAG=${URBIS_TAG:-}
# A dpkg -x'd dependency folder may hold only libexpatw (UTF-16, which libosmium cannot read) beside a
# dangling libexpat.so: then take the system's libexpat.
EXPAT_ARGS=()
if [[ ! -e $ROOT/usr/lib/x86_64-linux-gnu/libexpat.so ]]; then
  for f in /usr/lib/x86_64-linux-gnu/libexpat.so /usr/lib/x86_64-linux-gnu/libexpat.so.1; do
    [[ -e $f ]] && { EXPAT_ARGS=(-DEXPAT_LIBRARY="$f"); break; }
  done
fi
say() { echo "== $* ($(date +%T))" | tee -a "$LOG"; }
run() { "$@" 2>&1 | tee -a "$LOG"; return "${PIPESTATUS[0]}"; }
status=0

if [[ $STEPS == *,build,* ]]; then
  say build
  run nvidia-smi --query-gpu=name,memory.total,clocks.sm,clocks.max.sm --format=csv
  run cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$ROOT/usr" -DURBIS_BUILD_BENCH=OFF -DURBIS_GDAL=OFF \
      -DURBIS_CUDA_RESOURCE_USAGE=ON -DCMAKE_CUDA_FLAGS="${URBIS_CUDA_FLAGS:-}" \
      "${EXPAT_ARGS[@]}" || exit 1
  run cmake --build "$BUILD" -j"$JOBS" || exit 1
  grep -E "ptxas info|stack frame" "$LOG" | tail -8
fi

if [[ $STEPS == *,test,* ]]; then
  say "GPU tests"
  # The test binary itself rather than ctest, so that binaries built elsewhere run too.
  export URBIS_BIN
  URBIS_BIN=$(realpath "$BUILD/urbis")
  run "$BUILD"/urbis_gpu_tests || status=1
fi

if [[ $STEPS == *,bench,* ]]; then
  # Each scene twice: procedural facades (the default) and plain walls (stored triangles only).
  for geometry in procedural plain; do
    say "GPU bench ($geometry): San Francisco"
    run "$BUILD"/urbis bench --device cuda --geometry $geometry --osm "$SF" --json "$OUT/bench_sf_${geometry}${TAG}_cuda.json" || status=1
    say "GPU bench ($geometry): San Francisco from street level"
    run "$BUILD"/urbis bench --device cuda --geometry $geometry --osm "$SF" --camera-geo -122.397,37.789,300,20,-25 \
        --json "$OUT/bench_sfstreet_${geometry}${TAG}_cuda.json" || status=1
    say "GPU bench ($geometry): generated city, 100k buildings"
    run "$BUILD"/urbis bench --device cuda --geometry $geometry --buildings 100000 --json "$OUT/bench_100k_${geometry}${TAG}_cuda.json" || status=1
  done
  say "GPU render: San Francisco, 1920x1080, 64 spp"
  if [[ -z $TAG ]]; then
    run "$BUILD"/urbis render --device cuda --osm "$SF" --width 1920 --height 1080 --spp 64 --out "$OUT/sf_gpu.png" \
        --stats "$OUT/render_sf_cuda.json" || status=1
  fi
fi

if [[ $STEPS == *,cpu,* ]]; then
  say "CPU bench: San Francisco"
  run "$BUILD"/urbis bench --device cpu --osm "$SF" --repeats 3 --json "$OUT/bench_sf_cpu.json" || status=1
  say "CPU bench: generated city, 100k buildings"
  run "$BUILD"/urbis bench --device cpu --buildings 100000 --repeats 3 --json "$OUT/bench_100k_cpu.json" || status=1
fi

if [[ $STEPS == *,profile,* ]]; then
  HEIGHT=${URBIS_PROFILE_HEIGHT:-40}
  say "profile: render kernel, generated city at $HEIGHT m, 1280x720, 4 spp"
  CUBINS=$OUT/cubins
  mkdir -p "$CUBINS"
  BIN=$(realpath "$BUILD/urbis")
  (cd "$CUBINS" && cuobjdump -xelf all "$BIN" >/dev/null) || status=1
  SASS=$OUT/render_kernel.sass
  for f in "$CUBINS"/*.cubin; do nvdisasm -g -c "$f"; done > "$SASS"
  for geometry in procedural triangles; do
    ncu --kernel-name regex:renderKernel --launch-count 1 --section SourceCounters --section WarpStateStats \
        --import-source yes -f -o "$OUT/profile_$geometry" "$BUILD"/urbis render --buildings 3000 --seed 7 \
        --building-height-range 10:30 --camera -300,40,300,0,20,0 --height-scale "$(python3 -c "print($HEIGHT / 12.1)")" --width 1280 --height 720 \
        --spp 4 --device cuda --geometry $geometry --out "$OUT/profile_$geometry.png" >/dev/null 2>&1 || status=1
    ncu --import "$OUT/profile_$geometry.ncu-rep" --page source --csv --print-source sass |
        gzip > "$OUT/profile_$geometry.csv.gz"
    say "profile ($geometry)"
    # The render kernel's copy for the scene (its mangled name holds its set of gpu/render_variants.h:
    # 47 a procedural city with trees, 5 stored triangles and the ground).
    features=$([[ $geometry == procedural ]] && echo 47 || echo 5)
    run python3 bench/sass_lines.py "renderKernelILj${features}E" "$SASS" "$OUT/profile_$geometry.csv.gz" 30 || status=1
  done
fi

say "done, status $status"
exit $status

#!/usr/bin/env bash
# GPU check and benchmark in one go: builds urbis with CUDA, runs the GPU tests (CTest label gpu),
# benchmarks the GPU (and the CPU, for comparison) on downtown San Francisco and on a generated
# 100k-building city, and renders one image per backend. Logs and JSON go to $OUT (default
# ./gpu-out): gpu.log, bench_*.json, sf_gpu.png. Dependencies: $URBIS_DEPS (default ./.deps) with
# root/usr (headers and libraries, dpkg -x) and data/ (sf_downtown_2023.osm.pbf, the Bavarian village).
# Usage: bench/gpu.sh [steps], steps a comma list of build,test,bench,cpu,fmad (default build,test,bench,cpu).
set -uo pipefail
STEPS=",${1:-build,test,bench,cpu},"
OUT=${OUT:-$PWD/gpu-out}
DEPS=${URBIS_DEPS:-$PWD/.deps}
JOBS=${JOBS:-$(nproc)}
mkdir -p "$OUT"
LOG=$OUT/gpu.log
export LD_LIBRARY_PATH=$DEPS/root/usr/lib/x86_64-linux-gnu:${LD_LIBRARY_PATH:-}
export URBIS_OSMNX_DATA=$DEPS/data URBIS_SHARED_DATA=$DEPS/data
SF=$DEPS/data/sf_downtown_2023.osm.pbf
say() { echo "== $* ($(date +%T))" | tee -a "$LOG"; }
run() { "$@" 2>&1 | tee -a "$LOG"; return "${PIPESTATUS[0]}"; }
status=0

if [[ $STEPS == *,build,* ]]; then
  say build
  run nvidia-smi --query-gpu=name,memory.total,clocks.sm,clocks.max.sm --format=csv
  run cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$DEPS/root/usr" -DURBIS_BUILD_BENCH=OFF \
      -DURBIS_CUDA_RESOURCE_USAGE=ON || exit 1
  run cmake --build build -j"$JOBS" || exit 1
  grep -E "ptxas info|stack frame" "$LOG" | tail -8
fi

if [[ $STEPS == *,test,* ]]; then
  say "GPU tests"
  run ctest --test-dir build -L gpu --output-on-failure --timeout 300 || status=1
  run build/urbis_gpu_tests --gtest_filter='GpuRender.*:GpuTraversal.*' 2>&1 | grep -E "parity|bit-identical|OK|FAILED" || true
fi

if [[ $STEPS == *,bench,* ]]; then
  say "GPU bench: San Francisco"
  run build/urbis bench --device cuda --osm "$SF" --json "$OUT/bench_sf_cuda.json" || status=1
  say "GPU bench: generated city, 100k buildings"
  run build/urbis bench --device cuda --buildings 100000 --json "$OUT/bench_100k_cuda.json" || status=1
  say "GPU render: San Francisco, 1920x1080, 64 spp"
  run build/urbis render --device cuda --osm "$SF" --width 1920 --height 1080 --spp 64 --out "$OUT/sf_gpu.png" \
      --stats "$OUT/render_sf_cuda.json" || status=1
fi

if [[ $STEPS == *,cpu,* ]]; then
  say "CPU bench: San Francisco"
  run build/urbis bench --device cpu --osm "$SF" --repeats 3 --json "$OUT/bench_sf_cpu.json" || status=1
  say "CPU bench: generated city, 100k buildings"
  run build/urbis bench --device cpu --buildings 100000 --repeats 3 --json "$OUT/bench_100k_cpu.json" || status=1
fi

if [[ $STEPS == *,fmad,* ]]; then
  say "GPU bench without FMA contraction (-fmad=false)"
  run cmake -S . -B build-nofmad -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$DEPS/root/usr" \
      -DURBIS_BUILD_BENCH=OFF -DURBIS_BUILD_TESTS=OFF -DURBIS_CUDA_FMAD=OFF >/dev/null || exit 1
  run cmake --build build-nofmad -j"$JOBS" --target urbis >/dev/null || exit 1
  run build-nofmad/urbis bench --device cuda --osm "$SF" || status=1
fi
say "done, status $status"
exit $status

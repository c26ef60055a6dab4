#!/usr/bin/env bash
# Builds a libFuzzer target (fuzz/) into build-fuzz/ with clang and runs it for SECONDS on one core,
# from a seed corpus made of pieces of the real extracts (scripts/fuzz_corpus.sh). Findings land in
# build-fuzz/findings/TARGET/; the corpus grows in build-fuzz/corpus/TARGET/. See docs/fuzzing.md.
#   scripts/fuzz.sh osm_import_fuzz 600
#   scripts/fuzz.sh scene_file_fuzz 300
set -euo pipefail
target=${1:?usage: scripts/fuzz.sh TARGET SECONDS}
seconds=${2:?usage: scripts/fuzz.sh TARGET SECONDS}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz

# The warning set is held at zero for g++ (the normal build); clang builds only the fuzzer and
# knows none of g++'s diagnostic pragmas, so its warnings are shown, not fatal.
cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DURBIS_FUZZ=ON -DURBIS_WERROR=OFF \
  -DURBIS_ENABLE_CUDA=OFF -DURBIS_BUILD_TESTS=OFF -DURBIS_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null
cmake --build "$build" --target "$target" -j"${URBIS_FUZZ_JOBS:-2}"

corpus=$build/corpus/$target
findings=$build/findings/$target
mkdir -p "$corpus" "$findings"
if [ -z "$(ls -A "$corpus")" ]; then
    case $target in
        # Scene files: the hand-written seeds and the documented example; their keys as a dictionary.
        scene_file_fuzz) cp "$root"/fuzz/seeds/scene_file/*.json "$root"/docs/examples/*.json "$corpus/" ;;
        *) "$root/scripts/fuzz_corpus.sh" "$corpus" ;;
    esac
fi
dictionary=()
[ -f "$root/fuzz/$target.dict" ] && dictionary=(-dict="$root/fuzz/$target.dict")

# -timeout: one input may take 10 s (an extract of the seed corpus takes well under one);
# -rss_limit_mb / -malloc_limit_mb: a single allocation or a process over 2 GB is a finding.
# UBSan halts on every report but those fuzz/ubsan_suppressions.txt names (libraries' known ones).
cd "$findings"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$root/fuzz/ubsan_suppressions.txt"
exec "$build/fuzz/$target" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -malloc_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$findings/" "${dictionary[@]}"

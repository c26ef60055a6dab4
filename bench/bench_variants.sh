# Sourced by the scripts that time `urbis bench`'s frame under a few variants of one scene
# (bench/atmosphere_bench.sh, bench/clouds_bench.sh, bench/nature_bench.sh): their arguments and the
# interleaved runs.
#
# bench_arguments NAME "$@": reads BUILD_DIR [DEVICE [WIDTH HEIGHT [ROUNDS]]] into BUILD, DEVICE (cuda
# by default, or cpu), WIDTH and HEIGHT (1920x1080), ROUNDS (3); OUT defaults to ./NAME-out (made).
bench_arguments() {
  local name=$1
  shift
  BUILD=${1:?build folder}
  DEVICE=${2:-cuda}
  WIDTH=${3:-1920}
  HEIGHT=${4:-1080}
  ROUNDS=${5:-3}
  OUT=${OUT:-$PWD/$name-out}
  mkdir -p "$OUT"
  bench_status=0
}

# bench_variants PREFIX VARIANT...: `urbis bench` of 3 repeats for each VARIANT with the options in
# ${flags[VARIANT]} (an associative array the caller declares), once per round, every variant in
# each round so that a drift of the clocks touches all alike: $OUT/PREFIX_VARIANT_DEVICE_ROUND.json
# and .log. A failed run sets bench_status to 1.
bench_variants() {
  local prefix=$1 round variant
  shift
  for round in $(seq 1 "$ROUNDS"); do
    for variant in "$@"; do
      # shellcheck disable=SC2086,SC2154
      "$BUILD"/urbis bench --device "$DEVICE" --width "$WIDTH" --height "$HEIGHT" --repeats 3 ${flags[$variant]} \
          --json "$OUT/${prefix}_${variant}_${DEVICE}_${round}.json" > "$OUT/${prefix}_${variant}_${DEVICE}_${round}.log" 2>&1 ||
        bench_status=1
    done
  done
}

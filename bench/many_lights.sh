#!/usr/bin/env bash
# Equal-time error of the light samplers (docs/lights.md § Measured): each of bvh, colliders, uniform
# and power renders the same view for about the same render time, and its error against a converged
# reference is written to OUT/many_lights.md. Any scene and options: everything after OUT goes to
# `urbis render` (a night scene with many lights: see docs/lights.md, e.g.
#   bench/many_lights.sh out --scene bench/night.json --width 320 --height 180
# and on the GPU add --device cuda).
#
# The reference is independent of every image it ranks: the scene the options amount to is saved
# (--save-scene) and rendered again with other sampler seeds (integrator.seed; the city's seed is
# kept): one render of REF_SPP / n samples per entry of REF_SAMPLERS, each with its own seed, and
# their mean taken. Two entries of the same sampler are two independent halves, so their error
# against each other, a quarter of it, estimates the reference's own noise (the line below the
# table); every image's error includes that noise. Errors (bench/exr_error.py): the relative MSE,
# the same after clamping both images to the reference's 99.9th percentile, and the median of
# 16 x 16 tiles' relative MSE: the first counts the fireflies, the other two rank the samplers
# where a handful of pixels would decide it.
#
# Environment: URBIS (./build/urbis), BUDGET (render seconds per sampler, 20), CAL_SPP (spp of the
# timing run, 4), REF_SPP (spp of the reference, 2048), REF_SAMPLERS ("bvh bvh"), SAMPLERS
# ("bvh colliders uniform power").
set -euo pipefail
if [ $# -lt 1 ]; then
    echo "usage: $0 OUT_DIR [urbis render options...]" >&2
    exit 2
fi
out=$1
shift
urbis=${URBIS:-./build/urbis}
budget=${BUDGET:-20}
cal=${CAL_SPP:-4}
refSpp=${REF_SPP:-2048}
refSamplers=${REF_SAMPLERS:-bvh bvh}
samplers=${SAMPLERS:-bvh colliders uniform power}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"

seconds() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seconds_render"])' "$1"; }

# The options that are no scene keys (where and how to run) go to the reference's runs too.
runOptions=()
args=()
while [ $# -gt 0 ]; do
    case $1 in
    --device | --threads | --max-memory) runOptions+=("$1" "$2"); set -- "${@:3}" ;;
    *) args+=("$1"); shift ;;
    esac
done
set -- "${args[@]}" "${runOptions[@]}"

refs=()
read -r -a refList <<<"$refSamplers"
for k in "${!refList[@]}"; do refs+=("$out/reference_${k}_${refList[$k]}.exr"); done
if [ ! -f "${refs[0]}" ]; then
    "$urbis" render "$@" --spp 1 --save-scene "$out/scene.json" --out "$out/scene_probe.exr" >/dev/null
    each=$(((refSpp + ${#refList[@]} - 1) / ${#refList[@]}))
    for k in "${!refList[@]}"; do
        python3 -c 'import json,sys; d = json.load(open(sys.argv[1])); i = d.setdefault("integrator", {})
i["seed"] = (int(i.get("seed", 0)) + 0x9E3779B9 * (int(sys.argv[3]) + 1)) % 2**32; json.dump(d, open(sys.argv[2], "w"), indent=1)' \
            "$out/scene.json" "$out/reference_scene_$k.json" "$k"
        "$urbis" render --scene "$out/reference_scene_$k.json" "${runOptions[@]}" --light-sampler "${refList[$k]}" --spp "$each" \
            --exr-float --out "${refs[$k]}" --stats "$out/reference_$k.json" >/dev/null
    done
fi
reference=$(IFS=,; echo "${refs[*]}")
{
    echo "| sampler | spp | render s | rel. MSE | clamped at p99.9 | tile median | rel. MSE x s | clamped x s |"
    echo "|---|---|---|---|---|---|---|---|"
    for s in $samplers; do
        "$urbis" render "$@" --light-sampler "$s" --spp "$cal" --exr-float --out "$out/cal_$s.exr" --stats "$out/cal_$s.json" >/dev/null
        spp=$(python3 -c "import sys; print(max(1, round($cal * $budget / max(1e-6, float(sys.argv[1])))))" "$(seconds "$out/cal_$s.json")")
        "$urbis" render "$@" --light-sampler "$s" --spp "$spp" --exr-float --out "$out/$s.exr" --stats "$out/$s.json" >/dev/null
        t=$(seconds "$out/$s.json")
        read -r _ e c m < <(python3 "$here/exr_error.py" "$reference" "$out/$s.exr")
        python3 -c "import sys; t, e, c, m = map(float, sys.argv[3:7]); print(f'| {sys.argv[1]} | {sys.argv[2]} | {t:.2f} | {e:.4g} | {c:.4g} | {m:.4g} | {e * t:.4g} | {c * t:.4g} |')" \
            "$s" "$spp" "$t" "$e" "$c" "$m"
    done
    if [ ${#refs[@]} -ge 2 ]; then
        read -r _ e c m < <(python3 "$here/exr_error.py" "${refs[0]}" "${refs[1]}")
        python3 -c "import sys; e, c, m = (float(x) / 4 for x in sys.argv[1:4]); print(f'\nReference noise (its halves against each other / 4): rel. MSE {e:.3g}, clamped {c:.3g}, tile median {m:.3g}')" "$e" "$c" "$m"
    fi
} | tee "$out/many_lights.md"

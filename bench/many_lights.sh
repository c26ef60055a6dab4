#!/usr/bin/env bash
# Equal-time error of the light samplers (docs/lights.md § Measured): each of bvh, colliders, uniform
# and power renders the same view for about the same render time, and its relative MSE against a
# converged reference is written to OUT/many_lights.md. Any scene and options: everything after OUT
# goes to `urbis render` (a night scene with many lights: see docs/lights.md, e.g.
#   bench/many_lights.sh out --scene bench/night.json --width 320 --height 180
# and on the GPU add --device cuda).
#
# Environment: URBIS (./build/urbis), BUDGET (render seconds per sampler, 20), CAL_SPP (spp of the
# timing run, 4), REF_SPP (spp of the reference, 2048), SAMPLERS ("bvh colliders uniform power").
# The reference is the power sampler's, whose first samples the power image shares: if anything the
# comparison favours power.
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
samplers=${SAMPLERS:-bvh colliders uniform power}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"

seconds() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seconds_render"])' "$1"; }

if [ ! -f "$out/reference.exr" ]; then
    "$urbis" render "$@" --light-sampler power --spp "$refSpp" --exr-float --out "$out/reference.exr" \
        --stats "$out/reference.json" >/dev/null
fi
{
    echo "| sampler | spp | render s | rel. MSE | rel. MSE x s |"
    echo "|---|---|---|---|---|"
    for s in $samplers; do
        "$urbis" render "$@" --light-sampler "$s" --spp "$cal" --exr-float --out "$out/cal_$s.exr" --stats "$out/cal_$s.json" >/dev/null
        spp=$(python3 -c "import sys; print(max(1, round($cal * $budget / max(1e-6, float(sys.argv[1])))))" "$(seconds "$out/cal_$s.json")")
        "$urbis" render "$@" --light-sampler "$s" --spp "$spp" --exr-float --out "$out/$s.exr" --stats "$out/$s.json" >/dev/null
        t=$(seconds "$out/$s.json")
        err=$(python3 "$here/exr_error.py" "$out/reference.exr" "$out/$s.exr" | cut -d' ' -f2)
        python3 -c "import sys; t, e = float(sys.argv[3]), float(sys.argv[4]); print(f'| {sys.argv[1]} | {sys.argv[2]} | {t:.2f} | {e:.4g} | {e * t:.4g} |')" "$s" "$spp" "$t" "$err"
    done
} | tee "$out/many_lights.md"

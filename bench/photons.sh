#!/usr/bin/env bash
# Photon buffers against the hash-grid photon map and the path tracer (docs/photons.md; issue 23):
# the generated city and San Francisco, by day and by night, at equal photons per pass. For each view
# every integrator renders SPP passes; a path-traced reference of REF_SPP samples gives each image's
# relative MSE (bench/exr_error.py). Writes OUT/photons.md: per integrator the photon pass (tracing, with
# the buffers' visibility flags and splats or the map's stores), the grid build, the camera pass and the
# frame (all per pass, from --stats), and the ratios the issue asks for:
#   lighting pass: buffers (flags + photons) against the map (photons + grid + its gathers, the map's
#     camera pass less the buffers', which is the same camera pass with an O(1) look-up in place of the gather);
#   frame: the photon map's against the buffers'.
# Usage: bench/photons.sh OUT_DIR [DEVICE [WIDTH HEIGHT [SPP]]]
#   DEVICE cpu (default) or cuda; WIDTH HEIGHT 1024 768 by default (the paper's), 1920 1080 for 1080p.
# Environment: URBIS (./build/urbis), PHOTONS (65536), REF_SPP (1024), SF (the SF extract; its views
# are skipped where it is absent), VIEWS ("city-day city-night sf-day sf-night"), EXTRA (more render options).
set -euo pipefail
if [ $# -lt 1 ]; then
    echo "usage: $0 OUT_DIR [cpu|cuda [WIDTH HEIGHT [SPP]]]" >&2
    exit 2
fi
out=$1
device=${2:-cpu}
width=${3:-1024}
height=${4:-768}
spp=${5:-16}
urbis=${URBIS:-./build/urbis}
photons=${PHOTONS:-65536}
refSpp=${REF_SPP:-1024}
here=$(cd "$(dirname "$0")" && pwd)
sf=${SF:-$here/../../shared/data/sf_downtown_2023.osm.pbf}
views=${VIEWS:-city-day city-night sf-day sf-night}
mkdir -p "$out"

# The options of a view: a street of the generated city (README's generated_street.png), or SF's
# view of the README; by day or at night.
viewOptions() {
    case $1 in
        city-day) echo "--camera 8,1.7,45,-4,0.5,-20 --fov 70 --time 2024-06-21T13:00+02:00" ;;
        city-night) echo "--camera 8,1.7,45,-4,0.5,-20 --fov 70 --time 2024-10-15T21:00+02:00 --exposure 10 --light-sampler bvh" ;;
        sf-day) echo "--osm $sf --camera-geo -122.3940,37.7950,25,200,-25 --fov 60 --time 2023-06-21T13:00-07:00" ;;
        sf-night) echo "--osm $sf --camera-geo -122.3940,37.7950,25,200,-25 --fov 60 --time 2023-06-21T23:00-07:00 --exposure 11 --light-sampler bvh" ;;
    esac
}

{
    echo "| view | integrator | photon pass ms | grid ms | camera pass ms | frame ms | rel. MSE |"
    echo "|---|---|---|---|---|---|---|"
} > "$out/photons.md"
ratios=""
for view in $views; do
    case $view in sf-*) [ -f "$sf" ] || { echo "skipping $view: no $sf" >&2; continue; } ;; esac
    # shellcheck disable=SC2046
    common=(--device "$device" --width "$width" --height "$height" --photons "$photons" $(viewOptions "$view") ${EXTRA:-})
    base="$out/${view}_${width}x${height}"
    if [ ! -f "${base}_reference.exr" ]; then
        "$urbis" render "${common[@]}" --spp "$refSpp" --exr-float --out "${base}_reference.exr" >/dev/null
    fi
    for integrator in photon-buffers photon-map path; do
        "$urbis" render "${common[@]}" --integrator "$integrator" --spp "$spp" --exr-float \
            --out "${base}_$integrator.exr" --stats "${base}_$integrator.json" >/dev/null
    done
    row=$(python3 - "$base" "$view" "$spp" "$here" <<'PY'
import json, subprocess, sys
base, view, spp, here = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
ms = {}
for integrator in ("photon-buffers", "photon-map", "path"):
    stats = json.load(open(f"{base}_{integrator}.json"))
    err = subprocess.run([sys.executable, f"{here}/exr_error.py", f"{base}_reference.exr", f"{base}_{integrator}.exr"],
                         capture_output=True, text=True, check=True).stdout.split()[1]
    p = stats.get("photons", {"seconds": {"flags": 0, "photons": 0, "grid": 0, "camera": stats["seconds_render"]}})["seconds"]
    ms[integrator] = {k: 1000 * v / spp for k, v in p.items()}
    ms[integrator]["frame"] = 1000 * stats["seconds_render"] / spp
    m = ms[integrator]
    print(f"| {view} | {integrator} | {m['flags'] + m['photons']:.1f} | {m['grid']:.1f} | {m['camera']:.1f} | {m['frame']:.1f} | {float(err):.4g} |")
b, m = ms["photon-buffers"], ms["photon-map"]
lighting_b = b["flags"] + b["photons"]
lighting_m = m["photons"] + m["grid"] + max(0.0, m["camera"] - b["camera"])
print(f"RATIO {view}: lighting pass map/buffers {lighting_m / lighting_b:.2f}x (goal 4x), frame map/buffers {m['frame'] / b['frame']:.2f}x (goal 2.5x)")
PY
)
    echo "$row" | grep -v '^RATIO' >> "$out/photons.md"
    ratios+=$(echo "$row" | grep '^RATIO')$'\n'
done
echo >> "$out/photons.md"
printf '%s' "$ratios" | sed 's/^RATIO /- /' >> "$out/photons.md"
cat "$out/photons.md"

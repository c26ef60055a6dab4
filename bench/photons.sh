#!/usr/bin/env bash
# Photon buffers against the hash-grid photon map and the path tracer (docs/photons.md):
# the generated city and San Francisco, by day and by night, at equal photons per pass. For each view
# every integrator renders SPP passes; with REF_SPP > 0 a path-traced reference of REF_SPP samples gives
# each image's relative MSE (bench/exr_error.py), and the photon map and the path tracer render again at
# the passes that take them the photon buffers' time (equal-time error). Writes OUT/photons.md: per
# integrator, ms per pass, the photon pass (tracing, with the buffers' visibility flags and splats or
# the map's stores), the grid build, the camera pass, the frame (all from --stats), the lighting pass
# timed apart (photons.seconds.lighting_pass: the gathers or look-ups of every pixel's first hit), and
# the ratios the goals ask for:
#   lighting pass, the paper's measure: the map's gathers against the buffers' look-ups (goal 4x);
#   photon and lighting passes: the map's photons + grid + gathers against the buffers' flags + photons + look-ups;
#   frame: the photon map's against the buffers' (goal 2.5x).
# Usage: bench/photons.sh OUT_DIR [DEVICE [WIDTH HEIGHT [SPP]]]
#   DEVICE cpu (default) or cuda; WIDTH HEIGHT 1024 768 by default (the paper's), 1920 1080 for 1080p.
# Environment: URBIS (./build/urbis), PHOTONS (65536), REF_SPP (1024; 0: times only), SF (the SF
# extract; its views are skipped where it is absent), VIEWS ("city-day city-night sf-day sf-night"),
# EXTRA (more render options).
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

# Passes that take integrator $2's frames of view base $1 the photon buffers' time at SPP passes.
equalTimePasses() {
    python3 -c 'import json, sys
b, o = (json.load(open(f)) for f in sys.argv[1:3])
print(max(1, round(int(sys.argv[3]) * b["seconds_render"] / o["seconds_render"])))' "$1_photon-buffers.json" "$1_$2.json" "$spp"
}

done_views=()
for view in $views; do
    case $view in sf-*) [ -f "$sf" ] || { echo "skipping $view: no $sf" >&2; continue; } ;; esac
    # shellcheck disable=SC2046
    common=(--device "$device" --width "$width" --height "$height" --photons "$photons" $(viewOptions "$view") ${EXTRA:-})
    base="$out/${view}_${width}x${height}"
    for integrator in photon-buffers photon-map path; do
        "$urbis" render "${common[@]}" --integrator "$integrator" --spp "$spp" --exr-float \
            --out "${base}_$integrator.exr" --stats "${base}_$integrator.json" >/dev/null
    done
    if [ "$refSpp" -gt 0 ]; then
        [ -f "${base}_reference.exr" ] ||
            "$urbis" render "${common[@]}" --spp "$refSpp" --exr-float --out "${base}_reference.exr" >/dev/null
        for integrator in photon-map path; do
            n=$(equalTimePasses "$base" "$integrator")
            echo "$n" > "${base}_${integrator}_equal_time.passes"
            "$urbis" render "${common[@]}" --integrator "$integrator" --spp "$n" --exr-float \
                --out "${base}_${integrator}_equal_time.exr" >/dev/null
        done
        # The errors in the background (pure Python, seconds an image), while the next view renders.
        python3 "$here/exr_error.py" "${base}_reference.exr" "${base}_photon-buffers.exr" "${base}_photon-map.exr" \
            "${base}_path.exr" "${base}_photon-map_equal_time.exr" "${base}_path_equal_time.exr" > "${base}_errors.txt" &
    fi
    done_views+=("$view")
done
wait

python3 - "$out" "${width}x${height}" "$spp" "${done_views[@]}" > "$out/photons_${width}x${height}.md" <<'PY'
import json, os, sys
out, size, spp, views = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
print("| view | integrator | photon pass | grid | camera pass | frame | lighting pass (apart) | rel. MSE | equal time: passes | rel. MSE |")
print("|---|---|---|---|---|---|---|---|---|---|")
ratios = []
for view in views:
    base = f"{out}/{view}_{size}"
    errors = {}
    if os.path.exists(f"{base}_errors.txt"):
        for line in open(f"{base}_errors.txt"):
            path, mse = line.split()[:2]
            errors[os.path.basename(path)[len(os.path.basename(base)) + 1:-4]] = float(mse)
    ms = {}
    for integrator in ("photon-buffers", "photon-map", "path"):
        stats = json.load(open(f"{base}_{integrator}.json"))
        p = stats.get("photons", {"seconds": {"flags": 0, "photons": 0, "grid": 0, "camera": stats["seconds_render"],
                                              "lighting_pass": 0}})["seconds"]
        m = {k: 1000 * v / spp for k, v in p.items() if k != "lighting_pass"}
        m["lighting_pass"] = 1000 * p["lighting_pass"]
        m["frame"] = 1000 * stats["seconds_render"] / spp
        ms[integrator] = m
        err = errors.get(integrator)
        eq = f"{base}_{integrator}_equal_time.passes"
        eqPasses = open(eq).read().strip() if os.path.exists(eq) else (str(spp) if integrator == "photon-buffers" and errors else "")
        eqErr = errors.get(f"{integrator}_equal_time", err if integrator == "photon-buffers" else None)
        fmt = lambda e: "" if e is None else f"{e:.4g}"
        lighting = f"{m['lighting_pass']:.2f}" if integrator != "path" else ""
        print(f"| {view} | {integrator} | {m['flags'] + m['photons']:.2f} | {m['grid']:.2f} | {m['camera']:.2f} | "
              f"{m['frame']:.2f} | {lighting} | {fmt(err)} | {eqPasses} | {fmt(eqErr)} |")
    b, m = ms["photon-buffers"], ms["photon-map"]
    both_b = b["flags"] + b["photons"] + b["lighting_pass"]
    both_m = m["photons"] + m["grid"] + m["lighting_pass"]
    ratios.append(f"- {view}: lighting pass map/buffers {m['lighting_pass'] / max(b['lighting_pass'], 1e-9):.2f}x (goal 4x); "
                  f"photon + lighting passes {both_m / both_b:.2f}x; frame map/buffers {m['frame'] / b['frame']:.2f}x (goal 2.5x)")
print()
print("\n".join(ratios))
PY
cat "$out/photons_${width}x${height}.md"

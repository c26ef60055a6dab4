#!/bin/sh
# Procedural facades against their triangle twin: frame time and scene memory of both
# representations, same camera and settings, at mean building heights of about 20, 40 and 80 m
# (the thesis's Figure 4.9), on San Francisco downtown and on a generated city.
#
#   bench/facades.sh [build-dir] [out-dir]
#
# Writes one stats JSON per run into out-dir and prints a table (city, target height, mode,
# mean height, triangles, walls, wall tiles (BVH primitives), cells, bytes_scene, seconds_render, rays/s). A twin that does not
# fit in memory is reported as such (urbis refuses it before building). FACADES_DEVICE=cuda runs
# both representations on the GPU (default: cpu). FACADES_MODES="procedural" runs only that
# representation (default: "procedural triangles"); FACADES_CITIES="generated" only that city;
# FACADES_HEIGHTS="20 40" only those target heights (default "20 40 80"); FACADES_EXTRA is added
# to every urbis command (e.g. "--wall-tiles 4x4").
set -u
BUILD=${1:-build}
OUT=${2:-bench/out}
DATA=${URBIS_DATA:-$(dirname "$0")/../../shared/data}
SIZE=${FACADES_SIZE:-"--width 640 --height 360 --spp 4"}
DEVICE=${FACADES_DEVICE:-cpu}
MODES=${FACADES_MODES:-"procedural triangles"}
CITIES=${FACADES_CITIES:-"sf generated"}
HEIGHTS=${FACADES_HEIGHTS:-"20 40 80"}
EXTRA=${FACADES_EXTRA:-}
mkdir -p "$OUT"

# city name | urbis options | camera | native mean height (m) of that city at --height-scale 1
SF="--osm $DATA/sf_downtown_2023.osm.pbf"
SF_CAMERA="--camera-geo -122.4030,37.7880,60,45,-5"
GEN="--buildings 3000 --seed 7 --building-height-range 10:30"
GEN_CAMERA="--camera -300,40,300,0,20,0"

run() { # name options camera scale target
    case " $CITIES " in *" $1 "*) ;; *) return ;; esac
    for mode in $MODES; do
        stats="$OUT/$1_$5m_$mode.json"
        rm -f "$stats"
        if ! "$BUILD/urbis" render $2 $3 $SIZE --device "$DEVICE" --height-scale "$4" --geometry $mode $EXTRA \
                --out "$OUT/$1_$5m_$mode.png" --stats "$stats" 2>"$OUT/$1_$5m_$mode.err"; then
            printf '%-10s %4sm %-10s %s\n' "$1" "$5" "$mode" "$(cat "$OUT/$1_$5m_$mode.err")"
            continue
        fi
        python3 - "$stats" "$1" "$5" "$mode" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]:<10} {sys.argv[3]:>4}m {sys.argv[4]:<10} mean {s['counts']['mean_building_height']:6.1f} m  "
      f"tris {s['triangles']:>11,}  walls {s['walls']:>7,}  tiles {s.get('wall_tiles', s['walls']):>7,}  cells {s['facade_cells']:>10,}  "
      f"bytes {s['bytes_scene']:>14,}  render {s['seconds_render']:8.3f} s  bvh {s['seconds']['bvh']:7.2f} s  "
      f"{s['rays_per_second'] / 1e6:6.2f} Mrays/s")
PY
    done
}

# Mean heights at scale 1 (counts.mean_building_height of a stats run): SF 31.6 m, the generated city 12.1 m.
for target in $HEIGHTS; do
    run sf "$SF" "$SF_CAMERA" "$(python3 -c "print($target / 31.6)")" "$target"
    run generated "$GEN" "$GEN_CAMERA" "$(python3 -c "print($target / 12.1)")" "$target"
done

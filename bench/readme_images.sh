#!/usr/bin/env bash
# The README's pictures, each made by the command the README shows beside it, into $OUT (default
# docs/images). Usage: bench/readme_images.sh [URBIS_BINARY] [DATA_DIR]; defaults ./build/urbis and
# ../shared/data (the real extracts). On a GPU machine `--device auto` renders them there.
set -euo pipefail
URBIS=${1:-./build/urbis}
DATA=${2:-../shared/data}
OUT=${OUT:-docs/images}
mkdir -p "$OUT"
"$URBIS" render --width 960 --height 540 --spp 64 --out "$OUT/default.png"
"$URBIS" render --camera 150,6,3,20,35,-10 --fov 55 --width 960 --height 540 --spp 64 --out "$OUT/facades.png"
"$URBIS" render --camera 97,2.5,3,118,9,-7 --fov 70 --width 960 --height 540 --spp 128 --out "$OUT/shop_windows.png"
"$URBIS" render --osm docs/examples/roof_shapes.osm --camera 0,62,72,0,0,2 --fov 72 --width 960 --height 400 --spp 64 \
    --out "$OUT/roof_shapes.png"
"$URBIS" render --osm "$DATA/sf_downtown_2023.osm.pbf" --width 960 --height 540 --spp 32 --out "$OUT/sf_downtown.png"
"$URBIS" render --osm "$DATA/london_city_2020.osm.pbf" --camera-geo -0.1035,51.5095,160,45,-18 --fov 50 --width 960 \
    --height 540 --spp 32 --out "$OUT/london_city.png"
"$URBIS" render --osm "$DATA/sf_downtown_2023.osm.pbf" --camera-geo -122.3940,37.7950,25,200,-25 --sun 55,200 --fov 60 --width 960 \
    --height 540 --spp 64 --out "$OUT/sf_street.png"
"$URBIS" render --camera 8,1.7,45,-4,0.5,-20 --fov 70 --width 960 --height 540 --spp 64 --out "$OUT/generated_street.png"
"$URBIS" render --buildings 3000 --camera -60,110,430,0,0,230 --fov 55 --width 960 --height 540 --spp 128 \
    --out "$OUT/generated_river.png"
SF_STREET=(--osm "$DATA/sf_downtown_2023.osm.pbf" --camera-geo -122.3940,37.7950,25,200,-25 --fov 60 --width 960 --height 540)
"$URBIS" render "${SF_STREET[@]}" --time 2023-06-21T13:00-07:00 --spp 256 --out "$OUT/sf_noon.png"
"$URBIS" render "${SF_STREET[@]}" --time 2023-06-21T20:25-07:00 --exposure 4 --spp 512 --out "$OUT/sf_sunset.png"
"$URBIS" render "${SF_STREET[@]}" --time 2023-06-21T23:00-07:00 --exposure 11 --light-sampler bvh --spp 4096 --denoise \
    --out "$OUT/sf_night.png"
"$URBIS" render --time 2024-10-15T21:00+02:00 --exposure 10 --light-sampler bvh --width 960 --height 540 --spp 2048 --denoise \
    --out "$OUT/generated_night.png"
"$URBIS" render --planet --camera-orbit 12000,25,10 --width 960 --height 540 --spp 64 --out "$OUT/planet_orbit.png"
"$URBIS" render --scene docs/examples/planet_clouds.json --width 640 --height 360 --spp 16 --denoise \
    --out "$OUT/planet_clouds.png"
"$URBIS" render --osm "$DATA/sf_downtown_2023.osm.pbf" --camera-geo -122.3950,37.7950,35,300,-20 --fov 60 --width 960 \
    --height 540 --spp 256 --out "$OUT/sf_park_trees.png"
"$URBIS" render --scene docs/examples/forest_clouds.json --buildings 200 --width 960 --height 540 --spp 512 --denoise \
    --out "$OUT/forest_clouds.png"
# San Francisco on its DEM: DEM names a .vrt of the two osmnx tiles (GDAL; the GPU machine's binaries lack it).
if [[ -n ${DEM:-} ]]; then
  "$URBIS" render --osm "$DATA/sf_downtown_2023.osm.pbf" --dem "$DEM" --camera-geo -122.3935,37.7952,260,270,-14 --fov 60 \
      --width 640 --height 360 --spp 8 --denoise --out "$OUT/sf_dem.png"
fi
"$URBIS" render --scene docs/examples/lake_hills.json --width 960 --height 540 --spp 16 --denoise --out "$OUT/lake_hills.png"
STREET=(--camera 8,1.7,45,-4,0.5,-20 --fov 70 --width 960 --height 540 --time 2024-06-21T13:00+02:00)
"$URBIS" render "${STREET[@]}" --integrator photon-buffers --max-depth 1 --spp 64 --out "$OUT/photons_street_direct.png"
"$URBIS" render "${STREET[@]}" --integrator photon-buffers --spp 64 --out "$OUT/photons_street_buffers.png"
# The animation: frames of the scene file's keyframes, then a GIF with one palette (ffmpeg, optional).
FRAMES=$(mktemp -d)
"$URBIS" render --scene docs/examples/dusk_flyover.json --frames 0: --out "$FRAMES/f%03d.png"
ffmpeg -nostdin -loglevel error -y -framerate 9 -i "$FRAMES/f%03d.png" \
    -vf "split[a][b];[a]palettegen[p];[b][p]paletteuse" "$OUT/dusk_flyover.gif"
rm -r "$FRAMES"

#!/usr/bin/env bash
# BENCHMARKS.md § Terrain marches, frames with water: 1 spp frames (1920 x 1080 unless told) of the fBm landscape alone, the same
# landscape with its lake and the atmosphere (docs/examples/lake_hills.json), and San Francisco on its
# DEM with everything on (streets, water, trees, clouds, atmosphere), each found by the min/max
# hierarchy and by the Cambridge rule (lei); then the marches' accuracy against the fixed-step
# reference (bench/terrain_bench.sh: hits, missed, HDE, IDE, time). Prints one line a frame
# (seconds.render of --stats) and writes the stats, the pictures and the accuracy JSON to $OUT.
# Usage: bench/terrain_water_bench.sh BUILD_DIR [DEVICE [WIDTH HEIGHT]]
#   DEVICE cpu (default) or cuda. The DEM needs a build with GDAL (on the GPU machine, gpu_deps.sh's
#   GDAL_FOR carries its libraries). Data: $URBIS_OSMNX_DATA (elevation1.tif) and $URBIS_SHARED_DATA
#   (sf_downtown_2023.osm.pbf), by default where they lie on the development machine.
set -uo pipefail
BUILD=${1:?build folder}
DEVICE=${2:-cpu}
WIDTH=${3:-1920}
HEIGHT=${4:-1080}
OUT=${OUT:-$PWD/terrain-water-out}
HERE=$(cd "$(dirname "$0")" && pwd)
DEM=${URBIS_OSMNX_DATA:-/usr/share/doc/python-osmnx-doc/examples/tests/input_data}/elevation1.tif
SF=${URBIS_SHARED_DATA:-$HERE/../../shared/data}/sf_downtown_2023.osm.pbf
LAKE=$HERE/../docs/examples/lake_hills.json
mkdir -p "$OUT"
status=0
declare -A scenes=(
  [terrain]="--scene $LAKE --no-streets --no-aerial-perspective"
  [terrain_water_atmosphere]="--scene $LAKE"
  [sf_dem_all]="--osm $SF --dem $DEM --clouds 0.3 --camera-geo -122.3935,37.7952,260,270,-14 --fov 60"
)
for scene in terrain terrain_water_atmosphere sf_dem_all; do
  for march in hierarchy lei; do
    name=${scene}_${march}_${DEVICE}
    # shellcheck disable=SC2086
    if "$BUILD"/urbis render ${scenes[$scene]} --terrain-march "$march" --device "$DEVICE" --width "$WIDTH" \
        --height "$HEIGHT" --spp 1 --stats "$OUT/$name.json" --out "$OUT/$name.png" > "$OUT/$name.log" 2>&1; then
      echo "$name render_s=$(sed -n 's/.*"render": *\([0-9.e+-]*\).*/\1/p' "$OUT/$name.json" | head -1)"
    else
      status=1
      echo "$name FAILED: $(tail -1 "$OUT/$name.log")"
    fi
  done
done
REPEATS=$([[ $DEVICE == cpu ]] && echo 3 || echo 5)
OUT=$OUT bash "$HERE/terrain_bench.sh" "$BUILD" "$DEVICE" "$WIDTH" "$HEIGHT" "$REPEATS" || status=1
exit $status

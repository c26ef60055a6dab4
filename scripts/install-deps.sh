#!/usr/bin/env bash
# Installs the Debian 12 packages urbis builds and tests with. Idempotent: installs only what is missing.
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libosmium2-dev libprotozero-dev libexpat1-dev libbz2-dev zlib1g-dev   # OSM import
  libgeos-dev                                                           # footprint triangulation, validity
  libcgal-dev                                                           # straight skeletons (hipped roofs)
  libcli11-dev nlohmann-json3-dev libpng-dev libtbb-dev                 # command line, JSON, PNG, threads
  libopenexr-dev                                                        # EXR output of the film
  libgtest-dev libbenchmark-dev libembree-dev                           # tests, benchmarks, speed reference
  python-osmnx-doc                                                      # a tiny real OSM extract for the tests
  python3                                                               # scripts/check_layers.py (ctest: layers)
  python3-yaml                                                          # scripts/openjd/check_template.py (ctest: openjd_template)
  libgdal-dev gdal-bin                                                  # DEM rasters for the terrain (--dem); gdalbuildvrt for mosaics
  libglfw3-dev libimgui-dev libgl-dev                                   # the viewer's window (urbis view)
  libopenmpi-dev openmpi-bin                                            # mpirun -n N urbis render (docs/scale.md)
  xvfb xauth libgl1-mesa-dri                                            # the viewer's tests: a display without a screen
  libtinygltf-dev                                                       # glTF export (urbis export)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"

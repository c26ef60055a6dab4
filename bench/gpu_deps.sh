#!/bin/sh
# Gathers here what bench/gpu.sh needs on the GPU machine, which reaches no package registry: the
# Debian 12 packages of the libraries urbis links that that machine lacks (as .deb files; gpu.sh
# unpacks them there, so that the carried folder stays small: Boost's headers alone unpack to
# 150 MB) and the OSM extracts that the GPU tests and benchmarks read.
#   bench/gpu_deps.sh [deps-dir]      (default .deps, git-ignored; carry it to the GPU machine)
# With GDAL_FOR=BINARY (an urbis built here with GDAL), also the shared libraries that binary needs
# beyond glibc's and libstdc++, with PROJ's database, as one xz tarball (gdal.tar.xz: GDAL's 108
# libraries are 157 MB unpacked, far over the carry's 64 MiB; as xz about a third of that, so check the
# `du -sh` below against the carry with the binaries), which deps_root.sh unpacks there, and
# the osmnx DEM tiles: so that `--dem` runs on the GPU machine with the binary built here.
set -eu
DEPS=${1:-.deps}
DATA=${URBIS_DATA:-$(dirname "$0")/../../shared/data}
VILLAGE=/usr/share/doc/python-osmnx-doc/examples/tests/input_data
mkdir -p "$DEPS/debs" "$DEPS/data"
# apt-get download writes into the current folder, as the _apt user where it can.
(cd "$DEPS/debs" && apt-get download \
    libosmium2-dev libprotozero-dev libexpat1-dev libexpat1 libbz2-dev zlib1g-dev \
    libgeos-dev libgeos3.11.1 libgeos-c1v5 libcgal-dev libboost1.74-dev \
    libgmp-dev libgmp10 libgmpxx4ldbl libmpfr-dev libmpfr6 \
    libtbb-dev libtbb12 libtbbmalloc2 libtbbbind-2-5 libtinygltf2d \
    libopenexr-dev libopenexr-3-1-30 libimath-dev libimath-3-1-29 \
    libstb0 libglfw3 libopengl0 libglvnd0 libx11-6 libx11-data libxcb1 libxau6 libxdmcp6 libbsd0 libmd0)   # urbis view's window
cp "$VILLAGE/planet_10.068,48.135_10.071,48.137.osm" "$VILLAGE/West-Oakland.osm.bz2" "$DEPS/data/"
cp "$DATA/sf_downtown_2023.osm.pbf" "$DATA/london_city_2020.osm.pbf" "$DEPS/data/"
if [ -n "${GDAL_FOR:-}" ]; then
  PACK=$(mktemp -d)
  mkdir -p "$PACK/gdal/lib" "$PACK/gdal/proj"
  ldd "$GDAL_FOR" | awk '$3 ~ /^\// {print $3}' |
      grep -vE '/(libc|libm|libstdc\+\+|libgcc_s|libpthread|libdl|librt|ld-linux-x86-64)\.so' |
      while read -r lib; do cp -L "$lib" "$PACK/gdal/lib/"; done
  cp /usr/share/proj/proj.db "$PACK/gdal/proj/"
  tar -C "$PACK" -cf - gdal | xz -6 -T0 > "$DEPS/gdal.tar.xz"
  rm -rf "$PACK"
  cp "$VILLAGE/elevation1.tif" "$VILLAGE/elevation2.tif" "$DEPS/data/"
fi
du -sh "$DEPS"

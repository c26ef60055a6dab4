# Sourced by the GPU machine's scripts (bash): sets ROOT to the carried dependencies' file tree and
# LD_LIBRARY_PATH to its libraries. $DEPS/root where unpacked already, else the .debs of $DEPS/debs
# (bench/gpu_deps.sh) unpacked outside the working tree (unpacked, they are too large to carry).
ROOT=$DEPS/root
if [[ ! -d $ROOT/usr && -d $DEPS/debs ]]; then
  ROOT=${TMPDIR:-/tmp}/urbis-deps-root
  if [[ ! -d $ROOT/usr ]]; then
    for f in "$DEPS"/debs/*.deb; do dpkg -x "$f" "$ROOT" || exit 1; done
  fi
fi
export LD_LIBRARY_PATH=$ROOT/usr/lib/x86_64-linux-gnu:${LD_LIBRARY_PATH:-}
# GDAL's libraries and PROJ's database where gpu_deps.sh packed them (GDAL_FOR), unpacked once.
if [[ -f $DEPS/gdal.tar.xz ]]; then
  GDAL_ROOT=${TMPDIR:-/tmp}/urbis-gdal
  if [[ ! -d $GDAL_ROOT/gdal ]]; then
    mkdir -p "$GDAL_ROOT" && tar -C "$GDAL_ROOT" -xJf "$DEPS/gdal.tar.xz" || exit 1
  fi
  export LD_LIBRARY_PATH=$LD_LIBRARY_PATH:$GDAL_ROOT/gdal/lib PROJ_DATA=$GDAL_ROOT/gdal/proj PROJ_LIB=$GDAL_ROOT/gdal/proj
fi

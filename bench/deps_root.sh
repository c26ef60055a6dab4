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

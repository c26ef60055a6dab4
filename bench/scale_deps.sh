#!/bin/sh
# Gathers Open MPI's runtime as Debian 12 .debs into DIR/debs (default .deps), beside what
# bench/gpu_deps.sh gathers, for bench/scale.sh's MPI steps on the GPU machine, which reaches no
# package registry and has no mpirun: bench/deps_root.sh unpacks them there and scale.sh points
# OPAL_PREFIX at the unpacked tree.
#   sh bench/scale_deps.sh [deps-dir]
set -eu
DEPS=${1:-.deps}
mkdir -p "$DEPS/debs"
(cd "$DEPS/debs" && apt-get download \
    openmpi-bin openmpi-common libopenmpi3 libpmix2 libhwloc15 libevent-core-2.1-7 libevent-pthreads-2.1-7 \
    libfabric1 libucx0 libibverbs1 librdmacm1 libnl-3-200 libnl-route-3-200 libnuma1 libpsm-infinipath1 \
    libpsm2-2 libmunge2 libxnvctrl0 libxml2 libicu72 libpciaccess0 libxext6 libx11-6 libxcb1 libxau6 libxdmcp6)
du -sh "$DEPS"

#!/bin/sh
# Size of the CUDA kernels in instructions (sm_90 machine code, 16 bytes each), without a GPU: the
# render kernel's size decides how often it waits on instruction fetches (docs/gpu_notes.md § Instruction cache).
#   bench/kernel_size.sh [extra nvcc flags]
set -eu
cd "$(dirname "$0")/.."
NVCC=${NVCC:-$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)}
CUBIN=$(mktemp --suffix=.cubin)
trap 'rm -f "$CUBIN"' EXIT
"$NVCC" -std=c++20 -arch=sm_90 -cubin -O3 --use_fast_math -DURBIS_HAVE_CUDA=1 -I src "$@" src/gpu/gpu_backend.cu -o "$CUBIN"
readelf -SW "$CUBIN" 2>/dev/null | python3 -c '
import re, sys
for line in sys.stdin:
    m = re.search(r"\.text\.(\S+)\s+\S+\s+\S+\s+\S+\s+([0-9a-f]+)", line)
    if m and int(m.group(2), 16):
        name = next((k for k in ("renderKernel", "aovKernel", "closestKernel", "occludedKernel") if k in m.group(1)), m.group(1))
        costly = re.search(r"ILb([01])E", m.group(1))
        if costly: name += {"1": "<costly leaves>", "0": "<no costly leaves>"}[costly.group(1)]
        features = re.search(r"ILj([0-9]+)E", m.group(1))   # the render kernel per scene content (gpu/render_variants.h)
        if features:
            bits = int(features.group(1))
            name += "<" + "+".join(n for i, n in enumerate(("triangle", "wall", "ground", "lamp", "terrain", "tree",
                                                             "planet", "clouds", "photons")) if bits >> i & 1) + ">"
        print(f"{name:24s} {int(m.group(2), 16) // 16:6d} instructions")'

#!/usr/bin/env bash
# The animation on the GPU (docs/animation.md): the README's fly-over rendered with --device cuda,
# frame 20 rendered alone and compared byte for byte with frame 20 of the sequence, and the time of
# each frame (the progress lines). Logs and frames go to $OUT (default ./animation-out).
# Usage: bench/animation_gpu.sh [URBIS_BINARY]; a binary built here with CUDA runs there as it is
# (bench/gpu.sh says how to carry it with its dependencies, bench/deps_root.sh).
set -euo pipefail
URBIS=${1:-./build/urbis}
OUT=${OUT:-$PWD/animation-out}
SCENE=$(dirname "$0")/../docs/examples/dusk_flyover.json
mkdir -p "$OUT"
"$URBIS" render --scene "$SCENE" --device cuda --verbose --frames 0: --out "$OUT/seq/f%03d.png" | tee "$OUT/sequence.log"
"$URBIS" render --scene "$SCENE" --device cuda --frames 20 --out "$OUT/alone/f%03d.png" | tee "$OUT/alone.log"
if cmp "$OUT/seq/f020.png" "$OUT/alone/f020.png"; then echo "frame 20 alone equals frame 20 of the sequence"; else
  echo "frame 20 alone DIFFERS from frame 20 of the sequence"; exit 1; fi
tar -C "$OUT" -czf "$OUT/frames.tar.gz" seq alone

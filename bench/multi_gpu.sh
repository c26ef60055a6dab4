#!/usr/bin/env bash
# The figures of BENCHMARKS.md § Several GPUs: one process spreading tiles (`--devices 0,...,n-1`)
# over 1, 2, 4, 8 GPUs of one host: 1080p and 4K frames of downtown San Francisco and of the generated
# 1M-building city at 64 spp, and a 240-frame sequence (the README's fly-over at 59.75 fps) spread by
# frame; each with its time, speed-up and parallel efficiency against one GPU, as a table.
# Usage: bench/multi_gpu.sh [steps]   steps: a comma list of sf,city,sequence (default all three)
# Environment: URBIS_BIN (default build/urbis), GPUS (default 1,2,4,8, up to the machine's count),
#   SF (sf_downtown_2023.osm.pbf; default $URBIS_DEPS/data/ or ../shared/data/), SPP (64),
#   OUT (default ./multi-gpu-out): multi_gpu.log, SCENE_SIZE_N.json (--stats), seq_N.log,
#   SEQ_FILM (WIDTHxHEIGHT:SPP of the sequence's frames; default the README's 400x225:8, which the host
#   bounds: docs/multi_gpu.md § Sequences; 1920x1080:32 gives the GPUs the larger share).
# Every image of a row must be the same file (the tiles' pixels are the one-GPU frame's, bit for bit):
# the script says how many distinct images each row made. The city is built once a run (1M buildings:
# about 40 s of host time on the H200 machine), so a row of four GPU counts pays four builds.
set -uo pipefail
STEPS=",${1:-sf,city,sequence},"
OUT=${OUT:-$PWD/multi-gpu-out}
BIN=${URBIS_BIN:-build/urbis}
SPP=${SPP:-64}
HERE=$(cd "$(dirname "$0")" && pwd)
SF=${SF:-${URBIS_DEPS:-.deps}/data/sf_downtown_2023.osm.pbf}
[[ -f $SF ]] || SF=$HERE/../../shared/data/sf_downtown_2023.osm.pbf
COUNT=$(nvidia-smi -L 2>/dev/null | grep -c '^GPU' || true)
mkdir -p "$OUT"
LOG=$OUT/multi_gpu.log
say() { echo "== $* ($(date +%T))" | tee -a "$LOG"; }
status=0
(( COUNT > 0 )) || { echo "multi_gpu.sh: no GPU (nvidia-smi -L lists none)" | tee -a "$LOG"; exit 1; }
counts=()
for n in $(tr , " " <<< "${GPUS:-1,2,4,8}"); do (( n <= COUNT )) && counts+=("$n"); done
say "$COUNT GPUs here; measuring on ${counts[*]}"
devices() { seq -s, 0 $(( $1 - 1 )); }

# One frame, the render seconds of --stats (the tile queue's wall time), on each GPU count.
frame_row() {   # name size source-args...
  local name=$1 size=$2; shift 2
  for n in "${counts[@]}"; do
    say "$name $size on $n GPUs"
    "$BIN" render --devices "$(devices "$n")" --verbose "$@" --width "${size%x*}" --height "${size#*x}" --spp "$SPP" \
        --out "$OUT/${name}_${size}_$n.png" --stats "$OUT/${name}_${size}_$n.json" >>"$LOG" 2>&1 || status=1
  done
  python3 - "$OUT" "$name" "$size" "${counts[@]}" <<'PY' | tee -a "$LOG"
import hashlib, json, os, sys
out, name, size, counts = sys.argv[1], sys.argv[2], sys.argv[3], [int(n) for n in sys.argv[4:]]
first, images, cells = None, set(), []
for n in counts:
    path = os.path.join(out, f"{name}_{size}_{n}.json")
    if not os.path.exists(path):
        cells.append(f"{n}: failed")
        continue
    stats = json.load(open(path))
    s = stats["seconds"]["render"]
    first = first or (n, s)
    speedup = first[1] / s
    bands = "/".join(str(b) for b in stats.get("tiles_by_device", []))   # the bands each GPU took
    cells.append(f"{n} GPUs {s:.3f} s (x{speedup:.2f}, eff {speedup * first[0] / n:.2f}{', bands ' + bands if bands else ''})")
    images.add(hashlib.md5(open(os.path.join(out, f"{name}_{size}_{n}.png"), "rb").read()).hexdigest())
print(f"| {name} {size} | " + " | ".join(cells) + f" | {len(images)} distinct image(s) |")
PY
}

if [[ $STEPS == *,sf,* ]]; then
  for size in 1920x1080 3840x2160; do frame_row sf "$size" --osm "$SF"; done
fi
if [[ $STEPS == *,city,* ]]; then
  for size in 1920x1080 3840x2160; do frame_row city1m "$size" --buildings 1000000; done
fi

# A 240-frame sequence spread by frame over the GPUs (each renders whole frames from one upload).
if [[ $STEPS == *,sequence,* ]]; then
  python3 - "$HERE/../docs/examples/dusk_flyover.json" "$OUT/flyover_240.json" "${SEQ_FILM:-400x225:8}" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["animation"]["fps"] = 59.75   # 4 s of keyframes: frames 0..239
size, spp = sys.argv[3].split(":")
scene["film"]["width"], scene["film"]["height"] = (int(v) for v in size.split("x"))
scene["integrator"]["spp"] = int(spp)
json.dump(scene, open(sys.argv[2], "w"))
PY
  for n in "${counts[@]}"; do
    say "240 frames on $n GPUs"
    start=$(date +%s%N)
    "$BIN" render --scene "$OUT/flyover_240.json" --devices "$(devices "$n")" --frames 0:239 --overwrite \
        --out "$OUT/seq_$n/f%04d.png" >"$OUT/seq_$n.log" 2>&1 || status=1
    echo "$n $(( ($(date +%s%N) - start) / 1000000 ))" >>"$OUT/seq_times"
  done
  python3 - "$OUT/seq_times" "${SEQ_FILM:-400x225:8}" <<'PY' | tee -a "$LOG"
import sys
rows = [tuple(int(v) for v in line.split()) for line in open(sys.argv[1])]
first = rows[0]
print(f"| 240 frames {sys.argv[2]} | " + " | ".join(
    f"{n} GPUs {ms / 1000:.2f} s (x{first[1] / ms:.2f}, eff {first[1] / ms * first[0] / n:.2f})" for n, ms in rows) + " |")
PY
  rm -f "$OUT/seq_times"
fi
exit $status

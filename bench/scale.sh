#!/usr/bin/env bash
# The figures of BENCHMARKS.md § Scale: the generated city of N buildings, its host build time and
# peak memory, device memory and frame time (`urbis render --stats`); and MPI strong scaling, one frame
# across 1, 2, 4, 8, 16 ranks of the 16 host cores, each rank given 16/ranks threads.
# Usage: bench/scale.sh [steps] [sizes]
#   steps: a comma list of city,mpi,sequence (default city,mpi); sizes: building counts for `city`
#   (default 1000000,10000000). On the CPU VM: URBIS_DEVICE=cpu SCALE_CORES=2 bench/scale.sh city,mpi 100000,1000000
# Environment: URBIS_BIN (default build/urbis, built with MPI for the mpi step), URBIS_DEVICE (cuda),
#   SCALE_CORES (host cores, default nproc), MPI_RANKS (default 1,2,4,8,16 up to SCALE_CORES),
#   OUT (default ./scale-out): scale.log, city_N_DEVICE.json, mpi_R.json, mpi_R.png.
# On the GPU machine (no package registry): build here with -DURBIS_GDAL=OFF, put urbis, this script,
#   `sh bench/gpu_deps.sh DIR/.deps` and `sh bench/scale_deps.sh DIR/.deps` (Open MPI's runtime) in DIR,
#   then there: cd DIR; export DEPS=$PWD/.deps URBIS_DEPS=$PWD/.deps; source bench/deps_root.sh; URBIS_BIN=$PWD/urbis bash scale.sh
set -uo pipefail
STEPS=",${1:-city,mpi},"
SIZES=${2:-1000000,10000000}
OUT=${OUT:-$PWD/scale-out}
BIN=${URBIS_BIN:-build/urbis}
DEVICE=${URBIS_DEVICE:-cuda}
CORES=${SCALE_CORES:-$(nproc)}
mkdir -p "$OUT"
LOG=$OUT/scale.log
say() { echo "== $* ($(date +%T))" | tee -a "$LOG"; }
run() { "$@" 2>&1 | tee -a "$LOG"; return "${PIPESTATUS[0]}"; }
status=0

# Open MPI unpacked from .debs (bench/scale_deps.sh) runs from wherever it lies once told its prefix.
MPIRUN=$(command -v mpirun || true)   # the carried one, where there is one, wins: its libraries are first on the path
if [[ -n ${ROOT:-} && -x $ROOT/usr/bin/mpirun.openmpi ]]; then
  export OPAL_PREFIX=$ROOT/usr PATH=$ROOT/usr/bin:$PATH
  export LD_LIBRARY_PATH=$ROOT/usr/lib/x86_64-linux-gnu/openmpi/lib:$LD_LIBRARY_PATH
  MPIRUN=$ROOT/usr/bin/mpirun.openmpi
fi
MPI_ARGS=(--oversubscribe --bind-to none)
[[ $(id -u) -eq 0 ]] && MPI_ARGS+=(--allow-run-as-root)

# Host build time and memory, device memory and frame time of the generated city, from above.
if [[ $STEPS == *,city,* ]]; then
  for n in ${SIZES//,/ }; do
    say "city of $n buildings on $DEVICE"
    run /usr/bin/time -v "$BIN" render --device "$DEVICE" --buildings "$n" --width 1920 --height 1080 --spp 4 \
        --out "$OUT/city_${n}_${DEVICE}.png" --stats "$OUT/city_${n}_${DEVICE}.json" || status=1
    [[ -f $OUT/city_${n}_${DEVICE}.json ]] && python3 - "$OUT/city_${n}_${DEVICE}.json" <<'PY' | tee -a "$LOG"
import json, sys
s = json.load(open(sys.argv[1]))
t = s["seconds"]
gib = 2.0 ** 30
print(f"buildings {s['counts']['buildings']}: import+citygen+bvh {t['import']:.1f}+{t['citygen']:.1f}+{t['bvh']:.1f} s, "
      f"peak host {s['peak_host_bytes'] / gib:.2f} GiB, scene {s['bytes_scene'] / gib:.2f} GiB, "
      f"device {(s['peak_device_bytes'] or 0) / gib:.2f} GiB, frame ({s['spp']} spp) {t['render']:.3f} s")
PY
  done
fi

# Strong scaling: the same frame (the default world, 1920x1080, CPU) over more ranks, the cores shared out.
if [[ $STEPS == *,mpi,* ]]; then
  [[ -n $MPIRUN ]] || { echo "scale.sh: no mpirun (install openmpi-bin, or carry bench/scale_deps.sh's .debs)" | tee -a "$LOG"; exit 1; }
  for ranks in $(tr , " " <<< "${MPI_RANKS:-1,2,4,8,16}"); do
    ranks=${ranks//,/}
    (( ranks <= CORES )) || continue
    threads=$(( CORES / ranks ))
    say "one frame on $ranks ranks x $threads threads"
    run "$MPIRUN" -n "$ranks" "${MPI_ARGS[@]}" "$BIN" render --device cpu --threads "$threads" --width 1920 --height 1080 \
        --spp 16 --out "$OUT/mpi_${ranks}.png" --stats "$OUT/mpi_${ranks}.json" || status=1
  done
  python3 - "$OUT" ${MPI_RANKS:-1,2,4,8,16} <<'PY' | tee -a "$LOG"
import json, os, sys
out, ranks = sys.argv[1], [int(r) for r in sys.argv[2].split(",")]
first = None
for r in ranks:
    path = os.path.join(out, f"mpi_{r}.json")
    if not os.path.exists(path): continue
    s = json.load(open(path))["seconds"]["render"]
    first = first or (r, s)  # speed-up and efficiency against the fewest ranks measured
    speedup = first[1] / s
    print(f"{r:3d} ranks: render {s:8.2f} s, speed-up {speedup:5.2f}, efficiency {speedup * first[0] / r:5.2f}")
PY
  # Every rank's film is gathered bit for bit: the images of all rank counts are the same file.
  if ls "$OUT"/mpi_*.png >/dev/null 2>&1; then
    n=$(md5sum "$OUT"/mpi_*.png | awk '{print $1}' | sort -u | wc -l)
    echo "distinct images over the rank counts: $n (1 expected)" | tee -a "$LOG"
  fi
fi

# A sequence spread by frame: the README's fly-over (docs/examples/dusk_flyover.json), frames 0-31.
if [[ $STEPS == *,sequence,* ]]; then
  if "$BIN" render --help | grep -q -- "--frames"; then
    for ranks in $(tr , " " <<< "${MPI_RANKS:-1,2,4,8,16}"); do
      ranks=${ranks//,/}
      (( ranks <= CORES )) || continue
      say "a 32-frame sequence on $ranks ranks"
      start=$(date +%s%N)
      run "$MPIRUN" -n "$ranks" "${MPI_ARGS[@]}" "$BIN" render --device cpu --threads $(( CORES / ranks )) \
          --scene "$(dirname "$0")/../docs/examples/dusk_flyover.json" --width 960 --height 540 --spp 8 \
          --frames 0:31 --out "$OUT/seq_${ranks}/f%04d.png" || status=1
      echo "sequence on $ranks ranks: $(( ($(date +%s%N) - start) / 1000000 )) ms" | tee -a "$LOG"
    done
  else
    echo "scale.sh: this urbis has no --frames: the sequence step needs the frame loop" | tee -a "$LOG"
  fi
fi
exit $status

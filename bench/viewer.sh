#!/usr/bin/env bash
# The viewer's render loop without a window (urbis view --headless): frames per second at 1 spp a
# frame and its picture (made where the film is: on the GPU by its kernel, left there as the window's
# CUDA-OpenGL interop shows it), 1280x720 and 1920x1080, by day and by night, on downtown San
# Francisco and the generated city; and the latency from a change to the first picture after it, for a camera move (the image
# restarts) and a change of the time of day (the scene is rebuilt). The goal: 60 fps at
# 1920x1080 by day on the GPU.
# Usage: bench/viewer.sh BUILD_DIR [DEVICE [FRAMES]]
#   DEVICE cuda (default) or cpu; FRAMES per run (default 120 on cuda, 6 on cpu). SF is read from
#   $URBIS_SHARED_DATA (default ../shared/data) and skipped, saying so, where absent. Stats JSON and
#   logs in $OUT (default ./viewer-out); prints one table row a run.
set -uo pipefail
BUILD=${1:?build folder}
DEVICE=${2:-cuda}
if [ "$DEVICE" = cuda ]; then FRAMES=${3:-120}; else FRAMES=${3:-6}; fi
DATA=${URBIS_SHARED_DATA:-$(dirname "$0")/../../shared/data}
SF=$DATA/sf_downtown_2023.osm.pbf
OUT=${OUT:-$PWD/viewer-out}
mkdir -p "$OUT"
status=0
# Frame 1/3 of the way: a step forward (restart); 2/3: the time of day moves an hour (rebuild).
third=$((FRAMES / 3))
cat > "$OUT/latency_script.json" <<JSON
{"steps": [{"frame": $third, "input": {"keys": "W", "seconds": 0.05}},
           {"frame": $((2 * third)), "set": {"astronomy": {"time": "TIME_LATER"}}}]}
JSON
printf '%-10s %-6s %-10s %8s %10s %10s %12s %12s %12s\n' scene time size fps ms/frame render_ms rays/s restart_ms rebuild_ms
for scene in generated sf; do
  if [ "$scene" = sf ]; then
    if [ ! -f "$SF" ]; then echo "sf: $SF is absent, skipped"; continue; fi
    source_args=(--osm "$SF"); day=2023-06-21T14:00-07:00; later_day=2023-06-21T15:00-07:00
    night=2023-06-21T23:30-07:00; later_night=2023-06-22T00:30-07:00
  else
    source_args=(); day=2024-06-21T14:00+02:00; later_day=2024-06-21T15:00+02:00
    night=2024-06-21T23:30+02:00; later_night=2024-06-22T00:30+02:00
  fi
  for when in day night; do
    if [ "$when" = day ]; then time=$day; later=$later_day; exposure=-0.6; else time=$night; later=$later_night; exposure=6; fi
    sed "s/TIME_LATER/$later/" "$OUT/latency_script.json" > "$OUT/script_${scene}_${when}.json"
    for size in 1280x720 1920x1080; do
      name=${scene}_${when}_${size}_${DEVICE}
      "$BUILD"/urbis view --headless --device "$DEVICE" "${source_args[@]}" --time "$time" --exposure "$exposure" \
          --width "${size%x*}" --height "${size#*x}" --spp 1000000 --frames "$FRAMES" \
          --script "$OUT/script_${scene}_${when}.json" --stats "$OUT/$name.json" > "$OUT/$name.log" 2>&1 || status=1
      python3 - "$OUT/$name.json" "$scene" "$when" "$size" <<'PY' || status=1
import json, sys
s = json.load(open(sys.argv[1]))
lat = s["latencies"] + [float("nan")] * 2
print(f"{sys.argv[2]:10s} {sys.argv[3]:6s} {sys.argv[4]:10s} {s['fps']:8.1f} {s['ms_per_frame']:10.2f} "
      f"{s['ms_per_frame_render']:10.2f} {s['rays_per_second']:12.3g} {1e3 * lat[0]:12.1f} {1e3 * lat[1]:12.1f}")
PY
    done
  done
done
exit $status

#!/usr/bin/env bash
# The day frame with the atmosphere and aerial perspective against the same frame without aerial
# perspective (--no-aerial-perspective) and with the analytic sky (--sky analytic): `urbis bench`'s
# 1 spp frame of the default generated city, interleaved runs so that a drift of the clocks touches
# every variant alike. The goal: with / without aerial perspective at most 1.15.
# Usage: bench/atmosphere_bench.sh BUILD_DIR [DEVICE [WIDTH HEIGHT [ROUNDS]]]
#   DEVICE cuda (default; 1920x1080) or cpu; JSON and logs in $OUT (default ./atmosphere-out), one
#   file per run: bench_<variant>_<device>_<round>.json; prints the median frame times and the ratios,
#   raw and scaled by each run's ray batches (which no change of the atmosphere touches).
set -uo pipefail
source "$(dirname "$0")/bench_variants.sh"
bench_arguments atmosphere "$@"
declare -A flags=([aerial]="" [no_aerial]="--no-aerial-perspective" [analytic]="--sky analytic")
bench_variants bench aerial no_aerial analytic
python3 - "$OUT" "$DEVICE" <<'PY'
import glob, json, statistics, sys
out, device = sys.argv[1], sys.argv[2]
ms, norm = {}, {}
for variant in ("aerial", "no_aerial", "analytic"):
    runs = [json.load(open(f)) for f in sorted(glob.glob(f"{out}/bench_{variant}_{device}_*.json"))]
    frames = [j["frame"]["median_ms"] for j in runs]
    # The frame over the same run's ray batches (primary + diffuse + shadow): a load on a shared
    # machine slows both alike, so this ratio is steadier than the frame alone.
    scaled = [j["frame"]["median_ms"] / sum(j["rays"][k]["median_ms"] for k in ("primary", "diffuse", "shadow"))
              for j in runs]
    ms[variant] = statistics.median(frames) if frames else float("nan")
    norm[variant] = statistics.median(scaled) if scaled else float("nan")
    print(f"{variant:10s} frame median {ms[variant]:10.2f} ms over {len(runs)} rounds: {[round(f, 1) for f in frames]}; "
          f"frame / ray batches {norm[variant]:.3f}")
print(f"aerial / no_aerial {ms['aerial'] / ms['no_aerial']:.3f} (scaled by the ray batches {norm['aerial'] / norm['no_aerial']:.3f})"
      f"   aerial / analytic {ms['aerial'] / ms['analytic']:.3f} (scaled {norm['aerial'] / norm['analytic']:.3f})")
PY
exit $bench_status

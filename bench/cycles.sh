#!/usr/bin/env bash
# urbis against Blender's Cycles on the CPU, one city, camera and sample count:
#   bench/cycles.sh [BUILD_DIR]        (env: SCENE, THREADS, OUT)
# Exports the city of SCENE (default bench/cycles/scene.json: 200 generated buildings, a uniform
# analytic sky so that both worlds are the same, 480x270, 16 spp) to a .glb, renders it with Cycles
# (bench/cycles/cycles_render.py) and renders the scene with `urbis render`, procedural and as its
# triangle twin, each to a linear EXR, on THREADS CPU threads (default: all). For each: time to the
# first pixel (start of the process to the start of the render), render time, peak memory (VmHWM
# from /usr/bin/time), and the image against urbis's procedural one (bench/cycles/compare.py).
# Writes OUT/cycles.json (default OUT: cycles_out) and OUT/side_by_side.png (urbis | Cycles).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
urbis="$build/urbis"
scene="${SCENE:-$root/bench/cycles/scene.json}"
threads="${THREADS:-$(nproc)}"
out="${OUT:-cycles_out}"
mkdir -p "$out"
command -v blender >/dev/null || { echo "cycles.sh: blender is not installed (Debian's blender)" >&2; exit 1; }
[ -x "$urbis" ] || { echo "cycles.sh: $urbis not built" >&2; exit 1; }

read -r width height spp depth sky < <(python3 -c '
import json, sys
s = json.load(open(sys.argv[1]))
f, i = s.get("film", {}), s.get("integrator", {})
sky = s.get("sky", {}).get("zenith", [0.45, 0.5, 0.6])
print(f.get("width", 960), f.get("height", 540), i.get("spp", 16), i.get("max_depth", 8), ",".join(map(str, sky)))' "$scene")

now() { date +%s.%N; }
peak_kb() { sed -n 's/.*Maximum resident set size (kbytes): //p' "$1"; }

"$urbis" export --scene "$scene" --out "$out/city.glb" | tee "$out/export.txt"

# Cycles: time to first pixel = the process's start to the render's start (Blender's start-up and the import).
t0=$(now)
/usr/bin/time -v -o "$out/cycles_time.txt" blender -b --factory-startup --python "$root/bench/cycles/cycles_render.py" -- \
  "$out/city.glb" "$out/cycles.exr" "$width" "$height" "$spp" "$threads" "$depth" "$sky" > "$out/cycles_log.txt" 2>&1
t1=$(now)
cycles_render=$(sed -n 's/^cycles: import .* s, render \(.*\) s$/\1/p' "$out/cycles_log.txt")

# urbis: time to first pixel = the process's wall time less its render (import, citygen, BVH, start-up).
run_urbis() {  # NAME, extra options
  local name=$1; shift
  /usr/bin/time -v -o "$out/${name}_time.txt" "$urbis" render --scene "$scene" --device cpu --threads "$threads" \
    --out "$out/$name.exr" --stats "$out/${name}_stats.json" "$@" > "$out/${name}_log.txt" 2>&1
}
u0=$(now); run_urbis urbis; u1=$(now)
w0=$(now); run_urbis urbis_twin --geometry triangles; w1=$(now)

compare() { blender -b --factory-startup --python "$root/bench/cycles/compare.py" -- "$out/urbis.exr" "$1" "$2" 2>&1 |
            sed -n 's/^compare: //p'; }
cmp_cycles=$(compare "$out/cycles.exr" "$out/side_by_side.png")
cmp_twin=$(compare "$out/urbis_twin.exr" "$out/twin_side_by_side.png")

python3 - "$out" "$t0" "$t1" "$cycles_render" "$u0" "$u1" "$w0" "$w1" "$(peak_kb "$out/cycles_time.txt")" \
  "$(peak_kb "$out/urbis_time.txt")" "$(peak_kb "$out/urbis_twin_time.txt")" "$cmp_cycles" "$cmp_twin" \
  "$width" "$height" "$spp" "$threads" <<'PY'
import json, sys
a = sys.argv[1:]
out = a[0]
t0, t1, cr, u0, u1, w0, w1 = (float(x) for x in a[1:8])
pc, pu, pw = (int(x) * 1024 for x in a[8:11])
def urbis(name, start, end, peak):
    s = json.load(open(f"{out}/{name}_stats.json"))
    r = s["seconds"]["render"]
    return {"seconds_first_pixel": round(end - start - r, 3), "seconds_render": round(r, 3),
            "seconds_total": round(end - start, 3), "peak_bytes": peak, "triangles": s["triangles"]}
result = {
    "width": int(a[13]), "height": int(a[14]), "spp": int(a[15]), "threads": int(a[16]),
    "cycles": {"seconds_first_pixel": round(t1 - t0 - cr, 3), "seconds_render": cr, "seconds_total": round(t1 - t0, 3),
               "peak_bytes": pc},
    "urbis": urbis("urbis", u0, u1, pu),
    "urbis_twin": urbis("urbis_twin", w0, w1, pw),
    "image_cycles_vs_urbis": json.loads(a[11]),
    "image_urbis_twin_vs_urbis": json.loads(a[12]),
}
result["render_ratio_cycles_over_urbis"] = round(result["cycles"]["seconds_render"] / result["urbis"]["seconds_render"], 2)
json.dump(result, open(f"{out}/cycles.json", "w"), indent=2)
print(json.dumps(result, indent=2))
PY

#!/usr/bin/env python3
"""The table of bench/streets_bench.sh's results: per build, scene, geometry and device, the frame's
median without streets, with them, and the change. Usage: bench/streets_table.py OUT_DIR"""
import json
import pathlib
import re
import sys

rows = {}
for path in sorted(pathlib.Path(sys.argv[1]).glob("bench_*.json")):
    m = re.fullmatch(r"bench_(.+)_(sf|100k)_(procedural|plain)_(cuda|cpu)_(streets|bare)", path.stem)
    if not m:
        continue
    build, scene, geometry, device, streets = m.groups()
    rows.setdefault((build, scene, geometry, device), {})[streets] = json.loads(path.read_text())["frame"]["median_ms"]
print("| build | scene | geometry | device | without streets | with streets | change |")
print("|---|---|---|---|---:|---:|---:|")
for (build, scene, geometry, device), ms in sorted(rows.items(), key=lambda kv: (kv[0][1], kv[0][2], kv[0][3], kv[0][0])):
    bare, streets = ms.get("bare"), ms.get("streets")
    change = f"{100 * (streets / bare - 1):+.0f} %" if bare and streets else "-"
    fmt = lambda v: f"{v:.2f} ms" if v is not None else "-"
    print(f"| {build} | {scene} | {geometry} | {device} | {fmt(bare)} | {fmt(streets)} | {change} |")

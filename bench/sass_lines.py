#!/usr/bin/env python3
"""Where a CUDA kernel spends its time, by source file and line.

Joins Nsight Compute's per-instruction counters (`ncu --import R --page source --csv --print-source
sass`, optionally gzipped) with the line table of the same binary's kernel (`nvdisasm -g -c` of the
cubin that `cuobjdump -xelf all` extracts): instruction i of the kernel is row i of the CSV. Build
with `-lineinfo` (URBIS_CUDA_FLAGS=-lineinfo bench/gpu.sh build) so that the lines are there.

    sass_lines.py KERNEL_SUBSTRING DISASSEMBLY.sass PROFILE.csv[.gz] [LINES]

Prints the totals (warp instructions, active lanes per instruction, stall samples and the share of
"no instruction" stalls, i.e. instruction-cache misses), then per file and for the LINES hottest
lines: instructions executed at least once, share of warp instructions, lanes, share of samples.
"""
import collections
import csv
import gzip
import re
import sys


def kernel_lines(path, kernel):
    """(file, line) of each instruction of the kernel's .text section, in address order."""
    lines, inside, where = [], False, ("?", 0)
    with open(path) as f:
        for text in f:
            section = re.match(r"\s*\.text\.(\S+):", text)
            if section:
                inside = kernel in section.group(1)
                continue
            if not inside:
                continue
            loc = re.search(r'//## File "([^"]+)", line (\d+)', text)
            if loc:
                where = (loc.group(1).split("/")[-1], int(loc.group(2)))
            elif re.match(r"\s*/\*[0-9a-f]{4,}\*/\s+\S", text):
                lines.append(where)
    return lines


def profile_rows(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt") as f:
        rows = list(csv.reader(f))
    header = rows[1]  # rows[0] names the kernel
    column = {name: i for i, name in enumerate(header)}

    def value(row, name):
        text = row[column[name]].replace(",", "")
        return float(text) if text not in ("", "-") else 0.0

    keys = ("Instructions Executed", "Thread Instructions Executed", "Warp Stall Sampling (All Samples)", "stall_no_inst")
    return [[value(row, k) for k in keys] for row in rows[2:]]


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    kernel, disassembly, profile = sys.argv[1:4]
    top = int(sys.argv[4]) if len(sys.argv) > 4 else 30
    lines, rows = kernel_lines(disassembly, kernel), profile_rows(profile)
    if len(lines) != len(rows):
        sys.exit(f"sass_lines: {len(lines)} instructions in {disassembly}, {len(rows)} in {profile}: not the same binary")
    per_file = collections.defaultdict(lambda: [0, 0.0, 0.0, 0.0, 0.0])
    per_line = collections.defaultdict(lambda: [0, 0.0, 0.0, 0.0, 0.0])
    for where, (warp, thread, samples, no_inst) in zip(lines, rows):
        for table, key in ((per_file, where[0]), (per_line, where)):
            entry = table[key]
            entry[0] += warp > 0
            entry[1] += warp
            entry[2] += thread
            entry[3] += samples
            entry[4] += no_inst
    warp, thread, samples, no_inst = (sum(r[i] for r in rows) for i in range(4))
    print(f"{len(rows)} instructions, {sum(1 for r in rows if r[0] > 0)} executed; {warp / 1e9:.2f} G warp instructions, "
          f"{thread / max(warp, 1):.1f} lanes each; {samples:.0f} stall samples, {100 * no_inst / max(samples, 1):.0f} % no instruction")

    def show(name, e):
        print(f"{name:34s} {e[0]:6d} {100 * e[1] / warp:7.1f} {e[2] / max(e[1], 1):6.1f} {100 * e[3] / samples:8.1f} {100 * e[4] / samples:8.1f}")

    print(f"{'file':34s} {'hot':>6s} {'warp %':>7s} {'lanes':>6s} {'sample %':>8s} {'no-inst %':>8s}")
    for name, e in sorted(per_file.items(), key=lambda item: -item[1][3]):
        if e[0]:
            show(name, e)
    print(f"{'line':34s}")
    for (name, line), e in sorted(per_line.items(), key=lambda item: -item[1][3])[:top]:
        show(f"{name}:{line}", e)


if __name__ == "__main__":
    main()

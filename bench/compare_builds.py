"""Tables of two builds' benchmarks and of their converged images (bench/compare_builds.sh writes the inputs).

Images: mean absolute difference of the 8-bit sRGB channels, and the 99th percentile, after a 4x4 box
filter (which takes most of the remaining Monte Carlo noise out of the comparison, not the bias).
"""
import json
import sys
from pathlib import Path

import numpy as np


def read_png(path):
    try:
        from PIL import Image
        return np.asarray(Image.open(path).convert("RGB"), dtype=np.float64)
    except ImportError:
        from torchvision.io import read_image
        return read_image(str(path)).permute(1, 2, 0).numpy().astype(np.float64)


def box4(image):
    h, w = image.shape[0] // 4 * 4, image.shape[1] // 4 * 4
    return image[:h, :w].reshape(h // 4, 4, w // 4, 4, 3).mean(axis=(1, 3))


def main(out):
    out = Path(out)
    print("| scene | geometry | device | measure | before | after | change |")
    print("|---|---|---|---|---|---|---|")
    for after in sorted(out.glob("bench_after_*.json")):
        before = out / after.name.replace("bench_after_", "bench_before_")
        if not before.exists():
            continue
        _, _, scene, geometry, device = after.stem.split("_")
        a, b = json.loads(after.read_text()), json.loads(before.read_text())
        rows = [("frame 1 spp ms", b["frame"]["median_ms"], a["frame"]["median_ms"])]
        for kind in ("primary", "diffuse", "shadow"):
            if kind in a.get("rays", {}) and kind in b.get("rays", {}):
                rows.append((f"{kind} Grays/s", b["rays"][kind]["rays_per_second"] / 1e9,
                             a["rays"][kind]["rays_per_second"] / 1e9))
        for name, vb, va in rows:
            change = (va / vb - 1.0) * 100.0 if vb else float("nan")
            print(f"| {scene} | {geometry} | {device} | {name} | {vb:.4g} | {va:.4g} | {change:+.1f} % |")
    print()
    print("| converged image (640x360, 4096 spp, GPU) | mean abs diff (8-bit) | 99th percentile |")
    print("|---|---|---|")
    for world in ("default", "sf"):
        b, a = out / f"converged_before_{world}.png", out / f"converged_after_{world}.png"
        if not (a.exists() and b.exists()):
            print(f"| {world} | missing | missing |")
            continue
        diff = np.abs(box4(read_png(a)) - box4(read_png(b)))
        print(f"| {world} | {diff.mean():.3f} | {np.percentile(diff, 99):.3f} |")


if __name__ == "__main__":
    main(sys.argv[1])

#!/usr/bin/env python3
"""The denoiser against a converged reference: MSE at 4 spp with and without --denoise, by day and
by night, on the generated default world (docs/film.md, "Denoising").

    python3 bench/denoise_mse.py [--build build] [--size 320x180] [--ref-spp 1024] [--spp 4] [--device cpu]

References are rendered on the CPU at --ref-spp and cached in BUILD/denoise_refs/ (named by view, size
and spp; delete them after a change to the renderer). They share the noisy renders' first samples
(--seed also seeds the city), which lowers the noisy MSE by about 2 spp / ref-spp. For each view it prints the MSE of the linear
radiance (at the film's exposure) and of the tone-mapped image (ACES filmic + sRGB, in [0, 1]), noisy
and denoised, and their ratios, then the denoiser's time from --stats. Extra arguments after `--` go
to every urbis command. Standard library only: the EXR files (float, ZIP or uncompressed scan lines,
as urbis writes them) are read here.
"""

import argparse
import json
import os
import subprocess
import sys

from exr_error import read_exr

# name | urbis options. Night today: a sun below the horizon (a dark sky and the lit windows). The
# street view looks down the generated city's central avenue; the overview is the default framing,
# where most pixels hold several surfaces and much of the noise is the edges' (anti-aliasing).
STREET = ["--camera", "0,30,150,0,10,0"]
VIEWS = [
    ("day", STREET + ["--sun", "40,150"]),
    ("night", STREET + ["--sun", "-10,200"]),
    ("day_overview", ["--sun", "40,150"]),
    ("night_overview", ["--sun", "-10,200"]),
]


def read_exr_rgb(path):
    """The R, G, B channels of an EXR as three lists, and (width, height)."""
    width, height, out = read_exr(path)
    return out, (width, height)


def tone(v):
    """ACES filmic (Narkowicz) and sRGB encoding of a linear value, as src/film/tone_map.h."""
    v = max(v, 0.0)
    y = min(max((v * (2.51 * v + 0.03)) / (v * (2.43 * v + 0.59) + 0.14), 0.0), 1.0)
    return 12.92 * y if y <= 0.0031308 else 1.055 * y ** (1 / 2.4) - 0.055


def mse(a, b, f=lambda v: v):
    total, n = 0.0, 0
    for c in ("R", "G", "B"):
        for x, y in zip(a[c], b[c]):
            total += (f(x) - f(y)) ** 2
            n += 1
    return total / n


def render(args, options, spp, out, stats=None, denoise=False, device="cpu"):
    command = [os.path.join(args.build, "urbis"), "render", "--width", str(args.width), "--height", str(args.height),
               "--spp", str(spp), "--device", device, "--exr-float", "--out", out] + options + args.extra
    if denoise:
        command.append("--denoise")
    if stats:
        command += ["--stats", stats]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--ref-spp", type=int, default=1024)
    parser.add_argument("--spp", type=int, default=4)
    parser.add_argument("--device", default="cpu", help="of the noisy renders; references are always CPU")
    parser.add_argument("--views", default="day,night,day_overview,night_overview", help="which, comma-separated")
    parser.add_argument("extra", nargs="*", help="after --: more urbis options for every render")
    args = parser.parse_args()
    args.width, args.height = (int(v) for v in args.size.split("x"))
    cache = os.path.join(args.build, "denoise_refs")
    os.makedirs(cache, exist_ok=True)
    print(f"{'view':14} {'MSE linear':>12} {'denoised':>12} {'ratio':>7} {'MSE tonemapped':>15} {'denoised':>12} {'ratio':>7} {'denoise s':>10}")
    for name, options in VIEWS:
        if name not in args.views.split(","):
            continue
        reference = os.path.join(cache, f"{name}_{args.size}_{args.ref_spp}spp.exr")
        if not os.path.exists(reference):
            render(args, options, args.ref_spp, reference)
        ref, _ = read_exr_rgb(reference)
        noisy_path = os.path.join(cache, f"{name}_{args.size}_{args.spp}spp.exr")
        clean_path = os.path.join(cache, f"{name}_{args.size}_{args.spp}spp_denoised.exr")
        stats_path = os.path.join(cache, f"{name}_{args.size}_denoise_stats.json")
        render(args, options, args.spp, noisy_path, device=args.device)
        render(args, options, args.spp, clean_path, stats=stats_path, denoise=True, device=args.device)
        noisy, _ = read_exr_rgb(noisy_path)
        clean, _ = read_exr_rgb(clean_path)
        linear = (mse(noisy, ref), mse(clean, ref))
        toned = (mse(noisy, ref, tone), mse(clean, ref, tone))
        seconds = json.load(open(stats_path))["seconds"]["denoise"]
        print(f"{name:14} {linear[0]:12.4e} {linear[1]:12.4e} {linear[0] / linear[1]:7.2f} "
              f"{toned[0]:15.4e} {toned[1]:12.4e} {toned[0] / toned[1]:7.2f} {seconds:10.3f}")


if __name__ == "__main__":
    main()

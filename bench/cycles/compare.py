# Compares two linear EXR renders of one view (bench/cycles.sh), in Blender's Python (numpy):
#   blender -b --factory-startup --python bench/cycles/compare.py -- A.exr B.exr SIDE_BY_SIDE.png
# Prints one line of JSON: each image's mean luminance, their ratio (B / A), and the relative mean
# absolute difference of the luminance, raw and after B is scaled to A's mean; 8x8-pixel block means
# as well (the noise of a few samples averaged out). The PNG shows A | B tone-mapped as urbis does
# (ACES filmic fit, sRGB; film/tone_map.h).
import json
import sys

import bpy
import numpy as np

a_path, b_path, png = sys.argv[sys.argv.index("--") + 1:][:3]


def load(path):
    image = bpy.data.images.load(path)
    w, h = image.size
    pixels = np.array(image.pixels[:], dtype=np.float64).reshape(h, w, 4)[:, :, :3]
    return pixels


def luminance(rgb):
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def blocks(y, n=8):
    h, w = (y.shape[0] // n) * n, (y.shape[1] // n) * n
    return y[:h, :w].reshape(h // n, n, w // n, n).mean(axis=(1, 3))


def tone(rgb):
    x = np.maximum(rgb, 0)
    y = np.clip((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0, 1)
    return np.where(y <= 0.0031308, 12.92 * y, 1.055 * np.power(y, 1 / 2.4) - 0.055)


a, b = load(a_path), load(b_path)
ya, yb = luminance(a), luminance(b)
scale = ya.mean() / max(yb.mean(), 1e-12)
result = {
    "mean_luminance_a": ya.mean(),
    "mean_luminance_b": yb.mean(),
    "ratio_b_over_a": yb.mean() / max(ya.mean(), 1e-12),
    "rel_mean_abs_diff": np.abs(yb - ya).mean() / ya.mean(),
    "rel_mean_abs_diff_scaled": np.abs(yb * scale - ya).mean() / ya.mean(),
    "rel_mean_abs_diff_blocks8_scaled": np.abs(blocks(yb) * scale - blocks(ya)).mean() / blocks(ya).mean(),
}
print("compare: " + json.dumps({k: round(float(v), 4) for k, v in result.items()}))

side = np.concatenate([tone(a), tone(b)], axis=1)
h, w = side.shape[:2]
out = bpy.data.images.new("side", w, h, alpha=False, float_buffer=True)
out.colorspace_settings.name = "Non-Color"
out.pixels[:] = np.concatenate([side, np.ones((h, w, 1))], axis=2).astype(np.float32).ravel()
out.filepath_raw = png
out.file_format = "PNG"
out.save()

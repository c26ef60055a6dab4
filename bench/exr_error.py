"""Relative MSE of EXR images against a reference (bench/many_lights.sh): the mean over pixels of
(x - r)^2 / (r^2 + 1e-2 m^2), on luminance, with r the reference and m its mean (Rousselle et al. 2011's
form, whose 1e-2 keeps black pixels from dominating, made independent of the image's exposure: a night
is far darker than 1). A handful of fireflies can make that mean, so two robust figures come with it:
the same mean after clamping both images' luminance to the reference's 99.9th percentile
("clamped"), and the median over 16 x 16 pixel tiles of each tile's relative MSE ("tile median").
The reference may be several EXRs joined by commas (renders with other seeds or samplers): their
mean is the reference. Reads the scanline ZIP/ZIPS/uncompressed EXRs that `urbis render --out X.exr`
writes, with the standard library alone (no numpy or OpenEXR module on the machines this runs on).

usage: exr_error.py REFERENCE.exr[,REFERENCE2.exr...] IMAGE.exr [IMAGE.exr ...]
       -> one line per image: path rel_mse clamped_rel_mse tile_median_rel_mse
"""
import struct
import sys
import zlib

COMPRESSION_LINES = {0: 1, 2: 1, 3: 16}  # none, ZIPS, ZIP


def half_to_float(h):
    return struct.unpack("<e", struct.pack("<H", h))[0]


def read_exr(path):
    """Returns (width, height, {channel: list of floats}) for channels R, G and B."""
    data = open(path, "rb").read()
    if data[:4] != b"\x76\x2f\x31\x01":
        sys.exit(f"{path}: not an OpenEXR file")
    pos, channels, window, compression = 8, [], None, None
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        tend = data.index(b"\0", end + 1)
        size = struct.unpack_from("<i", data, tend + 1)[0]
        value = data[tend + 5:tend + 5 + size]
        if name == "channels":
            p = 0
            while value[p] != 0:
                e = value.index(b"\0", p)
                channels.append((value[p:e].decode(), struct.unpack_from("<i", value, e + 1)[0]))
                p = e + 1 + 16
        elif name == "dataWindow":
            window = struct.unpack("<4i", value)
        elif name == "compression":
            compression = value[0]
        pos = tend + 5 + size
    pos += 1
    if compression not in COMPRESSION_LINES:
        sys.exit(f"{path}: compression {compression} not read here (urbis writes ZIP)")
    width, height = window[2] - window[0] + 1, window[3] - window[1] + 1
    lines = COMPRESSION_LINES[compression]
    chunks = (height + lines - 1) // lines
    offsets = struct.unpack_from(f"<{chunks}Q", data, pos)
    sizes = [2 if t == 1 else 4 for _, t in channels]  # HALF 2 bytes; UINT and FLOAT 4
    out = {name: [] for name, _ in channels}
    for offset in offsets:
        y, size = struct.unpack_from("<ii", data, offset)
        raw = data[offset + 8:offset + 8 + size]
        rows = min(lines, window[3] + 1 - y)
        expected = rows * width * sum(sizes)
        if compression != 0 and size < expected:
            t = bytearray(zlib.decompress(raw))
            for i in range(1, len(t)):
                t[i] = (t[i - 1] + t[i] - 128) & 0xFF
            half = (len(t) + 1) // 2
            raw = bytearray(len(t))
            raw[0::2], raw[1::2] = t[:half], t[half:]
        p = 0
        for _ in range(rows):
            for (name, kind), s in zip(channels, sizes):
                row = raw[p:p + width * s]
                p += width * s
                if kind == 2:
                    out[name].extend(struct.unpack(f"<{width}f", row))
                elif kind == 1:
                    out[name].extend(half_to_float(h) for h in struct.unpack(f"<{width}H", row))
    return width, height, out


def luminance(image):
    _, _, c = image
    return [0.2126 * r + 0.7152 * g + 0.0722 * b for r, g, b in zip(c["R"], c["G"], c["B"])]


def rel_mse(reference, image):
    if len(reference) != len(image):
        sys.exit("images of different sizes")
    eps = 1e-2 * (sum(reference) / len(reference)) ** 2
    return sum((x - r) ** 2 / (r * r + eps) for x, r in zip(image, reference)) / len(reference)


def clamped_rel_mse(reference, image):
    """rel_mse with both images' values clamped to the reference's 99.9th percentile."""
    ordered = sorted(reference)
    top = ordered[min(len(ordered) - 1, int(0.999 * len(ordered)))]
    return rel_mse([min(r, top) for r in reference], [min(x, top) for x in image])


def tile_median_rel_mse(reference, image, width, tile=16):
    """Median over tile x tile pixel blocks of each block's mean relative squared error (the
    epsilon of rel_mse, from the whole reference's mean)."""
    eps = 1e-2 * (sum(reference) / len(reference)) ** 2
    height = len(reference) // width
    errors = []
    for ty in range(0, height, tile):
        for tx in range(0, width, tile):
            total, count = 0.0, 0
            for y in range(ty, min(ty + tile, height)):
                for i in range(y * width + tx, y * width + min(tx + tile, width)):
                    r = reference[i]
                    total += (image[i] - r) ** 2 / (r * r + eps)
                    count += 1
            errors.append(total / count)
    errors.sort()
    return errors[len(errors) // 2]


def read_reference(paths):
    """Width and the mean luminance of the EXRs named in `paths` (comma-separated)."""
    images = [read_exr(p) for p in paths.split(",")]
    width = images[0][0]
    lums = [luminance(i) for i in images]
    if any(i[0] != width or len(l) != len(lums[0]) for i, l in zip(images, lums)):
        sys.exit(f"{paths}: references of different sizes")
    return width, [sum(v) / len(lums) for v in zip(*lums)]


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    width, reference = read_reference(argv[1])
    for path in argv[2:]:
        image = luminance(read_exr(path))
        if len(image) != len(reference):
            sys.exit(f"{path}: not the reference's size")
        print(f"{path} {rel_mse(reference, image):.6g} {clamped_rel_mse(reference, image):.6g} "
              f"{tile_median_rel_mse(reference, image, width):.6g}")


if __name__ == "__main__":
    main(sys.argv)

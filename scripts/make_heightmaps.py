#!/usr/bin/env python3
"""Writes the height-field images of examples/height_fields.rt into examples/heights/:
hills8.png (8-bit grey, 48x40), hills16.png (16-bit grey, 48x40), terrace.png (4-bit palette,
32x32: POV-Ray takes a palette image's index, not its colour, as the height) and
ramp_rgb.png (8-bit RGB, 24x24: red is the high byte, green the low one).

Usage: python3 scripts/make_heightmaps.py   (standard library only)
"""
import math, os, struct, zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "heights")


def chunk(kind, data):
    c = struct.pack(">I", len(data)) + kind + data
    return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def write(name, w, h, depth, colour, rows, palette=None):
    raw = b"".join(b"\x00" + r for r in rows)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, colour, 0, 0, 0))
    if palette:
        png += chunk(b"PLTE", bytes(palette))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(png)


def hills(x, z):
    """Rolling hills in [0, 1]."""
    v = 0.5 + 0.25 * math.sin(x * 7.0) * math.cos(z * 5.0) + 0.2 * math.exp(-((x - 0.6) ** 2 + (z - 0.4) ** 2) * 12)
    return min(max(v, 0.0), 1.0)


def main():
    os.makedirs(OUT, exist_ok=True)
    w, h = 48, 40
    rows8, rows16 = [], []
    for j in range(h):
        z = 1.0 - j / (h - 1)
        vals = [hills(i / (w - 1), z) for i in range(w)]
        rows8.append(bytes(int(v * 255 + 0.5) for v in vals))
        rows16.append(b"".join(struct.pack(">H", int(v * 65535 + 0.5)) for v in vals))
    write("hills8.png", w, h, 8, 0, rows8)
    write("hills16.png", w, h, 16, 0, rows16)
    # Terraces: palette indices 0..15 in rings; the palette's colours are unrelated greys.
    n = 32
    palette = []
    for k in range(16):
        palette += [(k * 37) % 256, (k * 91) % 256, (k * 53) % 256]
    rows = []
    for j in range(n):
        idx = []
        for i in range(n):
            r = math.hypot(i - n / 2 + 0.5, j - n / 2 + 0.5)
            idx.append(max(0, 15 - int(r)))
        rows.append(bytes((idx[2 * k] << 4) | idx[2 * k + 1] for k in range(n // 2)))
    write("terrace.png", n, n, 4, 3, rows, palette)
    # RGB: height = red * 256 + green, blue ignored.
    n = 24
    rows = []
    for j in range(n):
        row = b""
        for i in range(n):
            v = int((i / (n - 1)) * 0.6 * 65535) + int(j * 900)
            row += bytes([v >> 8, v & 255, 200])
        rows.append(row)
    write("ramp_rgb.png", n, n, 8, 2, rows)
    print("wrote", sorted(os.listdir(OUT)))


if __name__ == "__main__":
    main()

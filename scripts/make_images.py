#!/usr/bin/env python3
"""Writes the image files of examples/image_formats.rt into examples/images/, one per format
POV-Ray reads, made from examples/trace_logo.png (64x48) and examples/heights/hills8.png:
logo.jpg (4:2:0 JPEG), logo.gif (non-interlaced, 256-colour palette), logo.tga, logo.ppm,
logo.bmp, logo.tif, grey.pgm, logo16.png/.bmp/.tga (one 16-colour palette image, the TGA
run-length encoded), hills.gif (palette height field: the index is the height),
hills16.pgm (16-bit grey height field) and hills16.pot (the same heights as Fractint's POT
file: a GIF twice as wide, high bytes left, low bytes right), ramp.hdr (Radiance RGBE, values up to 3) and
sky.exr (a trace render of examples/mirrors.rt at 64x48, float channels), and the DF3 voxel
files blob8.df3 (8x8x8, 8-bit) and blob16.df3 (6x6x6, 16-bit).

Usage: python3 scripts/make_images.py   (needs Pillow; the EXR needs a built trace)
"""
import math, os, struct, subprocess

from PIL import Image

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
OUT = os.path.join(ROOT, "examples", "images")


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    e = math.frexp(m)[1]
    s = 256.0 / 2.0 ** e
    return bytes([int(r * s), int(g * s), int(b * s), e + 128])


def pot(grey16, path):
    """Writes a 16-bit grey image as a POT file: palette indices, the left half each pixel's
    high byte, the right half its low byte (the palette, a grey ramp, is not used)."""
    w, h = grey16.size
    im = Image.new("P", (2 * w, h))
    im.putpalette(bytes(i for i in range(256) for _ in range(3)))
    for y in range(h):
        for x in range(w):
            v = grey16.getpixel((x, y))
            im.putpixel((x, y), v >> 8)
            im.putpixel((x + w, y), v & 255)
    im.save(path, format="GIF", optimize=False, interlace=False)


def main():
    os.makedirs(OUT, exist_ok=True)
    out = lambda name: os.path.join(OUT, name)
    logo = Image.open(os.path.join(ROOT, "examples", "trace_logo.png"))
    logo.save(out("logo.jpg"), quality=90)
    logo.convert("P", palette=Image.ADAPTIVE, colors=256).save(out("logo.gif"), interlace=False)
    logo.save(out("logo.tga"))
    logo.save(out("logo.ppm"))
    logo.save(out("logo.bmp"))
    logo.save(out("logo.tif"))
    logo.convert("L").save(out("grey.pgm"))
    # One 16-colour palette image in three formats (the same indices: tests compare them).
    logo16 = logo.convert("RGB").quantize(16)
    logo16.save(out("logo16.png"))
    logo16.save(out("logo16.bmp"))
    logo16.save(out("logo16.tga"), compression="tga_rle")
    hills = Image.open(os.path.join(ROOT, "examples", "heights", "hills8.png"))
    hills.convert("P").save(out("hills.gif"), interlace=False)
    hills16 = Image.open(os.path.join(ROOT, "examples", "heights", "hills16.png"))
    w, h = hills16.size
    data = b"".join(struct.pack(">H", hills16.getpixel((x, y))) for y in range(h) for x in range(w))
    with open(out("hills16.pgm"), "wb") as f:
        f.write(b"P5\n%d %d\n65535\n" % (w, h) + data)
    pot(hills16, out("hills16.pot"))
    w, h = 64, 48
    pixels = b"".join(
        rgbe(3.0 * x / w, 2.0 * y / h, 0.5 + 0.5 * math.sin(x * 0.3 + y * 0.2))
        for y in range(h)
        for x in range(w)
    )
    with open(out("ramp.hdr"), "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (h, w) + pixels)
    for name, n, bits in (("blob8.df3", 8, 8), ("blob16.df3", 6, 16)):
        data = b""
        for z in range(n):
            for y in range(n):
                for x in range(n):
                    d = math.sqrt((x - n / 2 + 0.5) ** 2 + (y - n / 2 + 0.5) ** 2 + (z - n / 2 + 0.5) ** 2) / (n / 2)
                    v = max(0.0, 1.0 - d) * (0.6 + 0.4 * math.sin(x * 1.3 + y * 0.7))
                    data += bytes([int(v * 255)]) if bits == 8 else struct.pack(">H", int(v * 65535))
        with open(out(name), "wb") as f:
            f.write(struct.pack(">HHH", n, n, n) + data)
    trace = os.path.join(ROOT, "target", "release", "trace")
    if os.path.exists(trace):
        subprocess.run([trace, os.path.join(ROOT, "examples", "mirrors.rt"), "-o", out("sky.exr"),
                        "--width", "64", "--height", "48", "--quiet"], check=True)


if __name__ == "__main__":
    main()

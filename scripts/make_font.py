#!/usr/bin/env python3
"""Writes examples/fonts/trace-sample.ttf: a small TrueType font of trace's own for the text
examples and tests (POV-Ray's bundled fonts are not ours to ship).

Usage: python3 scripts/make_font.py        (needs fontTools: pip install fontTools)

Glyphs (1000 units per em), chosen to exercise what POV-Ray's text object reads:
  A  straight edges with a triangular hole (even-odd fill), kerned against V (-120 units)
  V  straight edges, left bearing 20
  O  quadratic curves, outer ring and inner hole
  S  quadratic curves with off-curve runs (implied on-curve midpoints)
  T  straight edges; T followed by O kerned -60
  space (advance 300, no outline); .notdef a box.
The kern table is Microsoft version 0 with one format-0 subtable whose pairs are sorted by
their left glyph only (POV-Ray scans them in file order and stops after the left glyph).
"""
import os
from fontTools.fontBuilder import FontBuilder
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib.tables._k_e_r_n import KernTable_format_0
from fontTools.ttLib import newTable

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
OUT = os.path.join(ROOT, "examples", "fonts", "trace-sample.ttf")


def polygon(pen, points):
    pen.moveTo(points[0])
    for p in points[1:]:
        pen.lineTo(p)
    pen.closePath()


def glyph_notdef():
    pen = TTGlyphPen(None)
    polygon(pen, [(50, 0), (50, 700), (450, 700), (450, 0)])
    polygon(pen, [(100, 50), (400, 50), (400, 650), (100, 650)])
    return pen.glyph()


def glyph_a():
    pen = TTGlyphPen(None)
    # Outer contour clockwise (TrueType's convention), hole counter-clockwise.
    polygon(pen, [(0, 0), (330, 700), (400, 700), (730, 0), (600, 0), (520, 200), (210, 200), (130, 0)])
    polygon(pen, [(260, 300), (470, 300), (365, 560)])
    return pen.glyph()


def glyph_v():
    pen = TTGlyphPen(None)
    polygon(pen, [(20, 700), (150, 700), (370, 120), (590, 700), (700, 700), (420, 0), (320, 0)])
    return pen.glyph()


def glyph_o():
    pen = TTGlyphPen(None)
    # A ring of quadratic arcs: four off-curve points between on-curve ones.
    pen.moveTo((380, 0))
    pen.qCurveTo((40, 0), (40, 350))
    pen.qCurveTo((40, 710), (380, 710))
    pen.qCurveTo((720, 710), (720, 350))
    pen.qCurveTo((720, 0), (380, 0))
    pen.closePath()
    pen.moveTo((380, 100))
    pen.qCurveTo((600, 100), (600, 355))
    pen.qCurveTo((600, 610), (380, 610))
    pen.qCurveTo((160, 610), (160, 355))
    pen.qCurveTo((160, 100), (380, 100))
    pen.closePath()
    return pen.glyph()


def glyph_s():
    pen = TTGlyphPen(None)
    # Runs of two off-curve points: the on-curve midpoints are implied.
    pen.moveTo((80, 120))
    pen.qCurveTo((200, -20), (420, -10), (560, 120), (520, 300), (330, 360))
    pen.qCurveTo((180, 410), (230, 560), (450, 600), (520, 560))
    pen.lineTo((560, 660))
    pen.qCurveTo((420, 740), (160, 700), (90, 560), (130, 360), (300, 300))
    pen.qCurveTo((460, 250), (440, 110), (250, 60), (120, 220))
    pen.closePath()
    return pen.glyph()


def glyph_t():
    pen = TTGlyphPen(None)
    polygon(pen, [(280, 0), (280, 600), (20, 600), (20, 700), (660, 700), (660, 600), (400, 600), (400, 0)])
    return pen.glyph()


def main():
    order = [".notdef", "space", "A", "O", "S", "T", "V"]
    fb = FontBuilder(1000, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap({0x20: "space", 0x41: "A", 0x4F: "O", 0x53: "S", 0x54: "T", 0x56: "V"})
    empty = TTGlyphPen(None).glyph()
    glyphs = {
        ".notdef": glyph_notdef(),
        "space": empty,
        "A": glyph_a(),
        "O": glyph_o(),
        "S": glyph_s(),
        "T": glyph_t(),
        "V": glyph_v(),
    }
    fb.setupGlyf(glyphs)
    advances = {".notdef": 500, "space": 300, "A": 730, "O": 760, "S": 640, "T": 680, "V": 720}
    glyf = fb.font["glyf"]
    metrics = {}
    for name in order:
        g = glyf[name]
        g.recalcBounds(glyf)
        lsb = getattr(g, "xMin", 0) if g.numberOfContours else 0
        metrics[name] = (advances[name], lsb)
    fb.setupHorizontalMetrics(metrics)
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": "trace sample", "styleName": "Regular"})
    fb.setupOS2()
    fb.setupPost()
    # Also a Macintosh (1, 0) format-0 map, which POV-Ray prefers for ASCII strings.
    cmap = fb.font["cmap"]
    from fontTools.ttLib.tables._c_m_a_p import cmap_format_0
    mac = cmap_format_0(0)
    mac.platformID, mac.platEncID, mac.language = 1, 0, 0
    mac.cmap = {0x20: "space", 0x41: "A", 0x4F: "O", 0x53: "S", 0x54: "T", 0x56: "V"}
    cmap.tables.insert(0, mac)
    kern = newTable("kern")
    kern.version = 0
    sub = KernTable_format_0()
    sub.version, sub.coverage, sub.format = 0, 1, 0
    sub.kernTable = {("A", "V"): -120, ("T", "O"): -60, ("V", "A"): -100}
    kern.kernTables = [sub]
    fb.font["kern"] = kern
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    fb.save(OUT)
    print("wrote", OUT, os.path.getsize(OUT), "bytes")


if __name__ == "__main__":
    main()

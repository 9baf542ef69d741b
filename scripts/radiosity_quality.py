#!/usr/bin/env python3
"""Radiosity: trace and POV-Ray 3.7 against the ground truth of the same lighting model.

For each scene (tests/radiosity's three and POV-Ray's own radiosity/cornell.pov), trace renders
the ground truth: `--radiosity-reference N` (every radiosity query answered afresh by one ray
in a random cosine-weighted direction, N paths a pixel, averaged: the nested mean that
POV-Ray's cached samples estimate). Then both renderers render the scene with its own
radiosity settings and with a sweep of others (more rays a sample, a smaller error bound,
more samples reused, a finer pretrace: "count 100", "count 200", "count 500"), without anti-aliasing, each with two threads; every
image is compared with the ground truth (mean FLIP), and its end-to-end wall time is measured
in the same run. POV-Ray also renders with one thread, its only reproducible picture, which
trace's picture is compared with too.

Writes docs/radiosity.csv (every render), docs/radiosity-quality.md (the table) and
docs/radiosity.svg (error against time, one panel per scene).
Usage: scripts/radiosity_quality.py [SCENE ...]   (env: WIDTH, HEIGHT, PATHS)
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TRACE = os.path.join(ROOT, "target", "release", "trace")
WIDTH = int(os.environ.get("WIDTH", 160))
HEIGHT = int(os.environ.get("HEIGHT", 120))
PATHS = int(os.environ.get("PATHS", 1024))
POV_SCENES = "/usr/share/povray-3.7/scenes"
SCENES = {
    "room": os.path.join(ROOT, "tests/radiosity/room.pov"),
    "settings": os.path.join(ROOT, "tests/radiosity/settings.pov"),
    "legacy": os.path.join(ROOT, "tests/radiosity/legacy.pov"),
    "cornell": os.path.join(POV_SCENES, "radiosity/cornell.pov"),
}
# Other settings, each added at the end of the scene's radiosity block (so they win, and the
# rest of its model stays): (label, settings).
SWEEP = [
    ("count 100", "count 100 error_bound 1.0 nearest_count 8 pretrace_end 0.02"),
    ("count 200", "count 200 error_bound 0.6 nearest_count 10 pretrace_end 0.01"),
    ("count 500", "count 500 error_bound 0.3 nearest_count 15 pretrace_end 0.005 minimum_reuse 0.005"),
]


def timed(cmd, cwd):
    p = subprocess.run(["/usr/bin/time", "-f", "TIME %e"] + cmd, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), p.stderr[-2000:]))
    return float([l for l in p.stderr.splitlines() if l.startswith("TIME ")][-1].split()[1])


def flip(a, b):
    out = subprocess.run([TRACE, "compare", a, b], capture_output=True, text=True, check=True).stdout
    return float(re.search(r"mean FLIP\s+([0-9.]+)", out).group(1))


def with_settings(path, body, tmp, label):
    """The scene with `body` added at the end of its radiosity block: later settings win, so
    the finer ones replace the scene's and the rest of its model (bounces, brightness, grey
    threshold, normal, media, a rad_def.inc macro's settings) stays."""
    text = open(path).read()
    m = re.search(r"radiosity\s*\{", text)
    depth, i = 1, m.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    new = text[:i - 1] + " " + body + " " + text[i - 1:]
    out = os.path.join(tmp, "%s-%s.pov" % (os.path.splitext(os.path.basename(path))[0], label.replace(" ", "")))
    open(out, "w").write(new)
    return out


def main():
    names = sys.argv[1:] or list(SCENES)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            path = SCENES[name]
            cwd = os.path.dirname(path)
            size = ["--width", str(WIDTH), "--height", str(HEIGHT)]
            truth = os.path.join(tmp, name + "-truth.exr")
            t = timed([TRACE, path, "-o", truth, "--quiet", "--threads", "2", "--radiosity-reference", str(PATHS)] + size, cwd)
            print("%s: ground truth in %.1f s" % (name, t), file=sys.stderr)
            pov1 = os.path.join(tmp, name + "-pov1.exr")
            t1 = timed(["povray", "+I" + path, "+O" + pov1, "+FE", "+W%d" % WIDTH, "+H%d" % HEIGHT, "-A", "-D", "-GA", "+WT1"], cwd)
            variants = [("scene", path)] + [(label, with_settings(path, body, tmp, label)) for label, body in SWEEP]
            for label, scene in variants:
                out_t = os.path.join(tmp, "%s-%s-trace.exr" % (name, label.replace(" ", "")))
                out_p = os.path.join(tmp, "%s-%s-pov.exr" % (name, label.replace(" ", "")))
                tt = timed([TRACE, scene, "-o", out_t, "--quiet", "--threads", "2", "--aa", "off"] + size, cwd)
                tp = timed(["povray", "+I" + scene, "+O" + out_p, "+FE", "+W%d" % WIDTH, "+H%d" % HEIGHT, "-A", "-D", "-GA",
                            "+WT2"], cwd)
                row = {"scene": name, "settings": label, "trace_s": tt, "trace_flip": flip(out_t, truth), "pov_s": tp,
                       "pov_flip": flip(out_p, truth)}
                if label == "scene":
                    row["trace_vs_pov1"] = flip(out_t, pov1)
                    row["pov2_vs_pov1"] = flip(out_p, pov1)
                    row["pov1_s"] = t1
                    row["pov1_flip"] = flip(pov1, truth)
                rows.append(row)
                print(row, file=sys.stderr)
    fields = ["scene", "settings", "trace_s", "trace_flip", "pov_s", "pov_flip", "trace_vs_pov1", "pov2_vs_pov1", "pov1_s",
              "pov1_flip"]
    # (A run over some scenes keeps the other scenes' rows.)
    path = os.path.join(ROOT, "docs/radiosity.csv")
    if os.path.exists(path):
        kept = [{k: (float(v) if k not in ("scene", "settings") and v != "" else v) for k, v in r.items()}
                for r in csv.DictReader(open(path)) if r["scene"] not in names]
        rows = kept + rows
        names = [n for n in SCENES if any(r["scene"] == n for r in rows)]
        rows.sort(key=lambda r: names.index(r["scene"]))
    with open(os.path.join(ROOT, "docs/radiosity.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in rows:
            w.writerow(r)
    write_table(rows)
    write_chart(rows, names)


def write_table(rows):
    lines = ["Radiosity at %dx%d without anti-aliasing, two threads, against the ground truth (trace "
             "`--radiosity-reference %d`); written by `scripts/radiosity_quality.py`." % (WIDTH, HEIGHT, PATHS), "",
             "| scene | settings | trace (s) | trace FLIP | POV-Ray (s) | POV-Ray FLIP | POV-Ray / trace time |",
             "|---|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append("| %s | %s | %.2f | %.4f | %.2f | %.4f | %.1f |" % (
            r["scene"], r["settings"], r["trace_s"], r["trace_flip"], r["pov_s"], r["pov_flip"], r["pov_s"] / r["trace_s"]))
    lines += ["", "Each scene's own settings, against POV-Ray's reproducible picture (one thread): trace's distance "
              "from it, and POV-Ray's own two-thread picture's.", "",
              "| scene | trace vs POV-Ray +WT1 | POV-Ray +WT2 vs +WT1 | POV-Ray +WT1 (s) | POV-Ray +WT1 FLIP |",
              "|---|---:|---:|---:|---:|"]
    for r in rows:
        if r["settings"] == "scene":
            lines.append("| %s | %.4f | %.4f | %.2f | %.4f |" % (r["scene"], r["trace_vs_pov1"], r["pov2_vs_pov1"],
                                                                 r["pov1_s"], r["pov1_flip"]))
    open(os.path.join(ROOT, "docs/radiosity-quality.md"), "w").write("\n".join(lines) + "\n")


def write_chart(rows, names):
    pw, ph, pad = 300, 240, 50
    width = pad + len(names) * (pw + pad)
    svg = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">'
           % (width, ph + 2 * pad), '<rect width="100%" height="100%" fill="white"/>']
    for k, name in enumerate(names):
        pts = [r for r in rows if r["scene"] == name]
        xs = [math.log10(v) for r in pts for v in (r["trace_s"], r["pov_s"])]
        ys = [math.log10(max(v, 1e-4)) for r in pts for v in (r["trace_flip"], r["pov_flip"])]
        x0, x1 = min(xs) - 0.1, max(xs) + 0.1
        y0, y1 = min(ys) - 0.1, max(ys) + 0.1
        ox = pad + k * (pw + pad)

        def px(v):
            return ox + (math.log10(v) - x0) / (x1 - x0) * pw

        def py(v):
            return pad + ph - (math.log10(max(v, 1e-4)) - y0) / (y1 - y0) * ph

        svg.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#888"/>' % (ox, pad, pw, ph))
        svg.append('<text x="%d" y="%d" font-weight="bold">%s</text>' % (ox, pad - 8, name))
        svg.append('<text x="%d" y="%d">time (s, log)</text>' % (ox + pw / 2 - 30, pad + ph + 30))
        if k == 0:
            svg.append('<text x="8" y="%d" transform="rotate(-90 8 %d)">mean FLIP against ground truth (log)</text>'
                       % (pad + ph, pad + ph))
        for key_t, key_f, colour in (("trace_s", "trace_flip", "#d62728"), ("pov_s", "pov_flip", "#1f77b4")):
            line = sorted(pts, key=lambda r: r[key_t])
            svg.append('<polyline fill="none" stroke="%s" points="%s"/>' % (
                colour, " ".join("%.1f,%.1f" % (px(r[key_t]), py(r[key_f])) for r in line)))
            for r in line:
                svg.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"><title>%s %.2f s %.4f</title></circle>' % (
                    px(r[key_t]), py(r[key_f]), colour, r["settings"], r[key_t], r[key_f]))
        for v in (0.01, 0.02, 0.05, 0.1):
            if y0 <= math.log10(v) <= y1:
                svg.append('<text x="%d" y="%.1f" text-anchor="end">%g</text>' % (ox - 4, py(v) + 4, v))
        for v in (0.1, 0.3, 1, 3, 10, 30, 100):
            if x0 <= math.log10(v) <= x1:
                svg.append('<text x="%.1f" y="%d" text-anchor="middle">%g</text>' % (px(v), pad + ph + 14, v))
    svg.append('<text x="%d" y="%d" fill="#d62728">trace</text>' % (pad, ph + 2 * pad - 6))
    svg.append('<text x="%d" y="%d" fill="#1f77b4">POV-Ray 3.7</text>' % (pad + 50, ph + 2 * pad - 6))
    svg.append("</svg>")
    open(os.path.join(ROOT, "docs/radiosity.svg"), "w").write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main()

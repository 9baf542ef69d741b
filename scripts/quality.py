#!/usr/bin/env python3
"""Speed against accuracy: trace and POV-Ray 3.7 over their anti-aliasing settings.

For each chart scene (seven examples and two scenes of the speed table), both renderers render a
reference converged further than any setting of the sweep: trace with its own sampler
(method 3, threshold 0, up to 256 stratified samples in every pixel, area lights sampled over
their whole surface), POV-Ray with method 1 at threshold 0, depth 9 and jitter (82 jittered
samples in every pixel). Then a sweep of quality settings: no anti-aliasing; methods 1 and 2
at thresholds 0.3, 0.1 and 0 and several depths (without jitter, as trace's methods 1 and 2
match POV-Ray's); POV-Ray's method 1 with jitter, its default; trace's method 3. Each image is
compared with *its own renderer's* reference (mean FLIP and RMSE), so the curves show sampling
error against time; the FLIP between the two references (the renderers' remaining difference)
is recorded beside them. Times are end-to-end wall times in the same run.

Writes docs/quality.csv (every render), docs/quality.md (references, each renderer at its
default settings, and the first time each renderer reaches FLIP 0.01 and 0.005) and
docs/quality.svg (one log-log panel per scene: error against time, a curve per renderer and
method; docs/quality.png too when rsvg-convert is installed). At a size other than 320x240 the
files are docs/quality-WxH.*. Usage: scripts/quality.py [SCENE ...]   (env: WIDTH, HEIGHT)
"""
import csv
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TRACE = os.path.join(ROOT, "target", "release", "trace")
WIDTH = int(os.environ.get("WIDTH", 320))
HEIGHT = int(os.environ.get("HEIGHT", 240))
SCENES = ["area_glass_metal", "basic_spheres", "mirrors", "glass", "lights", "meshes", "transparent", "speed:spheres",
          "speed:terrain"]
TRACE_REFERENCE = ("3", "0.0", "7")
POV_REFERENCE = ("1", "0.0", "9", True)
# (method, threshold, depth); method 1 without a threshold is no anti-aliasing.
TRACE_SWEEP = [("1", "off", None), ("1", "0.3", "3"), ("1", "0.1", "3"), ("1", "0.0", "2"), ("1", "0.0", "3"), ("1", "0.0", "4"),
               ("1", "0.0", "6"), ("2", "0.3", "3"), ("2", "0.1", "3"), ("2", "0.0", "3"),
               ("3", "0.5", "2"), ("3", "0.3", "3"), ("3", "0.1", "3"), ("3", "0.1", "4"), ("3", "0.03", "4"), ("3", "0.0", "3"),
               ("3", "0.0", "4"), ("3", "0.0", "5")]
# (method, threshold, depth, jitter)
POV_SWEEP = [("1", None, None, False), ("1", "0.3", "3", False), ("1", "0.1", "3", False), ("1", "0.0", "2", False),
             ("1", "0.0", "3", False), ("1", "0.0", "4", False), ("1", "0.0", "6", False), ("2", "0.3", "3", False),
             ("2", "0.1", "3", False), ("2", "0.0", "3", False),
             ("1", "0.3", "3", True), ("1", "0.1", "3", True), ("1", "0.0", "3", True), ("1", "0.0", "5", True)]
# Each renderer's settings when none are given: trace's default, and POV-Ray's +A0.3 +R3 +AM1 +J1.
TRACE_DEFAULT = ("3", "0.3", "3")
POV_DEFAULT = ("1", "0.3", "3", True)


def timed(cmd, cwd):
    p = subprocess.run(["/usr/bin/time", "-f", "TIME %e"] + cmd, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), p.stderr[-2000:]))
    return float([l for l in p.stderr.splitlines() if l.startswith("TIME ")][-1].split()[1])


def trace_render(scene, out, method, aa, depth):
    cmd = [TRACE, scene, "-o", out, "--width", str(WIDTH), "--height", str(HEIGHT), "--quiet", "--aa", aa,
           "--aa-method", method]
    if depth:
        cmd += ["--aa-depth", depth]
    return timed(cmd, os.path.dirname(scene))


def trace_setting(method, aa, depth):
    return "--aa %s%s --aa-method %s" % (aa, " --aa-depth " + depth if depth else "", method)


def pov_render(scene, out, method, threshold, depth, jitter):
    cmd = ["povray", "+I" + os.path.basename(scene), "+O" + out, "+FE", "+W%d" % WIDTH, "+H%d" % HEIGHT, "-D", "-GA"]
    cmd += ["-A"] if threshold is None else ["+A" + threshold, "+R" + depth, "+AM" + method]
    cmd += ["+J"] if jitter else ["-J"]
    return timed(cmd, os.path.dirname(scene))


def pov_setting(method, threshold, depth, jitter):
    return "-A" if threshold is None else "+AM%s +A%s +R%s %s" % (method, threshold, depth, "+J" if jitter else "-J")


def compare(ref, test):
    out = subprocess.run([TRACE, "compare", ref, test], capture_output=True, text=True, check=True).stdout.split()
    return float(out[2]), float(out[4])


def chart(rows, path):
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    cols = 3
    pw, ph, gap_x, gap_y, left, top = 260, 200, 70, 70, 60, 40
    w = left + cols * (pw + gap_x)
    h = top + math.ceil(len(scenes) / cols) * (ph + gap_y) + 50
    styles = {"trace, method 1": ("#d62728", ""), "trace, method 2": ("#ff7f0e", "9,3,2,3"),
              "trace, method 3": ("#8b0000", ""), "POV-Ray, method 1": ("#1f77b4", "6,4"),
              "POV-Ray, method 1 + jitter": ("#17becf", "6,4"), "POV-Ray, method 2": ("#2ca02c", "2,3")}
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">' % (w, h),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="20" text-anchor="middle" font-size="14">mean FLIP against each renderer\'s converged image, against end-to-end time (log-log), %d×%d</text>' % (w / 2, WIDTH, HEIGHT)]
    for k, scene in enumerate(scenes):
        x0 = left + (k % cols) * (pw + gap_x)
        y0 = top + (k // cols) * (ph + gap_y)
        pts = [r for r in rows if r["scene"] == scene and float(r["flip"]) > 0]
        ts = [math.log10(float(r["seconds"])) for r in pts]
        es = [math.log10(float(r["flip"])) for r in pts]
        tx0, tx1 = math.floor(min(ts) * 2) / 2, math.ceil(max(ts) * 2) / 2
        ey0, ey1 = math.floor(min(es)), math.ceil(max(es))
        sx = lambda t: x0 + (math.log10(t) - tx0) / max(tx1 - tx0, 1e-9) * pw
        sy = lambda e: y0 + ph - (math.log10(e) - ey0) / max(ey1 - ey0, 1e-9) * ph
        out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#444"/>' % (x0, y0, pw, ph))
        out.append('<text x="%d" y="%d" text-anchor="middle" font-size="12">%s</text>' % (x0 + pw / 2, y0 - 6, scene))
        for e in range(ey0, ey1 + 1):
            y = sy(10 ** e)
            out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#eee"/><text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (x0, y, x0 + pw, y, x0 - 4, y + 4, e))
        t = tx0
        while t <= tx1 + 1e-9:
            x = sx(10 ** t)
            out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#eee"/><text x="%.1f" y="%d" text-anchor="middle">%.2g s</text>' % (x, y0, x, y0 + ph, x, y0 + ph + 14, 10 ** t))
            t += 0.5
        for curve, (colour, dash) in styles.items():
            series = sorted((float(r["seconds"]), float(r["flip"])) for r in pts if r["curve"] == curve)
            # The lower envelope: the best error reached at each time or less.
            best, env = float("inf"), []
            for s, e in series:
                if e < best:
                    best = e
                    env.append((s, e))
            if env:
                out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="2" stroke-dasharray="%s"/>'
                           % (" ".join("%.1f,%.1f" % (sx(s), sy(e)) for s, e in env), colour, dash))
            for s, e in series:
                out.append('<circle cx="%.1f" cy="%.1f" r="2.5" fill="%s"/>' % (sx(s), sy(e), colour))
    for i, (curve, (colour, dash)) in enumerate(styles.items()):
        lx = left + (i % 3) * 300
        ly = h - 30 + (i // 3) * 16
        out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2" stroke-dasharray="%s"/><text x="%d" y="%d">%s</text>'
                   % (lx, ly, lx + 30, ly, colour, dash, lx + 36, ly + 4, curve))
    out.append("</svg>")
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")


def main():
    scenes = sys.argv[1:] or SCENES
    subprocess.run(["cargo", "build", "--release", "--quiet", "--manifest-path", os.path.join(ROOT, "Cargo.toml")], check=True)
    rows, refs = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for name in scenes:
            if name.startswith("speed:"):
                # A scene of the speed table (scripts/speed.py): 10k spheres, 100k triangles.
                sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
                import speed
                name = name.split(":", 1)[1]
                scene = os.path.join(tmp, name + ".pov")
                if name == "spheres":
                    speed.spheres(10000, scene)
                else:
                    speed.terrain(225, scene)
            else:
                scene = os.path.join(ROOT, "examples", name + ".rt")
            t_ref = os.path.join(tmp, name + ".tref.exr")
            p_ref = os.path.join(tmp, name + ".pref.exr")
            tt = trace_render(scene, t_ref, *TRACE_REFERENCE)
            pt = pov_render(scene, p_ref, *POV_REFERENCE)
            cross, _ = compare(p_ref, t_ref)
            refs.append((name, tt, pt, cross))
            print("%-14s references: trace %.2f s, POV-Ray %.2f s, FLIP between them %.4f" % (name, tt, pt, cross), flush=True)
            for method, aa, depth in TRACE_SWEEP:
                out = os.path.join(tmp, "t.exr")
                s = trace_render(scene, out, method, aa, depth)
                f, r = compare(t_ref, out)
                rows.append({"scene": name, "curve": "trace, method %s" % method, "setting": trace_setting(method, aa, depth),
                             "seconds": "%.3f" % s, "flip": "%.6f" % f, "rmse": "%.6f" % r})
            for method, threshold, depth, jitter in POV_SWEEP:
                out = os.path.join(tmp, "p.exr")
                s = pov_render(scene, out, method, threshold, depth, jitter)
                f, r = compare(p_ref, out)
                curve = "POV-Ray, method %s%s" % (method, " + jitter" if jitter else "")
                rows.append({"scene": name, "curve": curve, "setting": pov_setting(method, threshold, depth, jitter),
                             "seconds": "%.3f" % s, "flip": "%.6f" % f, "rmse": "%.6f" % r})
    docs = os.path.join(ROOT, "docs")
    stem = "quality" if (WIDTH, HEIGHT) == (320, 240) else "quality-%dx%d" % (WIDTH, HEIGHT)
    with open(os.path.join(docs, stem + ".csv"), "w", newline="") as fh:
        wr = csv.DictWriter(fh, fieldnames=list(rows[0]))
        wr.writeheader()
        wr.writerows(rows)
    def row(name, setting):
        return next(r for r in rows if r["scene"] == name and r["setting"] == setting)

    lines = ["Each renderer at its default settings (trace: `%s`; POV-Ray: `%s`), %d×%d; FLIP against the renderer's own reference." % (
                 trace_setting(*TRACE_DEFAULT), pov_setting(*POV_DEFAULT), WIDTH, HEIGHT), "",
             "| scene | trace (s) | trace FLIP | POV-Ray (s) | POV-Ray FLIP | POV-Ray / trace time | trace's error no higher |",
             "|---|---:|---:|---:|---:|---:|---|"]
    for name, _, _, _ in refs:
        t, p = row(name, trace_setting(*TRACE_DEFAULT)), row(name, pov_setting(*POV_DEFAULT))
        lines.append("| %s | %s | %.4f | %s | %.4f | %.2f× | %s |" % (
            name, t["seconds"], float(t["flip"]), p["seconds"], float(p["flip"]), float(p["seconds"]) / float(t["seconds"]),
            "yes" if float(t["flip"]) <= float(p["flip"]) else "no"))
    lines += ["", "The first time each renderer reaches mean FLIP 0.01 and 0.005 against its own reference (any setting of the sweep).", "",
              "| scene | reference: trace (s) | reference: POV-Ray (s) | FLIP between references | trace at FLIP ≤ 0.01 | POV-Ray at FLIP ≤ 0.01 | trace at FLIP ≤ 0.005 | POV-Ray at FLIP ≤ 0.005 |",
              "|---|---:|---:|---:|---|---|---|---|"]
    for name, tt, pt, cross in refs:
        def best(curve_prefix, limit):
            ok = [r for r in rows if r["scene"] == name and r["curve"].startswith(curve_prefix) and float(r["flip"]) <= limit]
            if not ok:
                return "—"
            r = min(ok, key=lambda r: float(r["seconds"]))
            return "%s s (`%s`, FLIP %.4f)" % (r["seconds"], r["setting"], float(r["flip"]))
        lines.append("| %s | %.2f | %.2f | %.4f | %s | %s | %s | %s |" % (
            name, tt, pt, cross, best("trace", 0.01), best("POV-Ray", 0.01), best("trace", 0.005), best("POV-Ray", 0.005)))
    with open(os.path.join(docs, stem + ".md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    chart(rows, os.path.join(docs, stem + ".svg"))
    # A PNG copy when librsvg's converter is installed (apt-get install librsvg2-bin).
    if subprocess.run(["sh", "-c", "command -v rsvg-convert"], capture_output=True).returncode == 0:
        subprocess.run(["rsvg-convert", os.path.join(docs, stem + ".svg"), "-o", os.path.join(docs, stem + ".png")], check=True)
    print("\n".join(lines))


if __name__ == "__main__":
    main()

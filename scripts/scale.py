#!/usr/bin/env python3
"""The scaling chart: trace against POV-Ray 3.7 as scenes and images grow, in one run.

Three families, each rendered by both renderers side by side (no anti-aliasing, as in the
scale issue), recording end-to-end wall time and peak memory (max RSS):
  - statements: N spheres written one statement each (10^3 .. 10^6), 640x480;
  - loop:       N spheres made by a #for loop (10^3 .. 10^7), 640x480;
  - pixels:     examples/mirrors.rt at 10^5 .. 10^9 pixels (square PNGs).
For each curve it fits the slope of log(time) and log(memory) against log(size) over the
sizes where the renderer's start-up no longer dominates (the upper half of each range).

Writes docs/scale.csv, docs/scale.md (table and slopes) and docs/scale.svg (log-log time and
memory). Usage: scripts/scale.py [--quick | --from-csv | --family F | --throughput |
                                   --realistic [N ...]]
  --quick:      small sizes only, written to target/;
  --from-csv:   the table and chart again from docs/scale.csv, without rendering;
  --family F:   measure family F (statements, loop or pixels) again and keep the other rows;
  --throughput: parse throughput on a generated 100 MB file of sphere statements, plain and
                with an expression in each (so the grammar reads them instead of the fast
                lane), with the default threads and one; prints MB/s, writes nothing.
  --realistic:  the realistic file (realistic_scene: each object its own pigment and finish,
                some an interior, comments, small expressions; about 130 bytes an object) at
                N objects (default 100000 and 1000000): parse MB/s of trace, and trace's and
                POV-Ray's parse time, whole time and memory in the same run, as ratios;
                prints a Markdown table, writes nothing.
"""
import csv
import math
import os
import random
import subprocess
import sys
import tempfile

import speed  # (this folder: the sphere scenes of the speed table)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TRACE = os.path.join(ROOT, "target", "release", "trace")


def loop_scene(n, path):
    """n spheres from a #for loop, placed by a formula (no rand: both renderers agree)."""
    side = 40.0
    r = 0.5 * side / n ** (1 / 3)
    lines = speed.scene_head() + [
             "#for (I, 0, %d)" % (n - 1),
             "  sphere { <mod(I * 7919, 10007) / 10007, mod(I * 104729, 10009) / 10009,"
             " mod(I * 1299709, 10037) / 10037> * %g - %g, %g" % (side, side / 2, r),
             "    pigment { rgb <mod(I, 7) / 7, mod(I, 11) / 11, mod(I, 13) / 13> } }",
             "#end"]
    speed.write(path, lines)


def realistic_scene(n, path):
    """n objects as a user's exported scene writes them: each its own pigment and finish,
    one in ten an interior, a comment every few lines, small expressions (no rand)."""
    rnd = random.Random(7)
    side = 40.0
    r = 0.5 * side / n ** (1 / 3)
    out = speed.scene_head() + ["#declare Gloss = 0.4;"]
    for i in range(n):
        x, y, z = (rnd.uniform(-side / 2, side / 2) for _ in range(3))
        c = [rnd.random() for _ in range(3)]
        if i % 8 == 0:
            out.append("// part %d" % i)
        interior = " interior { ior 1.%d }" % (i % 5) if i % 10 == 0 else ""
        out.append("sphere { <%.3f, %.3f, %.3f>, %.3f pigment { rgb <%.2f, %.2f, %.2f> }"
                   " finish { phong Gloss*%d specular 0.1 }%s }"
                   % (x, y, z, r, c[0], c[1], c[2], 1 + i % 2, interior))
    speed.write(path, out)


def povray_parse_seconds(stderr):
    """POV-Ray's own parse time from its statistics (`Parse Time: … (5.123 seconds)`)."""
    for line in stderr.splitlines():
        if line.strip().startswith("Parse Time"):
            return float(line.split("(")[1].split()[0])
    return float("nan")


def realistic(sizes):
    """Parse speed and the whole render of the realistic file, trace against POV-Ray."""
    print("| objects | MB | trace parse | MB/s | POV-Ray parse | parse ratio | trace total | POV-Ray total | total ratio | trace MiB | POV-Ray MiB | memory ratio |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for n in sizes:
            path = os.path.join(tmp, "realistic.pov")
            realistic_scene(n, path)
            mb = os.path.getsize(path) / 1e6
            cmd = [TRACE, path, "-o", os.path.join(tmp, "t.png"), "+W320", "+H240", "-A", "--stats"]
            p = subprocess.run(["/usr/bin/time", "-f", "TIME %e %M"] + cmd, capture_output=True, text=True, check=True)
            parse = float([l for l in p.stderr.splitlines() if l.startswith("Parse Time")][0].split()[2])
            t_total, t_kb = [float(v) for v in p.stderr.splitlines()[-1].split()[1:3]]
            p = subprocess.run(["/usr/bin/time", "-f", "TIME %e %M", "povray", "+I" + path,
                                "+O" + os.path.join(tmp, "p.png"), "+W320", "+H240", "-A", "-D"],
                               capture_output=True, text=True, check=True, cwd=tmp)
            p_parse = povray_parse_seconds(p.stderr)
            p_total, p_kb = [float(v) for v in p.stderr.splitlines()[-1].split()[1:3]]
            print("| %d | %.0f | %.2f s | %.0f | %.2f s | %.2f | %.2f s | %.2f s | %.2f | %.0f | %.0f | %.2f |"
                  % (n, mb, parse, mb / parse, p_parse, parse / p_parse, t_total, p_total,
                     t_total / p_total, t_kb / 1024, p_kb / 1024, t_kb / p_kb), flush=True)


def slope(points):
    """Least-squares slope of log y against log x."""
    xs = [math.log10(x) for x, _ in points]
    ys = [math.log10(y) for _, y in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")


def upper_half(series):
    """The points used for a slope: the larger half of the sizes (at least two)."""
    series = sorted(series)
    return series[len(series) // 2:] if len(series) > 3 else series[-2:]


FAMILIES = [("statements", "spheres, one statement each (count)"),
            ("loop", "spheres from a #for loop (count)"),
            ("pixels", "pixels of mirrors.rt")]
COLOURS = {"statements": "#d62728", "loop": "#2ca02c", "pixels": "#1f77b4"}


def panel(rows, key_t, key_p, unit, title, x_off, w, h):
    """One log-log panel (an SVG group) of `key_t`/`key_p` (trace/POV-Ray) against size."""
    left, right, top, bottom = 70, 20, 30, 50
    vals = [float(r[k]) for r in rows for k in (key_t, key_p)]
    sizes = [float(r["size"]) for r in rows]
    x0, x1 = math.floor(math.log10(min(sizes))), math.ceil(math.log10(max(sizes)))
    y0, y1 = math.floor(math.log10(min(vals))), math.ceil(math.log10(max(vals)))
    sx = lambda v: x_off + left + (math.log10(v) - x0) / max(x1 - x0, 1) * (w - left - right)
    sy = lambda v: h - bottom - (math.log10(v) - y0) / max(y1 - y0, 1) * (h - top - bottom)
    out = []
    for e in range(x0, x1 + 1):
        x = sx(10 ** e)
        out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (x, top, x, h - bottom))
        out.append('<text x="%.1f" y="%d" text-anchor="middle">10<tspan dy="-6" font-size="9">%d</tspan></text>' % (x, h - bottom + 18, e))
    for e in range(y0, y1 + 1):
        y = sy(10 ** e)
        out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (x_off + left, y, x_off + w - right, y))
        out.append('<text x="%d" y="%.1f" text-anchor="end">%g %s</text>' % (x_off + left - 6, y + 4, 10 ** e, unit))
    out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#444"/>' % (x_off + left, top, w - left - right, h - top - bottom))
    out.append('<text x="%d" y="%d" text-anchor="middle">size (statements, spheres or pixels)</text>' % (x_off + (left + w - right) / 2, h - 10))
    out.append('<text x="%d" y="18" text-anchor="middle">%s (log-log)</text>' % (x_off + (left + w - right) / 2, title))
    for fam, _ in FAMILIES:
        for key, dash in ((key_t, ""), (key_p, "6,4")):
            series = sorted((float(r["size"]), float(r[key])) for r in rows if r["family"] == fam)
            if not series:
                continue
            d = " ".join("%.1f,%.1f" % (sx(x), sy(y)) for x, y in series)
            out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="2" stroke-dasharray="%s"/>' % (d, COLOURS[fam], dash))
            for x, y in series:
                out.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"/>' % (sx(x), sy(y), COLOURS[fam]))
    return out


def svg_chart(rows, path):
    w, h, legend = 440, 400, 60
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">' % (2 * w, h + legend),
           '<rect width="100%" height="100%" fill="white"/>']
    out += panel(rows, "trace_s", "povray_s", "s", "end-to-end time", 0, w, h)
    out += panel(rows, "trace_mib", "povray_mib", "MiB", "peak memory", w, w, h)
    x = 80
    for fam, label in FAMILIES:
        out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"/>' % (x, h + 15, x + 30, h + 15, COLOURS[fam]))
        out.append('<text x="%d" y="%d">%s</text>' % (x + 36, h + 19, label.split(" (")[0]))
        x += 260
    out.append('<text x="80" y="%d">solid: trace, dashed: POV-Ray 3.7</text>' % (h + 45))
    out.append("</svg>")
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")


def main():
    known = {"--quick", "--from-csv", "--family", "--throughput", "--realistic"}
    flags = [a for a in sys.argv[1:] if a.startswith("-")]
    if any(a not in known for a in flags):
        # Anything else (--help among them) prints the usage rather than starting an
        # hour-long run.
        print(__doc__)
        sys.exit(0 if flags == ["--help"] or flags == ["-h"] else 2)
    if "--from-csv" in sys.argv:
        docs = os.path.join(ROOT, "docs")
        with open(os.path.join(docs, "scale.csv"), newline="") as fh:
            rows = [dict(r, size=int(r["size"])) for r in csv.DictReader(fh)]
        write_docs(rows, docs, "")
        return
    quick = "--quick" in sys.argv
    subprocess.run(["cargo", "build", "--release", "--quiet", "--manifest-path", os.path.join(ROOT, "Cargo.toml")], check=True)
    if "--realistic" in sys.argv:
        sizes = [int(a) for a in sys.argv[sys.argv.index("--realistic") + 1:]] or [100000, 1000000]
        realistic(sizes)
        return
    if "--throughput" in sys.argv:
        throughput()
        return
    only = sys.argv[sys.argv.index("--family") + 1] if "--family" in sys.argv else None
    statements = (1000, 10000) if quick else (1000, 10000, 100000, 1000000)
    loops = (1000, 10000) if quick else (1000, 10000, 100000, 1000000, 10000000)
    pixels = (10 ** 5, 10 ** 6) if quick else (10 ** 5, 10 ** 6, 10 ** 7, 10 ** 8, 10 ** 9)
    if only:
        statements, loops, pixels = [sizes if only == fam else () for fam, sizes in
                                     (("statements", statements), ("loop", loops), ("pixels", pixels))]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        jobs = []
        for n in statements:
            jobs.append(("statements", n, lambda p, n=n: speed.spheres(n, p), 640, 480))
        for n in loops:
            jobs.append(("loop", n, lambda p, n=n: loop_scene(n, p), 640, 480))
        for px in pixels:
            side = int(round(math.sqrt(px)))
            jobs.append(("pixels", side * side, None, side, side))
        for family, size, make, w, h in jobs:
            if make:
                name = "%s_%d" % (family, size)
                scene = name + ".pov"
                make(os.path.join(tmp, scene))
                mib_file = os.path.getsize(os.path.join(tmp, scene)) / 2 ** 20
            else:
                name = "pixels_%d" % size
                scene = os.path.join(ROOT, "examples", "mirrors.rt")
                mib_file = 0.0
            # (The loop of 10^7 needs more evaluation steps than the default budget.)
            tt, tm = speed.run([TRACE, scene, "-o", name + ".t.png", "--width", str(w), "--height", str(h),
                          "--aa", "off", "--quiet", "--max-steps", "1000000000"], tmp)
            pt, pm = speed.run(["povray", "+I" + scene, "+O" + name + ".p.png", "+FN", "+W%d" % w, "+H%d" % h,
                          "-D", "-A", "-GA"], tmp)
            row = {"family": family, "size": size, "file_mib": "%.1f" % mib_file,
                   "trace_s": "%.3f" % tt, "povray_s": "%.3f" % pt, "time_ratio": "%.2f" % (tt / pt),
                   "trace_mib": "%.0f" % tm, "povray_mib": "%.0f" % pm, "memory_ratio": "%.2f" % (tm / pm)}
            rows.append(row)
            print("%-10s %11d  trace %8.2f s %7.0f MiB   POV-Ray %8.2f s %7.0f MiB   time %.2f  memory %.2f"
                  % (family, size, tt, tm, pt, pm, tt / pt, tm / pm), flush=True)
            for f in (name + ".t.png", name + ".p.png"):
                if os.path.exists(os.path.join(tmp, f)):
                    os.remove(os.path.join(tmp, f))
    docs = os.path.join(ROOT, "target") if quick else os.path.join(ROOT, "docs")
    suffix = "-quick" if quick else ""
    if only:
        # The other families' rows as last measured, in the table's order.
        with open(os.path.join(docs, "scale.csv"), newline="") as fh:
            kept = [dict(r, size=int(r["size"])) for r in csv.DictReader(fh) if r["family"] != only]
        order = [fam for fam, _ in FAMILIES]
        rows = sorted(kept + rows, key=lambda r: (order.index(r["family"]), int(r["size"])))
    with open(os.path.join(docs, "scale%s.csv" % suffix), "w", newline="") as fh:
        wr = csv.DictWriter(fh, fieldnames=list(rows[0]))
        wr.writeheader()
        wr.writerows(rows)
    write_docs(rows, docs, suffix)


def throughput():
    """Parse throughput (MB/s, from trace's own parse time) on a 100 MB statement file."""
    with tempfile.TemporaryDirectory() as tmp:
        plain = os.path.join(tmp, "plain.pov")
        speed.spheres(1240000, plain)
        with open(plain) as fh:
            text = fh.read()
        variants = [("plain statements (fast lane)", plain)]
        expr = os.path.join(tmp, "expr.pov")
        with open(expr, "w") as fh:
            # (Brackets: the fast lane reads names and numbers joined by operators, `*1`
            # too, and leaves a bracket to the grammar.)
            fh.write(text.replace(" pigment {", "*(1) pigment {"))
        variants.append(("an expression in each (grammar)", expr))
        for label, path in variants:
            mb = os.path.getsize(path) / 1e6
            for threads in (None, 1):
                best = None
                for _ in range(3):
                    cmd = [TRACE, path, "-o", os.path.join(tmp, "out.png"), "--width", "64",
                           "--height", "48", "--aa", "off", "--stats"]
                    if threads:
                        cmd += ["--threads", str(threads)]
                    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stderr
                    t = float([l for l in out.splitlines() if l.startswith("Parse Time")][0].split()[2])
                    best = t if best is None else min(best, t)
                print("%-34s %5.0f MB  %-15s parse %.2f s  %4.0f MB/s"
                      % (label, mb, "one thread" if threads else "default threads", best, mb / best), flush=True)


def write_docs(rows, docs, suffix):
    """docs/scale.md (the table and the slopes) and docs/scale.svg from the rows."""
    labels = dict(FAMILIES)
    lines = ["| family | size | file (MiB) | trace (s) | POV-Ray (s) | trace / POV-Ray time | trace peak (MiB) | POV-Ray peak (MiB) | trace / POV-Ray memory |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["family"], "{:,}".format(r["size"]), r["file_mib"] if float(r["file_mib"]) > 0 else "—", r["trace_s"], r["povray_s"], r["time_ratio"],
            r["trace_mib"], r["povray_mib"], r["memory_ratio"]))
    lines += ["", "Slopes of log(time) and log(peak memory) against log(size), fitted over the larger half of each range:", "",
              "| family | trace time | POV-Ray time | trace memory | POV-Ray memory |", "|---|---:|---:|---:|---:|"]
    for fam, _ in FAMILIES:
        fr = [r for r in rows if r["family"] == fam]
        if len(fr) < 2:
            continue
        s = [slope(upper_half([(float(r["size"]), float(r[k])) for r in fr]))
             for k in ("trace_s", "povray_s", "trace_mib", "povray_mib")]
        lines.append("| %s | %.2f | %.2f | %.2f | %.2f |" % (labels[fam].split(" (")[0], *s))
    with open(os.path.join(docs, "scale%s.md" % suffix), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    svg_chart(rows, os.path.join(docs, "scale%s.svg" % suffix))
    print("\n".join(lines))


if __name__ == "__main__":
    main()

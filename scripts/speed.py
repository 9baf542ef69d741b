#!/usr/bin/env python3
"""The speed table: trace against POV-Ray 3.7 on big scenes, in one run.

Generates the speed scenes (random spheres, mesh2 terrains, instances of a 20k-triangle mesh),
renders each with trace and with POV-Ray at the same size and anti-aliasing (method 1,
threshold 0.3, depth 3, no jitter), and records end-to-end wall time (parse + build + render
+ write; both write an EXR of half floats, POV-Ray's +FE), peak memory (max RSS), and the mean
FLIP between the two images.

Writes docs/speed.csv, docs/speed.md (the table) and docs/speed.svg (log-log chart of time
against scene size). Usage: scripts/speed.py [--quick]   (env: WIDTH, HEIGHT, RUNS)
--quick renders only the small sizes (a smoke test of the script; it writes to target/).
"""
import csv
import math
import os
import random
import subprocess
import sys
import tempfile
import time

import make_meshes  # (this folder)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WIDTH = int(os.environ.get("WIDTH", 640))
HEIGHT = int(os.environ.get("HEIGHT", 480))
RUNS = int(os.environ.get("RUNS", 1))
TRACE = os.path.join(ROOT, "target", "release", "trace")
HEADER = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"


def scene_head():
    """The lines before the objects of the generated sphere scenes: camera, light, floor."""
    return [HEADER,
            "camera { location <0, 30, -70> look_at 0 angle 50 right x*image_width/image_height }",
            "light_source { <30, 60, -40>, rgb 1 }",
            "plane { y, -25 pigment { rgb 0.8 } }"]


def spheres(n, path):
    rnd = random.Random(1)
    side = 40.0
    r = 0.5 * side / n ** (1 / 3)
    out = scene_head()
    for _ in range(n):
        x, y, z = (rnd.uniform(-side / 2, side / 2) for _ in range(3))
        c = [rnd.random() for _ in range(3)]
        out.append("sphere { <%.4f,%.4f,%.4f>, %.4f pigment { rgb <%.3f,%.3f,%.3f> } }" % (x, y, z, r, *c))
    write(path, out)


def terrain_mesh2(side, name):
    """A side×side-vertex height field as a mesh2 declaration (2·(side−1)² triangles)."""
    out = ["#declare %s = mesh2 {" % name, "vertex_vectors { %d," % (side * side)]
    rows = []
    for j in range(side):
        z = 20.0 * (j / (side - 1) - 0.5)
        row = []
        for i in range(side):
            x = 20.0 * (i / (side - 1) - 0.5)
            y = 0.8 * math.sin(0.9 * x) * math.cos(0.7 * z) + 0.3 * math.sin(2.3 * x + 1.7 * z)
            row.append("<%.5f,%.5f,%.5f>" % (x, y, z))
        rows.append(",".join(row))
    out.append(",\n".join(rows))
    out.append("}")
    t = 2 * (side - 1) ** 2
    out.append("face_indices { %d," % t)
    rows = []
    for j in range(side - 1):
        row = []
        for i in range(side - 1):
            a = j * side + i
            row.append("<%d,%d,%d>,<%d,%d,%d>" % (a, a + side, a + 1, a + 1, a + side, a + side + 1))
        rows.append(",".join(row))
    out.append(",\n".join(rows))
    out.append("}")
    out.append("}")
    return out


def terrain(side, path):
    out = [HEADER,
           "camera { location <0, 12, -18> look_at <0, 0, 0> angle 60 right x*image_width/image_height }",
           "light_source { <-20, 30, -10>, rgb 1 }"]
    out += terrain_mesh2(side, "Terrain")
    out.append("object { Terrain pigment { rgb <0.5, 0.7, 0.4> } finish { phong 0.3 } }")
    write(path, out)


def knot_mesh2(segments, sides, name):
    """A trefoil-knot tube (scripts/make_meshes.py) as a smooth mesh2 (2·segments·sides triangles)."""
    verts, norms, quads = make_meshes.knot_tube(segments, sides, 0.35)
    vec = lambda v: "<%.5f,%.5f,%.5f>" % tuple(v)
    faces = ["<%d,%d,%d>,<%d,%d,%d>" % (a, c, d, a, d, b) for a, c, d, b in quads]
    return ["#declare %s = mesh2 {" % name,
            "vertex_vectors { %d,\n%s }" % (len(verts), ",\n".join(map(vec, verts))),
            "normal_vectors { %d,\n%s }" % (len(norms), ",\n".join(map(vec, norms))),
            "face_indices { %d,\n%s }" % (2 * len(verts), ",\n".join(faces)),
            "}"]


def instances(count, path):
    """`count` instances of a 20,000-triangle knot on a grid."""
    out = [HEADER,
           "camera { location <0, 60, -90> look_at <0, 0, 0> angle 50 right x*image_width/image_height }",
           "light_source { <-60, 100, -50>, rgb 1 }",
           "plane { y, -4 pigment { rgb 0.7 } }"]
    out += knot_mesh2(500, 20, "Knot")
    per_row = math.ceil(math.sqrt(count))
    rnd = random.Random(2)
    for k in range(count):
        x = (k % per_row - per_row / 2) * 8.0
        z = (k // per_row - per_row / 2) * 8.0
        c = [rnd.random() for _ in range(3)]
        out.append("object { Knot rotate <%d, %d, 0> translate <%.1f, 0, %.1f> pigment { rgb <%.3f,%.3f,%.3f> } finish { phong 0.5 } }"
                   % (rnd.randrange(360), rnd.randrange(360), x, z, *c))
    write(path, out)


def write(path, lines):
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")


def run(cmd, cwd):
    """Best wall time (s) and its peak RSS (MiB) over RUNS runs. The time is this script's
    monotonic clock around the run (/usr/bin/time, which gives the peak memory, reports time
    in steps of 10 ms: 5 % of the smallest rows)."""
    best = None
    for _ in range(RUNS):
        start = time.perf_counter()
        p = subprocess.run(["/usr/bin/time", "-f", "TIME %e %M"] + cmd, cwd=cwd,
                           capture_output=True, text=True)
        t = time.perf_counter() - start
        if p.returncode != 0:
            sys.exit("failed: %s\n%s" % (" ".join(cmd), p.stderr[-2000:]))
        line = [l for l in p.stderr.splitlines() if l.startswith("TIME ")][-1]
        kb = int(line.split()[2])
        if best is None or t < best[0]:
            best = (t, kb / 1024.0)
    return best


def flip(ref, test):
    out = subprocess.run([TRACE, "compare", ref, test], capture_output=True, text=True, check=True).stdout
    return float(out.split()[2])


def svg_chart(rows, path):
    """Log-log chart: end-to-end time against scene size, one line per family and renderer."""
    families = [("spheres", "random spheres (count)"), ("terrain", "mesh2 terrain (triangles)")]
    w, h, left, right, top, bottom = 720, 420, 70, 230, 30, 50
    pts = [(float(r["size"]), float(r[k])) for r in rows for k in ("trace_s", "povray_s")
           if r["family"] in dict(families)]
    xs = [math.log10(p[0]) for p in pts]
    ys = [math.log10(p[1]) for p in pts]
    x0, x1 = math.floor(min(xs)), math.ceil(max(xs))
    y0, y1 = math.floor(min(ys)), math.ceil(max(ys))
    sx = lambda v: left + (math.log10(v) - x0) / (x1 - x0) * (w - left - right)
    sy = lambda v: h - bottom - (math.log10(v) - y0) / (y1 - y0) * (h - top - bottom)
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">' % (w, h),
           '<rect width="100%" height="100%" fill="white"/>']
    for e in range(x0, x1 + 1):
        x = sx(10 ** e)
        out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (x, top, x, h - bottom))
        out.append('<text x="%.1f" y="%d" text-anchor="middle">10<tspan dy="-6" font-size="9">%d</tspan></text>' % (x, h - bottom + 18, e))
    for e in range(y0, y1 + 1):
        y = sy(10 ** e)
        out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (left, y, w - right, y))
        out.append('<text x="%d" y="%.1f" text-anchor="end">%g s</text>' % (left - 6, y + 4, 10 ** e))
    out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#444"/>' % (left, top, w - left - right, h - top - bottom))
    out.append('<text x="%d" y="%d" text-anchor="middle">scene size (objects or triangles)</text>' % ((left + w - right) / 2, h - 10))
    out.append('<text x="%d" y="18" text-anchor="middle">end-to-end time, %d×%d, AA 0.3 (log-log)</text>' % ((left + w - right) / 2, WIDTH, HEIGHT))
    styles = {("spheres", "trace"): ("#d62728", ""), ("spheres", "povray"): ("#d62728", "6,4"),
              ("terrain", "trace"): ("#1f77b4", ""), ("terrain", "povray"): ("#1f77b4", "6,4")}
    legend_y = top + 10
    for fam, label in families:
        for who, key in (("trace", "trace_s"), ("povray", "povray_s")):
            series = sorted((float(r["size"]), float(r[key])) for r in rows if r["family"] == fam)
            if not series:
                continue
            colour, dash = styles[(fam, who)]
            d = " ".join("%.1f,%.1f" % (sx(x), sy(y)) for x, y in series)
            out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="2" stroke-dasharray="%s"/>' % (d, colour, dash))
            for x, y in series:
                out.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"/>' % (sx(x), sy(y), colour))
            lx = w - right + 15
            out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2" stroke-dasharray="%s"/>' % (lx, legend_y, lx + 30, legend_y, colour, dash))
            out.append('<text x="%d" y="%d">%s, %s</text>' % (lx + 36, legend_y + 4, "trace" if who == "trace" else "POV-Ray", label.split(" (")[0]))
            legend_y += 20
    out.append("</svg>")
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")


def main():
    quick = "--quick" in sys.argv
    subprocess.run(["cargo", "build", "--release", "--quiet", "--manifest-path", os.path.join(ROOT, "Cargo.toml")], check=True)
    scenes = [("spheres", n, lambda p, n=n: spheres(n, p)) for n in ((1000, 3000) if quick else (1000, 3000, 10000, 30000, 100000))]
    sides = (72,) if quick else (72, 225, 708)
    scenes += [("terrain", 2 * (s - 1) ** 2, lambda p, s=s: terrain(s, p)) for s in sides]
    scenes += [("instances", 300 * 20000, lambda p: instances(300, p))] if not quick else []
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for family, size, make in scenes:
            name = "%s_%d" % (family, size)
            make(os.path.join(tmp, name + ".pov"))
            tt, tm = run([TRACE, name + ".pov", "-o", name + ".t.exr", "--width", str(WIDTH), "--height", str(HEIGHT),
                          "--aa", "0.3", "--aa-depth", "3", "--aa-method", "1", "--bits", "16", "--quiet"], tmp)
            pt, pm = run(["povray", "+I" + name + ".pov", "+O" + name + ".p.exr", "+FE", "+W%d" % WIDTH, "+H%d" % HEIGHT,
                          "-D", "-GA", "+A0.3", "+R3", "-J"], tmp)
            f = flip(os.path.join(tmp, name + ".p.exr"), os.path.join(tmp, name + ".t.exr"))
            rows.append({"family": family, "size": size, "trace_s": "%.3f" % tt, "povray_s": "%.3f" % pt,
                         "ratio": "%.2f" % (pt / tt), "trace_mib": "%.0f" % tm, "povray_mib": "%.0f" % pm,
                         "mean_flip": "%.4f" % f})
            print("%-10s %9d  trace %7.2f s %6.0f MiB   POV-Ray %7.2f s %6.0f MiB   %.2fx  FLIP %.4f"
                  % (family, size, tt, tm, pt, pm, pt / tt, f), flush=True)
    # (A --quick run writes beside the build, not over the published numbers.)
    docs = os.path.join(ROOT, "target") if quick else os.path.join(ROOT, "docs")
    suffix = "-quick" if quick else ""
    with open(os.path.join(docs, "speed%s.csv" % suffix), "w", newline="") as fh:
        wr = csv.DictWriter(fh, fieldnames=list(rows[0]))
        wr.writeheader()
        wr.writerows(rows)
    lines = ["| scene | size | trace (s) | POV-Ray (s) | POV-Ray / trace | trace peak (MiB) | POV-Ray peak (MiB) | mean FLIP |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    labels = {"spheres": "random spheres", "terrain": "mesh2 terrain (triangles)", "instances": "300 instances × 20k-triangle mesh2 (triangles)"}
    for r in rows:
        lines.append("| %s | %s | %s | %s | %s× | %s | %s | %s |" % (labels[r["family"]], "{:,}".format(r["size"]), r["trace_s"], r["povray_s"],
                                                                 r["ratio"], r["trace_mib"], r["povray_mib"], r["mean_flip"]))
    with open(os.path.join(docs, "speed%s.md" % suffix), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    svg_chart(rows, os.path.join(docs, "speed%s.svg" % suffix))
    print("\n".join(lines))


if __name__ == "__main__":
    main()

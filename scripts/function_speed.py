#!/usr/bin/env python3
"""Function-heavy scenes: trace against POV-Ray 3.7, side by side in one run.

Each scene spends its time in user functions: isosurfaces (functions.inc's internal
functions, noise, a pattern function), a parametric surface, function patterns in pigments
and normals, and a parse-time loop calling a function 200 000 times. Both renderers render at
the same size without anti-aliasing, on all cores; the table gives end-to-end wall time (parse
+ render + write), the ratio, and the mean FLIP between the two pictures.

Writes docs/function_speed.md and docs/function_speed.csv. Usage: scripts/function_speed.py
(env: WIDTH, HEIGHT; default 640x480). Needs povray and its include files.
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WIDTH = int(os.environ.get("WIDTH", 640))
HEIGHT = int(os.environ.get("HEIGHT", 480))
TRACE = os.path.join(ROOT, "target", "release", "trace")
INC = "/usr/share/povray-3.7/include"
HEADER = """#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> angle 45 }
light_source { <-5, 10, -8>, rgb 1 }
plane { y, -1 pigment { checker rgb 0.8, rgb 0.5 } }
"""

GENERATED = {
    # An isosurface of noise and internal functions: evaluations dominate the render.
    "iso_noise": HEADER + """
isosurface {
  function { f_sphere(x, y, z, 1.2) + f_noise3d(x * 3, y * 3, z * 3) * 0.6
             + f_torus(x, y, z, 1, 0.3) * 0.1 }
  contained_by { sphere { 0, 2 } }
  max_gradient 4
  pigment { rgb <0.8, 0.5, 0.3> } finish { phong 0.4 }
  translate y * 0.6
}
""",
    # A pattern function (granite) and a pigment function's channel shaping an isosurface.
    "iso_pattern": HEADER + """
#declare P = function { pigment { bozo scale 0.4 color_map { [0 rgb 0] [1 rgb 1] } } }
isosurface {
  function { f_sphere(x, y, z, 1.1) - f_granite(x * 0.5, y * 0.5, z * 0.5) * 0.4
             - P(x, y, z).gray * 0.2 }
  contained_by { box { -1.8, 1.8 } }
  max_gradient 3
  pigment { rgb <0.4, 0.7, 0.5> }
  translate y * 0.6
}
""",
    # Function patterns everywhere: each pixel evaluates several functions.
    "patterns": HEADER + """
#declare Rings = function { sin(sqrt(x * x + z * z) * 6) * 0.5 + 0.5 }
#declare Stone = function { pigment { granite color_map { [0 rgb <1, 0.3, 0>] [1 rgb <0, 0.4, 1>] } } }
plane { y, -0.99 pigment { function { Rings(x, y, z) * 0.7 + Stone(x, y, z).red * 0.3 } } }
sphere { <0, 0.6, 0>, 1.4
  pigment { function { f_agate(x, y, z) * Stone(x * 2, y * 2, z * 2).gray } color_map { [0 rgb <0.2, 0.1, 0.5>] [1 rgb <1, 0.9, 0.6>] } }
  normal { function { f_wrinkles(x * 2, y * 2, z * 2) } 0.8 }
}
""",
    # Parse time: a function called 200 000 times from a loop.
    "parse_calls": HEADER + """
#declare F = function(a, b) { f_noise3d(a, b, 0.5) * sin(a) + sqrt(a * a + b * b) / (1 + b * b) }
#declare S = 0;
#for (I, 0, 199999)
  #declare S = S + F(I / 7, I / 13);
#end
sphere { <0, 0.6, 0>, 1 pigment { rgb S / 200000 } }
""",
}
# Scenes of the repository (run from their folder).
FILES = {
    "isosurfaces.rt": os.path.join(ROOT, "examples", "isosurfaces.rt"),
    "parametric.rt": os.path.join(ROOT, "examples", "parametric.rt"),
    "function_patterns.rt": os.path.join(ROOT, "examples", "function_patterns.rt"),
}


def timed(cmd, cwd):
    start = time.monotonic()
    done = subprocess.run(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    elapsed = time.monotonic() - start
    if done.returncode != 0:
        sys.exit(f"{cmd[0]} failed on {cmd}: {done.stderr[-2000:]}")
    return elapsed


def flip(ref, test):
    out = subprocess.run([TRACE, "compare", ref, test], capture_output=True, text=True, check=True).stdout
    return float(next(l for l in out.splitlines() if l.startswith("mean FLIP")).split()[2])


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet", "--manifest-path", os.path.join(ROOT, "Cargo.toml")], check=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        scenes = {}
        for name, text in GENERATED.items():
            path = os.path.join(tmp, name + ".pov")
            with open(path, "w") as f:
                f.write(text)
            scenes[name] = path
        for name, path in FILES.items():
            copy = os.path.join(tmp, name)
            shutil.copy(path, copy)
            scenes[name] = copy
        for name, path in scenes.items():
            t_png, p_png = os.path.join(tmp, name + ".t.png"), os.path.join(tmp, name + ".p.png")
            t = timed([TRACE, path, "-o", t_png, "--width", str(WIDTH), "--height", str(HEIGHT),
                       "--aa", "off", "-q", "-L", INC], tmp)
            p = timed(["povray", "+I" + path, "+O" + p_png, f"+W{WIDTH}", f"+H{HEIGHT}", "-A", "-D",
                       "-GA", "+L" + INC], tmp)
            rows.append((name, t, p, p / t, flip(p_png, t_png)))
            print(f"{name}: trace {t:.2f} s, POV-Ray {p:.2f} s, {p / t:.2f}x", flush=True)
    with open(os.path.join(ROOT, "docs", "function_speed.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "trace_s", "povray_s", "speedup", "mean_flip"])
        for r in rows:
            w.writerow([r[0], f"{r[1]:.3f}", f"{r[2]:.3f}", f"{r[3]:.2f}", f"{r[4]:.6f}"])
    with open(os.path.join(ROOT, "docs", "function_speed.md"), "w") as f:
        f.write("# Function-heavy scenes: trace against POV-Ray 3.7\n\n")
        f.write(f"Made by `scripts/function_speed.py` ({WIDTH}×{HEIGHT}, no anti-aliasing, both renderers on all cores of\n")
        f.write("the same machine, one run side by side; wall time end to end). Raw: `docs/function_speed.csv`.\n\n")
        f.write("| scene | trace (s) | POV-Ray (s) | POV-Ray / trace | mean FLIP |\n|---|---:|---:|---:|---:|\n")
        for r in rows:
            f.write(f"| {r[0]} | {r[1]:.2f} | {r[2]:.2f} | {r[3]:.2f} | {r[4]:.6f} |\n")


if __name__ == "__main__":
    main()

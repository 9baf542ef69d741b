#!/usr/bin/env python3
"""Media rows of the speed table: trace against POV-Ray 3.7 on the media examples, in one run.

Renders each examples/media_*.rt with trace and with POV-Ray at the same size and settings
(anti-aliasing method 1, threshold 0.3, depth 3, no jitter; media with the scene's own
settings, POV-Ray's defaults), both on every core, and records end-to-end wall time (parse +
build + render + write of a half-float EXR), the ratio, and the mean FLIP between the two
pictures. Writes docs/media-speed.md. Usage: scripts/media_speed.py   (env: WIDTH, HEIGHT, RUNS)
"""
import glob
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WIDTH = int(os.environ.get("WIDTH", 640))
HEIGHT = int(os.environ.get("HEIGHT", 480))
RUNS = int(os.environ.get("RUNS", 3))
TRACE = os.path.join(ROOT, "target", "release", "trace")


def timed(cmd, cwd):
    """The least wall time of RUNS runs of `cmd`."""
    best = None
    for _ in range(RUNS):
        start = time.perf_counter()
        subprocess.run(cmd, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        t = time.perf_counter() - start
        best = t if best is None else min(best, t)
    return best


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    examples = os.path.join(ROOT, "examples")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for scene in sorted(glob.glob(os.path.join(examples, "media_*.rt"))):
            name = os.path.splitext(os.path.basename(scene))[0]
            pov_out = os.path.join(tmp, name + ".pov.exr")
            trace_out = os.path.join(tmp, name + ".trace.exr")
            pov = timed(["povray", "+I" + scene, "+O" + pov_out, "+FE", "+W%d" % WIDTH, "+H%d" % HEIGHT,
                         "-D", "-GA", "+A0.3", "+R3", "-J"], examples)
            tr = timed([TRACE, scene, "-o", trace_out, "--width", str(WIDTH), "--height", str(HEIGHT),
                        "--aa", "0.3", "--aa-depth", "3", "--aa-method", "1", "-q"], examples)
            out = subprocess.run([TRACE, "compare", pov_out, trace_out], check=True,
                                 capture_output=True, text=True).stdout
            flip = float(out.split()[2])
            rows.append((name, pov, tr, flip))
            print("%-20s POV-Ray %.2f s  trace %.2f s  %.2fx  FLIP %.4f" % (name, pov, tr, pov / tr, flip),
                  file=sys.stderr)
    lines = [
        "# Media: speed against POV-Ray 3.7",
        "",
        "Made by `scripts/media_speed.py` (do not edit by hand): each media example at %dx%d," % (WIDTH, HEIGHT),
        "anti-aliasing method 1 (threshold 0.3, depth 3, no jitter) in both, every core, end-to-end",
        "wall time (the least of %d runs), half-float EXR out. Mean FLIP is trace's picture against" % RUNS,
        "POV-Ray's.",
        "",
        "| scene | POV-Ray s | trace s | POV-Ray / trace | mean FLIP |",
        "|---|---:|---:|---:|---:|",
    ]
    for name, pov, tr, flip in rows:
        lines.append("| %s | %.2f | %.2f | %.2f | %.4f |" % (name, pov, tr, pov / tr, flip))
    with open(os.path.join(ROOT, "docs", "media-speed.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Edit-to-picture latency of `trace watch`: for each scene, a camera move, a light move and a
material edit are saved, and the time from the save to the first pixels of the new render (its
quick pass on the page) and to the finished picture is read off the server's event stream,
with what the server says the build took.

    python3 scripts/watch_latency.py [--trace target/release/trace] [--size 640x480]
                                     [--mesh] [--many] [--out docs/watch-latency.md]
                                     [SCENE.rt ...]

Without scenes it measures every example (examples/*.rt). `--mesh` adds a scene of a
1,000,000-triangle mesh2 read from an include file, `--many` one of 100,000 spheres each with
its own pigment and finish (both written into the scratch folder).
Each scene is copied with its folder into a scratch folder first: the examples are not
edited. The edits are textual: the camera's `location <…>` gains `+ <0.05, 0, 0>`, so does
the first `light_source`'s position, and the first `finish { … }` ends with `phong 0.31` (a
material edit the renderer cannot know changed nothing). A scene without a camera location, a light
position written as a vector or a finish skips that edit.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class Watch:
    """A running `trace watch` and the events it sent, each with the time it arrived."""

    def __init__(self, trace, scene, size):
        width, height = size
        self.proc = subprocess.Popen(
            [trace, "watch", os.path.basename(scene), "--width", str(width),
             "--height", str(height), "--quiet"],
            cwd=os.path.dirname(scene), stderr=subprocess.PIPE, text=True)
        first = self.proc.stderr.readline()
        match = re.search(r"http://127\.0\.0\.1:(\d+)/", first)
        if not match:
            raise RuntimeError(f"no address in {first!r}")
        self.port = int(match.group(1))
        threading.Thread(target=lambda: [None for _ in self.proc.stderr], daemon=True).start()
        self.events = []
        self.lock = threading.Condition()
        threading.Thread(target=self._listen, daemon=True).start()

    def _listen(self):
        stream = urllib.request.urlopen(f"http://127.0.0.1:{self.port}/events")
        for raw in stream:
            line = raw.decode()
            if line.startswith("data: "):
                with self.lock:
                    self.events.append((time.perf_counter(), json.loads(line[6:])))
                    self.lock.notify_all()

    def wait(self, test, since, timeout=600):
        """The time of the first event after index `since` for which test(status) holds."""
        end = time.perf_counter() + timeout
        with self.lock:
            while True:
                for at, status in self.events[since:]:
                    if test(status):
                        return at, status
                left = end - time.perf_counter()
                if left <= 0:
                    raise TimeoutError(str(self.events[-1][1] if self.events else "no event"))
                self.lock.wait(left)

    def count(self):
        with self.lock:
            return len(self.events)

    def stop(self):
        self.proc.kill()
        self.proc.wait()


def camera_move(text):
    edited, n = re.subn(r"(camera\s*\{[^}]*?location\s*)(<[^<>]*>)",
                        r"\1(\2 + <0.05, 0, 0>)", text, count=1)
    return edited if n else None


def light_move(text):
    edited, n = re.subn(r"(light_source\s*\{\s*)(<[^<>]*>)",
                        r"\1(\2 + <0.05, 0, 0>)", text, count=1)
    return edited if n else None


def material_edit(text):
    """`phong 0.31` added at the end of the first finish block (where it overrides any
    earlier phong, so the scene does change)."""
    start = re.search(r"finish\s*\{", text)
    if not start:
        return None
    depth = 1
    for i in range(start.end(), len(text)):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            return text[:i] + " phong 0.31 " + text[i:]
    return None


def save(path, text):
    """Writes `text` to `path` at once, as editors that save by renaming do (written in place,
    the watcher may first see the file truncated, and render an empty scene)."""
    temporary = path + ".saving"
    with open(temporary, "w") as f:
        f.write(text)
    os.replace(temporary, path)


def build_time(status):
    """What the server says building took (0 where only the camera was swapped)."""
    t = status["timings"]
    return t["build"] - t["parse"] if "build" in t else 0.0


def measure(watch, path, edit):
    """Saves the edited text; returns (first pixels, done, build) in seconds after the save
    (None where the edit broke the scene)."""
    text = open(path).read()
    edited = edit(text)
    if edited is None:
        return None
    since = watch.count()
    last = watch.events[-1][1]["id"] if watch.events else 0
    saved = time.perf_counter()
    save(path, edited)
    first, status = watch.wait(
        lambda s: s["id"] > last and (s["picture_id"] == s["id"] or s["state"] == "error"),
        since)
    if status["state"] != "error":
        done, status = watch.wait(lambda s: s["id"] > last and s["state"] in ("done", "error"),
                                  since)
    built = build_time(status)
    failed = status["state"] == "error"
    if failed:
        print(f"{os.path.basename(path)}: the edited scene fails: {status['errors'][0]['message']}",
              file=sys.stderr)
    # Back to the text as it was (and its render), so the next edit starts from it.
    since = watch.count()
    last = status["id"]
    save(path, text)
    watch.wait(lambda s: s["id"] > last and s["state"] in ("done", "error"), since)
    return None if failed else (first - saved, done - saved, built)


def mesh_scene(folder, triangles=1_000_000):
    """A scene of one mesh2 of `triangles` triangles (a rippled grid) in an include file."""
    n = int((triangles / 2) ** 0.5)
    with open(os.path.join(folder, "grid.inc"), "w") as f:
        f.write("#declare Grid = mesh2 {\n vertex_vectors { %d,\n" % ((n + 1) ** 2))
        for j in range(n + 1):
            f.write("".join("<%.4f,%.4f,%.4f>,\n" % (i / n - 0.5, 0.02 * ((i * 7 + j * 13) % 10) / 10, j / n - 0.5)
                            for i in range(n + 1)))
        f.write(" }\n face_indices { %d,\n" % (2 * n * n))
        for j in range(n):
            row = []
            for i in range(n):
                a = j * (n + 1) + i
                row.append("<%d,%d,%d>,<%d,%d,%d>," % (a, a + 1, a + n + 1, a + 1, a + n + 2, a + n + 1))
            f.write("".join(row) + "\n")
        f.write(" }\n}\n")
    path = os.path.join(folder, "mesh1m.rt")
    with open(path, "w") as f:
        f.write('#include "grid.inc"\n'
                "camera { location <0, 1, -1.2> look_at 0 }\n"
                "light_source { <2, 4, -3>, rgb 1 }\n"
                "object { Grid pigment { rgb <0.8, 0.7, 0.5> } finish { phong 0.5 } }\n")
    return path, 2 * n * n


def many_scene(folder, count=100_000):
    """A scene of `count` spheres on a grid, each with its own pigment and finish."""
    n = int(count ** 0.5)
    path = os.path.join(folder, "spheres100k.rt")
    with open(path, "w") as f:
        f.write("camera { location <0, 40, -60> look_at 0 }\n"
                "light_source { <30, 60, -40>, rgb 1 }\n"
                "plane { y, -1 pigment { rgb 0.5 } finish { diffuse 0.8 } }\n")
        for j in range(n):
            f.write("".join(
                "sphere { <%d, 0, %d>, 0.4 pigment { rgb <%.3f, %.3f, 0.5> } "
                "finish { phong %.2f } }\n" % (i - n // 2, j - n // 2, i / n, j / n, (i + j) % 7 / 7)
                for i in range(n)))
    return path, n * n


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scenes", nargs="*")
    ap.add_argument("--trace", default=os.path.join(ROOT, "target/release/trace"))
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--mesh", action="store_true")
    ap.add_argument("--many", action="store_true")
    ap.add_argument("--out")
    args = ap.parse_args()
    size = tuple(int(v) for v in args.size.split("x"))
    trace = os.path.abspath(args.trace)
    scenes = args.scenes or sorted(
        os.path.join(ROOT, "examples", f) for f in os.listdir(os.path.join(ROOT, "examples"))
        if f.endswith(".rt"))
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        jobs = []
        for scene in scenes:
            folder = os.path.join(scratch, os.path.basename(os.path.dirname(os.path.abspath(scene))))
            if not os.path.isdir(folder):
                shutil.copytree(os.path.dirname(os.path.abspath(scene)), folder)
            jobs.append((os.path.basename(scene), os.path.join(folder, os.path.basename(scene))))
        if args.mesh:
            folder = os.path.join(scratch, "mesh")
            os.makedirs(folder)
            path, n = mesh_scene(folder)
            jobs.append((f"mesh2 of {n:,} triangles", path))
        if args.many:
            folder = os.path.join(scratch, "many")
            os.makedirs(folder)
            path, n = many_scene(folder)
            jobs.append((f"{n:,} spheres", path))
        for name, path in jobs:
            watch = Watch(trace, path, size)
            try:
                _, status = watch.wait(lambda s: s["state"] in ("done", "error"), 0)
                if status["state"] == "error":
                    print(f"{name}: {status['errors'][0]['message']}", file=sys.stderr)
                    continue
                render = max(status["timings"].values())
                row = [name, render, build_time(status)]
                for edit in (camera_move, light_move, material_edit):
                    got = measure(watch, path, edit)
                    row += [None, None, None] if got is None else list(got)
                rows.append(row)
                cells = ["-" if v is None else (f"{1000 * v:.0f}" if isinstance(v, float) else v)
                         for v in row]
                print(" | ".join(str(c) for c in cells), flush=True)
            finally:
                watch.stop()
    ms = lambda v: "–" if v is None else f"{1000 * v:.0f}"
    lines = [
        f"| scene ({size[0]}×{size[1]}) | whole render | first build | "
        "camera: first pixels | camera: done | light: first pixels | light: done | light: build | "
        "material: first pixels | material: done | material: build |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for name, render, build, c1, c2, _, l1, l2, lb, m1, m2, mb in rows:
        cells = [render, build, c1, c2, l1, l2, lb, m1, m2, mb]
        lines.append(f"| {name} | " + " | ".join(ms(v) for v in cells) + " |")
    table = "\n".join(lines)
    print(table)
    if args.out:
        with open(args.out, "w") as f:
            f.write("# `trace watch`: from a save to the picture\n\n"
                    f"`python3 scripts/watch_latency.py {' '.join(sys.argv[1:])}`; milliseconds "
                    "from the save (the script's write) to the first pixels of the new render on "
                    "the event stream (its quick pass), and to the finished picture (with "
                    "anti-aliasing); \"build\" is what the server says building the render-ready "
                    "scene took after the edit (a camera move builds nothing), \"first build\" "
                    "the first load's. \"whole render\" is the first render's time from start to "
                    "finish as the server reports it.\n\n" + table + "\n")


if __name__ == "__main__":
    main()

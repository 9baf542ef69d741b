#!/usr/bin/env python3
"""Mutation fuzzer for trace's scene loader and renderer (runs on stable Rust: no cargo-fuzz).

Each input is a seed scene (examples/, tests/scenes/, tests/fuzz/seeds/) changed by a few
random mutations: bytes flipped, deleted or repeated, lines spliced from another seed, and
tokens inserted from a dictionary of hostile values (1e400, huge counts, wrong argument
counts, includes of files outside the scene's folder, bytes that are not UTF-8, ...). Each is
rendered by the release binary at 24x18, as a user would run it, and judged:

  exit 0        fine if the image has no NaN or infinite pixel (pixels that overflowed on
                extreme inputs are written black with a warning: counted apart, as "warned");
  exit 1 or 2   fine if stderr starts with an error message and holds no panic;
  anything else (a panic's 101, an abort's 134, a signal, a timeout) is a finding, except a
                timeout of a scene that renders at one pixel in time: a huge render (such as
                area_light 1000, 1000), counted apart as "slow render";
  and any run whose output shows the marker of the file outside the sandbox is a finding.

Findings are saved in tests/fuzz/crashers/ (replayed by `cargo test`, cli/tests/integration/
fuzz_replay.rs); a summary is printed at the end.

    python3 scripts/fuzz.py --minutes 60 [--seed 1] [--jobs 2] [--binary PATH]
"""

import argparse
import collections
import concurrent.futures
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BINARY = os.path.join(ROOT, "target", "release", "trace")
CRASHERS = os.path.join(ROOT, "tests", "fuzz", "crashers")
SEEDS = [
    os.path.join(ROOT, "examples"),
    os.path.join(ROOT, "tests", "scenes", "ok"),
    os.path.join(ROOT, "tests", "scenes", "err"),
    os.path.join(ROOT, "tests", "fuzz", "seeds"),
]
MARKER = b"FUZZ_SECRET_MARKER"
TIMEOUT_S = 60
# A smaller evaluation budget than the default (about 50 s) keeps endless loops quick; the
# budget itself is what stops them either way.
OPTIONS = ["--width", "24", "--height", "18", "--quiet", "--max-memory", "2G",
           "--max-steps", "2000000"]

TOKENS = [
    b"1e400", b"-1e400", b"1e308*10", b"exp(1000)", b"val(\"nan\")", b"0/0", b"-0", b"0",
    b"-1", b"1e-300", b"1e300", b"65536", b"4294967296", b"100000000", b"-1e6", b"9e18",
    b"<0,0,0>", b"<1e300,1e300,1e300>", b"<-1,-1,-1>", b"<0,0>", b"<1,2,3,4,5,6>",
    b"str(1)", b"str(1, 65536, 0)", b"str(1, -1e6, 0)", b"chr()", b"chr(1114112)",
    b"substr(\"abc\", 0, -1)", b"strupr()", b"strlwr(1, 2)", b"concat()", b"vstr(9, x, \"\", 0, 0)",
    b"#include \"/etc/passwd\"\n", b"#include \"../secret.inc\"\n", b"#include \"/proc/self/environ\"\n",
    b"#include \"link.inc\"\n", b"#include \"self.rt\"\n",
    b"image_map { png \"../secret.png\" }", b"mesh_file { \"../secret.obj\" }",
    b"#while (1) #end\n", b"#for (i, 0, 1e9) #end\n", b"#macro M(a) M(a) M(a) #end M(1)\n",
    b"#declare S = concat(S, S);\n", b"#declare A = array[16777216];\n", b"array[1e9]",
    b"scale 0", b"scale 1e200", b"scale -1e-300", b"translate 1e308", b"rotate <1e300, 0, 0>",
    b"matrix <0,0,0,0,0,0,0,0,0,0,0,0>", b"brilliance -1", b"fog { distance -1 rgb 1 }",
    b"fog { distance 0 rgb 1 }", b"fog_type 2 fog_alt 0", b"area_light x, z, 1000, 1000",
    b"adaptive 100", b"max_trace_level 1000000", b"ior 0", b"ior -1", b"fade_power -100",
    b"angle 0", b"angle 180", b"angle 1e9", b"up 0", b"right 0", b"direction 0",
    b"sky <0,0,0>", b"look_at <0,0,-5>", b"radius 0", b"falloff -1", b"tightness 1e9",
    b"\xe9", b"\xff\xfe", b"\x00", b"\xc3", b"/*", b"*/", b"\"", b"{", b"}", b"(", b")", b"<",
    b">", b"#end", b"#else", b"#if (1)", b"#switch (1)", b"#case (1)", b"#break", b"#local",
    b"#declare", b"#undef", b"#version 3.7;", b"#version 1e9;", b"#default { finish { ambient -1 } }",
    b"sphere { 0, 1 }", b"plane { y, -1e308 }", b"box { -1e300, 1e300 }", b"torus { 1e300, 1 }",
    b"torus { 0, 0 }", b"cone { 0, 0, 0, 0 }", b"cylinder { 0, 0, 1 }", b"disc { 0, 0, 0 }",
    b"triangle { 0, 0, 0 }", b"smooth_triangle { 0, 0, 0, 0, 0, 0 }",
    b"mesh2 { vertex_vectors { 1000000000, <0,0,0> } }", b"face_indices { 4294967295, <0,1,2> }",
    b"object { X }", b"texture { T }", b"pigment { rgbft <1e300, -1, 0, 2, 2> }",
    b"checker rgb 1e300, rgb -1e300", b"gradient 0", b"color_map { [1e300 rgb 1] [-1 rgb 0] }",
    b"interior { ior 1e300 }", b"finish { reflection 1e300 phong -1 phong_size 0 }",
    b"finish { specular 1 roughness 0 }", b"finish { diffuse -1e300 }",
    b"global_settings { assumed_gamma 0 }", b"global_settings { assumed_gamma -1 }",
    b"global_settings { adc_bailout -1 max_trace_level 0 }", b"background { rgb 1e39 }",
]


def seed_files():
    files = []
    for folder in SEEDS:
        for dirpath, _, names in os.walk(folder):
            for n in sorted(names):
                if n.endswith((".rt", ".pov", ".inc")):
                    files.append(os.path.join(dirpath, n))
    return sorted(files)


def mutate(rng, data, seeds):
    data = bytearray(data)
    for _ in range(rng.choice([1, 1, 2, 3])):
        choice = rng.random()
        pos = rng.randint(0, len(data)) if data else 0
        if choice < 0.35:
            token = rng.choice(TOKENS)
            data[pos:pos] = b" " + token + b" "
        elif choice < 0.5 and data:
            # Replace a number by a hostile one.
            numbers = [m.span() for m in re.finditer(rb"-?\d+(\.\d+)?([eE][-+]?\d+)?", bytes(data))]
            if numbers:
                a, b = rng.choice(numbers)
                data[a:b] = rng.choice(TOKENS[:20])
        elif choice < 0.6 and data:
            data[pos % len(data)] = rng.randrange(256)
        elif choice < 0.7 and data:
            end = min(len(data), pos + rng.randint(1, 40))
            del data[pos:end]
        elif choice < 0.8 and data:
            end = min(len(data), pos + rng.randint(1, 200))
            data[pos:pos] = data[pos:end] * rng.randint(1, 20)
        else:
            other = rng.choice(seeds).splitlines(keepends=True)
            if other:
                k = rng.randrange(len(other))
                data[pos:pos] = b"".join(other[k:k + rng.randint(1, 10)])
    return bytes(data)


def workspace():
    """A folder holding the scene's folder (with a link out) and a secret outside it."""
    top = tempfile.mkdtemp(prefix="trace-fuzz-")
    scene_dir = os.path.join(top, "scene")
    os.makedirs(scene_dir)
    for name in ["secret.inc", "secret.png", "secret.obj"]:
        with open(os.path.join(top, name), "wb") as f:
            f.write(MARKER + b" private line\n")
    os.symlink(os.path.join(top, "secret.inc"), os.path.join(scene_dir, "link.inc"))
    for folder in [os.path.join(ROOT, "examples"), os.path.join(ROOT, "tests", "scenes", "err")]:
        for dirpath, _, names in os.walk(folder):
            for n in names:
                if not n.endswith((".rt", ".pov")):
                    src = os.path.join(dirpath, n)
                    dst = os.path.join(scene_dir, os.path.relpath(src, folder))
                    os.makedirs(os.path.dirname(dst), exist_ok=True)
                    if not os.path.exists(dst):
                        shutil.copy(src, dst)
    return top, scene_dir


def non_finite_pixels(image):
    out = subprocess.run([BINARY, "compare", image, image], capture_output=True, timeout=60)
    m = re.search(rb"NaN/inf\s+(\d+)", out.stdout)
    return int(m.group(1)) if m else -1


def judge(scene_dir, index, data):
    scene = os.path.join(scene_dir, f"in{index}.rt")
    image = os.path.join(scene_dir, f"out{index}.exr")
    with open(scene, "wb") as f:
        f.write(data)
    start = time.time()
    try:
        run = subprocess.run([BINARY, scene, "-o", image] + OPTIONS, capture_output=True,
                             timeout=TIMEOUT_S, cwd=scene_dir)
        code, err = run.returncode, run.stderr
    except subprocess.TimeoutExpired as e:
        code, err = "timeout", e.stderr or b""
        # A scene may ask for a huge render (area_light 1000, 1000: a million shadow rays per
        # point), which is work, not a hang. If it loads and renders at one pixel in time, the
        # time goes to the render and is counted apart; if not, loading hangs: a finding.
        try:
            small = [a if a not in ("24", "18") else "1" for a in OPTIONS]
            subprocess.run([BINARY, scene, "-o", image] + small + ["--aa", "off"],
                           capture_output=True, timeout=TIMEOUT_S, cwd=scene_dir)
            code = "slow render"
        except subprocess.TimeoutExpired:
            pass
    verdict = None
    if MARKER in err:
        verdict = "leak"
    elif code == 0:
        if os.path.exists(image) and non_finite_pixels(image) != 0:
            verdict = "non-finite pixels"
        elif b"overflowed to NaN" in err:
            code = "0 (warned)"
    elif code in (1, 2):
        if b"panicked" in err or not err.startswith(b"error"):
            verdict = "bad message"
    elif code == "slow render":
        pass  # work asked for, not a hang (counted apart, as the summary says)
    else:
        verdict = f"exit {code}"
    for path in (scene, image):
        if os.path.exists(path):
            os.remove(path)
    return code, verdict, time.time() - start, err


def main():
    global BINARY
    ap = argparse.ArgumentParser()
    ap.add_argument("--minutes", type=float, default=5)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--binary", default=BINARY, help="the trace binary (default: the release build)")
    args = ap.parse_args()
    BINARY = os.path.abspath(args.binary)
    if not os.path.exists(BINARY):
        subprocess.run(["cargo", "build", "--release"], cwd=ROOT, check=True)
    # The seeds' contents, read once: a run does not depend on the tree changing under it.
    seeds = [open(path, "rb").read() for path in seed_files()]
    rng = random.Random(args.seed)
    top, scene_dir = workspace()
    os.makedirs(CRASHERS, exist_ok=True)
    codes = collections.Counter()
    findings = []
    deadline = time.time() + args.minutes * 60
    count = 0
    slowest = 0.0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        while time.time() < deadline:
            batch = []
            for _ in range(args.jobs * 4):
                data = mutate(rng, rng.choice(seeds), seeds)
                batch.append((count, data))
                count += 1
            results = pool.map(lambda item: (item,) + judge(scene_dir, *item), batch)
            for (index, data), code, verdict, seconds, err in results:
                codes[code] += 1
                slowest = max(slowest, seconds)
                if verdict:
                    name = f"s{args.seed}-{index}.rt"
                    with open(os.path.join(CRASHERS, name), "wb") as f:
                        f.write(data)
                    findings.append((name, verdict, err[-400:].decode("utf-8", "replace")))
                    print(f"FINDING {name}: {verdict}\n{findings[-1][2]}", flush=True)
    shutil.rmtree(top, ignore_errors=True)
    print(f"inputs {count}, seed {args.seed}, {args.minutes} min, jobs {args.jobs}")
    print("exit codes: " + ", ".join(f"{k}: {v}" for k, v in sorted(codes.items(), key=str)))
    print(f"slowest run {slowest:.1f} s")
    print(f"findings {len(findings)}")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Counts which declarations of POV-Ray's standard material include files trace can use.

For every `#declare NAME =` of each include file below, scenes include the file and use NAME
where a value of its kind stands (a texture, pigment, normal, finish, interior, material, sky
sphere, map, object, number or string), until one renders: NAME is usable, or trace named what
it cannot read in it. Prints a table per file and the reasons, most frequent first.

Usage: scripts/includes.py   (env: TRACE, the binary; INCLUDE, POV-Ray's include folder)
"""
import collections, os, re, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TRACE = os.environ.get("TRACE", os.path.join(ROOT, "target/release/trace"))
INCLUDE = os.environ.get("INCLUDE", "/usr/share/povray-3.7/include")
FILES = ["textures.inc", "stones1.inc", "stones2.inc", "woods.inc", "woodmaps.inc",
         "golds.inc", "metals.inc", "glass.inc", "skies.inc", "finish.inc", "colors.inc"]


# Where a declared value of each kind can stand (N is its name).
USES = [
    "sphere { 0, 1 texture { N } }",
    "sphere { 0, 1 pigment { N } }",
    "sphere { 0, 1 normal { N } }",
    "sphere { 0, 1 finish { N } }",
    "sphere { 0, 1 interior { N } }",
    "sphere { 0, 1 material { N } }",
    "sky_sphere { N }",
    "sphere { 0, 1 pigment { gradient y color_map { N } } }",
    "sphere { 0, 1 pigment { gradient y pigment_map { N } } }",
    "sphere { 0, 1 texture { gradient y texture_map { N } } }",
    "sphere { 0, 1 normal { gradient y normal_map { N } } }",
    "object { N }",
    "#declare Probe = N + 0;",
    '#declare Probe = concat(N, "");',
]


def declarations(path):
    names = []
    with open(path, encoding="latin-1") as f:
        for line in f:
            m = re.match(r"\s*#declare\s+([A-Za-z_][A-Za-z0-9_]*)\s*=", line)
            if m and m.group(1) not in names:
                names.append(m.group(1))
    return names


def main():
    reasons = collections.Counter()
    total = usable = 0
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for inc in FILES:
            names = declarations(os.path.join(INCLUDE, inc))
            ok = 0
            for name in names:
                reason = None
                for use in USES:
                    scene = os.path.join(tmp, "probe.pov")
                    with open(scene, "w") as f:
                        f.write(f'#version 3.7;\n#include "colors.inc"\n#include "{inc}"\n'
                                + use.replace("N", name) + "\n")
                    r = subprocess.run([TRACE, scene, "-o", os.path.join(tmp, "p.png"), "--width",
                                        "4", "--height", "4", "-q", "-L", INCLUDE],
                                       capture_output=True, text=True)
                    if r.returncode == 0:
                        reason = None
                        break
                    first = r.stderr.strip().splitlines()[0] if r.stderr.strip() else "?"
                    if "cannot be used" in first or reason is None and "expected" not in first:
                        reason = re.sub(r"`[A-Za-z0-9_]+` cannot be used: ", "", first)
                        if "cannot be used" in first:
                            break
                if r.returncode == 0:
                    ok += 1
                else:
                    reasons[reason or "no use found"] += 1
            rows.append((inc, len(names), ok))
            total += len(names)
            usable += ok
    print("| include file | declarations | usable |\n|---|---:|---:|")
    for inc, n, ok in rows:
        print(f"| {inc} | {n} | {ok} |")
    print(f"| all | {total} | {usable} |\n")
    for reason, n in reasons.most_common():
        print(f"{n:4d}  {reason}")


if __name__ == "__main__":
    sys.exit(main())

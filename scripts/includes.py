#!/usr/bin/env python3
"""Counts which declarations of POV-Ray's standard material include files trace can use.

For every `#declare NAME =` at the top of each include file below, a scene includes the file
and uses NAME (`#declare Probe = NAME;`); trace either loads it or names what it cannot read.
Prints a table per file and the reasons, most frequent first.

Usage: scripts/includes.py   (env: TRACE, the binary; INCLUDE, POV-Ray's include folder)
"""
import collections, os, re, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TRACE = os.environ.get("TRACE", os.path.join(ROOT, "target/release/trace"))
INCLUDE = os.environ.get("INCLUDE", "/usr/share/povray-3.7/include")
FILES = ["textures.inc", "stones1.inc", "stones2.inc", "woods.inc", "woodmaps.inc",
         "golds.inc", "metals.inc", "glass.inc", "skies.inc", "finish.inc", "colors.inc"]


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
                scene = os.path.join(tmp, "probe.pov")
                with open(scene, "w") as f:
                    f.write(f'#version 3.7;\n#include "colors.inc"\n#include "{inc}"\n#declare Probe = {name};\n')
                r = subprocess.run([TRACE, scene, "-o", os.path.join(tmp, "p.png"), "--width", "4",
                                    "--height", "4", "-q", "-L", INCLUDE],
                                   capture_output=True, text=True)
                if r.returncode == 0:
                    ok += 1
                else:
                    first = r.stderr.strip().splitlines()[0] if r.stderr.strip() else "?"
                    first = re.sub(r"`[A-Za-z0-9_]+` cannot be used: ", "", first)
                    reasons[first] += 1
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

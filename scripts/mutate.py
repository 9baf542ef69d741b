#!/usr/bin/env python3
"""Differential test of the language against POV-Ray: mutate valid scenes, render each mutant
with both renderers, and report what POV-Ray accepts that trace refuses (or renders otherwise).

Usage: python3 scripts/mutate.py [--per-scene N] [--seed S] [--out docs/mutations.md]
       [SCENE ...]   (default: every examples/*.rt)

Mutations (each applied once per mutant, at a place drawn at random outside strings and
comments):
  drop_comma    a comma removed
  macro_wrap    a number N becomes M__(N), `#macro M__(A) A #end` added at the top
  array_wrap    a number N becomes A__[0], `#declare A__ = array[1] {N};` added at the top
  if_wrap       a number N becomes `#if (1) N #else 0 #end`
  directive_in  `#declare Z__ = 1;` put between two tokens
  local_value   a number N becomes V__ with `#local V__ = N;` put just before the statement's
                first token

Both renderers run at 32x24 without anti-aliasing; a mutant both accept is compared by mean
FLIP (`trace compare`), 0.02 or more counting as a different picture. Needs `povray` and a
release build of trace (TRACE=path, default target/release/trace).
"""
import argparse
import os
import random
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TRACE = os.environ.get("TRACE", str(ROOT / "target/release/trace"))
INCLUDE = "/usr/share/povray-3.7/include"


def code_spans(text):
    """Byte ranges of text outside strings and comments."""
    spans, i, start, n = [], 0, 0, len(text)
    while i < n:
        if text.startswith("//", i):
            spans.append((start, i))
            j = text.find("\n", i)
            i = n if j < 0 else j
            start = i
        elif text.startswith("/*", i):
            spans.append((start, i))
            depth, i = 1, i + 2
            while i < n and depth:
                if text.startswith("/*", i):
                    depth, i = depth + 1, i + 2
                elif text.startswith("*/", i):
                    depth, i = depth - 1, i + 2
                else:
                    i += 1
            start = i
        elif text[i] == '"':
            spans.append((start, i))
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            i = j + 1
            start = i
        else:
            i += 1
    spans.append((start, n))
    return [(a, b) for a, b in spans if b > a]


def in_code(spans, at):
    return any(a <= at < b for a, b in spans)


NUMBER = re.compile(r"(?<![\w.])(\d+\.?\d*|\.\d+)(?![\w.])")


def candidates(text, pattern):
    spans = code_spans(text)
    # (Not inside a directive's line: `#version 3.7;`, `#include`, a macro's parameter list.)
    return [m for m in pattern.finditer(text) if in_code(spans, m.start())
            and not text[text.rfind("\n", 0, m.start()) + 1:m.start()].lstrip().startswith("#")]


def mutate(text, kind, rng):
    if kind == "drop_comma":
        ms = candidates(text, re.compile(","))
        if not ms:
            return None
        m = rng.choice(ms)
        return text[:m.start()] + " " + text[m.end():]
    if kind in ("macro_wrap", "array_wrap", "if_wrap", "local_value"):
        ms = candidates(text, NUMBER)
        if not ms:
            return None
        m = rng.choice(ms)
        n = m.group(0)
        if kind == "macro_wrap":
            return "#macro M__(A) A #end\n" + text[:m.start()] + f"M__({n})" + text[m.end():]
        if kind == "array_wrap":
            return f"#declare A__ = array[1] {{{n}}};\n" + text[:m.start()] + "A__[0]" + text[m.end():]
        if kind == "if_wrap":
            return text[:m.start()] + f"#if (1) {n} #else 0 #end" + text[m.end():]
        # local_value: before the line holding the number.
        line = text.rfind("\n", 0, m.start()) + 1
        return text[:line] + f"#local V__ = {n};\n" + text[line:m.start()] + "V__" + text[m.end():]
    if kind == "directive_in":
        ms = candidates(text, re.compile(r"(?<=[\w)}\]>,])\s+(?=[\w({<\[])"))
        if not ms:
            return None
        m = rng.choice(ms)
        return text[:m.start()] + " #declare Z__ = 1; " + text[m.end():]
    raise ValueError(kind)


KINDS = ["drop_comma", "macro_wrap", "array_wrap", "if_wrap", "directive_in", "local_value"]


def run(cmd, cwd):
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=60,
                           errors="replace")
        return p.returncode, (p.stderr or p.stdout).strip().splitlines()
    except subprocess.TimeoutExpired:
        return -1, ["timeout"]


def first_error(lines):
    for line in lines:
        if "error" in line.lower() or "Parse Error" in line:
            return line.strip()[:140]
    return (lines[-1].strip()[:140]) if lines else ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scenes", nargs="*")
    ap.add_argument("--per-scene", type=int, default=2)
    ap.add_argument("--seed", type=int, default=39)
    ap.add_argument("--out", default=str(ROOT / "docs/mutations.md"))
    args = ap.parse_args()
    scenes = [Path(s) for s in args.scenes] or sorted((ROOT / "examples").glob("*.rt"))
    # (Scenes using trace's own `mesh_file` are not POV-Ray's language.)
    scenes = [s for s in scenes if "mesh_file" not in s.read_text(encoding="latin-1")]
    rng = random.Random(args.seed)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for scene in scenes:
            text = scene.read_text(encoding="latin-1")
            for kind in KINDS:
                for k in range(args.per_scene):
                    mutant = mutate(text, kind, rng)
                    if mutant is None:
                        continue
                    name = f"{scene.stem}-{kind}-{k}"
                    # (Beside the original, so its includes and images are found.)
                    path = scene.parent / f".mutant-{name}.pov"
                    path.write_text(mutant, encoding="latin-1")
                    try:
                        pov_png, trace_png = tmp / f"{name}-p.png", tmp / f"{name}-t.png"
                        pc, pout = run(["povray", f"+I{path.name}", f"+O{pov_png}", "+W32", "+H24",
                                        "-A", "-D", "-GA", "+FN", f"+L{INCLUDE}"], scene.parent)
                        tc, tout = run([TRACE, path.name, "-o", str(trace_png), "+W32", "+H24",
                                        "-A", "-L", INCLUDE], scene.parent)
                    finally:
                        path.unlink()
                    flip = ""
                    if pc == 0 and tc == 0:
                        c, out = run([TRACE, "compare", str(pov_png), str(trace_png)], tmp)
                        m = re.search(r"FLIP[^0-9]*([0-9.]+)", " ".join(out))
                        flip = m.group(1) if m else "?"
                    rows.append((name, pc == 0, tc == 0, flip,
                                 "" if pc == 0 else first_error(pout),
                                 "" if tc == 0 else first_error(tout)))
                    print(rows[-1], file=sys.stderr)
    both = [r for r in rows if r[1] and r[2]]
    differ = [r for r in both if r[3] in ("?",) or (r[3] and float(r[3]) >= 0.02)]
    trace_refuses = [r for r in rows if r[1] and not r[2]]
    trace_accepts = [r for r in rows if not r[1] and r[2]]
    lines = [
        "# Mutations: trace against POV-Ray 3.7",
        "",
        f"`python3 scripts/mutate.py --per-scene {args.per_scene} --seed {args.seed}` on "
        f"{len(scenes)} scenes: {len(rows)} mutants ({', '.join(KINDS)}).",
        "",
        "| outcome | mutants |",
        "|---|---:|",
        f"| both accept, same picture (FLIP < 0.02) | {len(both) - len(differ)} |",
        f"| both accept, different picture | {len(differ)} |",
        f"| both refuse | {sum(1 for r in rows if not r[1] and not r[2])} |",
        f"| POV-Ray accepts, trace refuses | {len(trace_refuses)} |",
        f"| POV-Ray refuses, trace accepts | {len(trace_accepts)} |",
        "",
    ]
    for title, rs in [("POV-Ray accepts, trace refuses", trace_refuses),
                      ("Both accept, different picture", differ),
                      ("POV-Ray refuses, trace accepts", trace_accepts)]:
        if rs:
            lines += [f"## {title}", "", "| mutant | FLIP | POV-Ray | trace |", "|---|---|---|---|"]
            lines += [f"| {r[0]} | {r[3]} | {r[4].replace('|', '/')} | {r[5].replace('|', '/')} |" for r in rs]
            lines.append("")
    Path(args.out).write_text("\n".join(lines))
    print("\n".join(lines[:13]))


if __name__ == "__main__":
    main()

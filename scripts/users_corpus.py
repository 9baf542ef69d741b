#!/usr/bin/env python3
"""Runs POV-Ray 3.7 and trace over a corpus of real users' scenes (not POV-Ray's samples) and
compares the pictures where both render.

The corpus: 250 scenes from 115 public GitHub repositories (course work, hobby scenes,
scientific figures, exports from modellers), listed with their repository, path and commit in
docs/users-corpus-manifest.tsv; the files themselves are their authors' and are not part of
this repository. Lay them out as <DIR>/<owner>+<repo>/<path> (the manifest's rows) and run

    scripts/users_corpus.py [--dir DIR] [--out docs/users-corpus.csv] [--only TEXT[,TEXT…]]

(DIR defaults to $USERS_CORPUS or /work/users-corpus). With `--only`, only the scenes whose
name contains one of the texts are run (DIR then needs only their repositories and manifest
rows), and their rows replace the old ones in the existing CSV. Each scene is rendered from a copy of
its repository's folder at 320x240 without anti-aliasing, by POV-Ray (`-A -J +FE`, 120 s at
most) and by trace (`--aa off`, 60 s), both with POV-Ray's standard include folder; an
animation whose INI lies beside it at its first frame. Writes one CSV row per scene and
docs/users-corpus.md: how many POV-Ray renders, how many of those use only what the mission
covers (no CSG or photons, found by reading the scene and its own include
files), how many of those trace renders and how many match (mean FLIP <= 0.01), and what stops
the rest.
"""
import collections, csv, os, re, shutil, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus import animation, compare  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
INCLUDE = "/usr/share/povray-3.7/include"
OUTSIDE = {
    "CSG": re.compile(r"\b(difference|intersection|merge|clipped_by)\s*\{"),
    "photons": re.compile(r"\bphotons\s*\{"),
}
COMMENTS = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
INCLUDES = re.compile(r'#\s*include\s+"([^"]+)"')


def uses(scene, repo_dir):
    """What outside the mission `scene` uses: the constructs found in its text and in the
    include files of its own repository it names (followed one level deep and onward)."""
    seen, found, todo = set(), set(), [scene]
    while todo:
        path = todo.pop()
        if path in seen or not os.path.isfile(path):
            continue
        seen.add(path)
        text = COMMENTS.sub("", open(path, "rb").read().decode("latin-1"))
        found |= {name for name, pattern in OUTSIDE.items() if pattern.search(text)}
        for inc in INCLUDES.findall(text):
            for base in (os.path.dirname(path), os.path.dirname(scene), repo_dir):
                candidate = os.path.normpath(os.path.join(base, inc))
                if os.path.isfile(candidate):
                    todo.append(candidate)
                    break
    return sorted(found)


def first_error(stderr, marker):
    for line in stderr.splitlines():
        if marker in line:
            return line.strip()
    return ""


def main():
    args = sys.argv[1:]
    corpus = args[args.index("--dir") + 1] if "--dir" in args else os.environ.get("USERS_CORPUS", "/work/users-corpus")
    out = args[args.index("--out") + 1] if "--out" in args else os.path.join(ROOT, "docs/users-corpus.csv")
    subprocess.run(["cargo", "build", "--release", "--quiet", "--manifest-path", os.path.join(ROOT, "Cargo.toml")], check=True)
    trace = os.environ.get("TRACE", os.path.join(ROOT, "target/release/trace"))
    manifest = [line.rstrip("\n").split("\t") for line in open(os.path.join(corpus, "MANIFEST.tsv"))]
    scenes = [(repo, path) for repo, path, _, kind, _ in manifest if kind == "scene"]
    only = args[args.index("--only") + 1].split(",") if "--only" in args else None
    if only:
        scenes = [(repo, path) for repo, path in scenes if any(t in f"{repo}/{path}" for t in only)]
    rows = []
    for repo, path in scenes:
        work = tempfile.mkdtemp()
        repo_dir = os.path.join(work, repo.replace("/", "+"))
        shutil.copytree(os.path.join(corpus, repo.replace("/", "+")), repo_dir)
        folder, name = os.path.split(os.path.join(repo_dir, path))
        switches, suffix = animation(os.path.join(folder, os.path.splitext(name)[0] + ".ini"))
        row = {"scene": f"{repo}/{path}", "outside": "+".join(uses(os.path.join(folder, name), repo_dir)),
               "povray_exit": "", "povray_message": "", "povray_s": "", "trace_exit": "", "trace_message": "",
               "trace_s": "", "flip": "", "rmse": ""}
        t0 = time.time()
        try:
            p = subprocess.run(["povray", "+I" + name, "+Op.exr", "+FE", "+W320", "+H240", "-D", "-GA", "-A", "-J",
                                "+L" + INCLUDE] + switches, cwd=folder, capture_output=True, timeout=120)
            err = p.stderr.decode("latin-1")
            # (POV-Ray exits 0 after some parse errors; a picture is the test.)
            ok = p.returncode == 0 and os.path.exists(os.path.join(folder, f"p{suffix}.exr"))
            row["povray_exit"] = 0 if ok else (p.returncode or 1)
            row["povray_message"] = "" if ok else first_error(err, "error")[:200]
        except subprocess.TimeoutExpired:
            row["povray_exit"], row["povray_message"] = -1, "timeout"
        row["povray_s"] = f"{time.time() - t0:.2f}"
        t0 = time.time()
        try:
            p = subprocess.run([trace, name, "-o", "t.exr", "--width", "320", "--height", "240", "--aa", "off", "-q",
                                "-L", INCLUDE] + switches, cwd=folder, capture_output=True, timeout=60)
            err = p.stderr.decode("utf-8", "replace")
            row["trace_exit"], row["trace_message"] = p.returncode, first_error(err, "error")[:200]
        except subprocess.TimeoutExpired:
            row["trace_exit"], row["trace_message"] = -1, "timeout"
        row["trace_s"] = f"{time.time() - t0:.2f}"
        if row["povray_exit"] == 0 and row["trace_exit"] == 0:
            found = compare(trace, folder, f"p{suffix}.exr", f"t{suffix}.exr")
            row["flip"], row["rmse"] = found.get("flip", ""), found.get("rmse", "")
        rows.append(row)
        print(f"{row['scene'][:70]:70} pov={row['povray_exit']} trace={row['trace_exit']} flip={row['flip']} {row['outside']} {row['trace_message'][:60]}", flush=True)
        shutil.rmtree(work)
    if only:
        # (The rows re-run replace the old ones, in the old order.)
        fresh = {r["scene"]: r for r in rows}
        rows = [fresh.get(r["scene"], r) for r in csv.DictReader(open(out))]
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    note = ""
    if only:
        plural = "s" if len(fresh) != 1 else ""
        note = (f"Only the {len(fresh)} scene{plural} named by `--only` were re-run at this commit; the other rows "
                "come from the last full run.")
    write_report(out[:-4] + ".md", rows, note)


def write_report(path, rows, note=""):
    ok = lambda v: str(v) == "0"
    pov = [r for r in rows if ok(r["povray_exit"])]
    inside = [r for r in pov if not r["outside"]]
    rendered = [r for r in inside if ok(r["trace_exit"])]
    matching = [r for r in rendered if r["flip"] and float(r["flip"]) <= 0.01]
    beyond = [r for r in pov if r["outside"] and ok(r["trace_exit"])]
    crashes = [r for r in rows if str(r["trace_exit"]) not in ("0", "2")]
    reasons = collections.Counter(r["trace_message"].split(" (")[0][:90] for r in inside if not ok(r["trace_exit"]))
    outside = collections.Counter(part for r in pov if r["outside"] for part in r["outside"].split("+"))
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    lines = [
        "# Real users' scenes in trace",
        "",
        f"Made by `scripts/users_corpus.py` on {time.strftime('%Y-%m-%d')} (trace commit `{commit}`). The corpus: "
        f"{len(rows)} scenes from {len({r['scene'].split('/')[0] + '/' + r['scene'].split('/')[1] for r in rows})} public GitHub repositories that are not POV-Ray's",
        "(course work, hobby scenes, scientific figures, exports from VMD, Moray, PoseRay, OpenSCAD and",
        "FreeCAD), gathered without regard to what trace supports; `docs/users-corpus-manifest.tsv` names",
        "each file, its repository and commit. Each scene is rendered at 320×240 without anti-aliasing by",
        "POV-Ray 3.7 (`-A -J`) and by trace (`--aa off`), both with POV-Ray's standard include folder,",
        "and compared where both render. Raw results: `docs/users-corpus.csv`.",
        *([note] if note else []),
        "",
        f"- POV-Ray renders **{len(pov)}** of the {len(rows)} (the rest need files the repositories do not hold —",
        "  images, fonts, includes from the author's machine — or fail in POV-Ray 3.7 itself).",
        f"- Of those, **{len(inside)}** use only what the mission covers: no CSG or photons",
        f"  ({', '.join(f'{k} {v}' for k, v in outside.most_common())} scenes use those).",
        f"- trace renders **{len(rendered)}** of these {len(inside)} ({100 * len(rendered) / max(len(inside), 1):.0f} %), and **{len(matching)}** match POV-Ray",
        "  (mean FLIP ≤ 0.01).",
        f"- Crashes, timeouts or I/O failures in trace: {len(crashes)}.",
        f"- trace also renders {len(beyond)} of the scenes outside the mission (a `union` used as a group,",
        "  or a CSG block that is never placed, passes).",
        "",
        "## Scenes in the mission that trace renders",
        "",
        "| scene | mean FLIP | trace (s) | POV-Ray (s) |",
        "|---|---:|---:|---:|",
    ]
    for r in rendered:
        lines.append(f"| {r['scene']} | {r['flip']} | {r['trace_s']} | {r['povray_s']} |")
    lines += ["", "## What stops the others in the mission (trace's first error)", "", "| scenes | first error |", "|---:|---|"]
    for reason, n in reasons.most_common():
        lines.append(f"| {n} | {reason.replace('|', '/') or '(none)'} |")
    open(path, "w").write("\n".join(lines) + "\n")


if __name__ == "__main__":
    if "--report" in sys.argv:
        out = sys.argv[sys.argv.index("--report") + 1]
        write_report(out[:-4] + ".md", list(csv.DictReader(open(out))))
    else:
        main()

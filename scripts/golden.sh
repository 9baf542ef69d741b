#!/usr/bin/env bash
# Render POV-Ray 3.7 golden references for the example scenes.
#
# Usage: scripts/golden.sh [SCENE ...]
#   SCENE is a path to a .rt file (relative to the cwd or to the repository
#   root), or a name in examples/ (with or without ".rt").
#   Without arguments every examples/*.rt is rendered.
#
# For each scene NAME it writes, at 320x240:
#   golden/povray/NAME.exr     one centre ray per pixel (-A)
#   golden/povray/NAME.aa.exr  deterministic supersampling (+A0.0 +R3 -J)
#   golden/povray/NAME.am2.exr anti-aliasing method 2 (+AM2 +A0.1 +R3 -J)
# and rewrites golden/povray/COMMANDS.md with the POV-Ray version and the exact
# command lines. POV-Ray runs with the scene's folder as its working directory
# (it resolves #include and image files against the cwd, not the scene's folder).
# The script works from any working directory.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT_DIR="$ROOT/golden/povray"
WIDTH=320
HEIGHT=240
# The switches shared by both references, then the anti-aliasing switches of each.
COMMON=(+FE "+W$WIDTH" "+H$HEIGHT" -D -GA)
PLAIN=(-J -A)
AA=(+A0.0 +R3 -J)
AM2=(+AM2 +A0.1 +R3 -J)

# Install POV-Ray if it is missing (Debian/Ubuntu).
if ! command -v povray >/dev/null 2>&1; then
    echo "povray not found; installing it with apt-get" >&2
    SUDO=""
    if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
    $SUDO apt-get update
    $SUDO apt-get install -y povray
fi

# `povray --version` first complains about a missing ~/.povray/3.7/povray.conf
# (harmless), so pick the line that names the version.
POV_VERSION="$(povray --version 2>&1 | grep -m1 '^POV-Ray' || true)"
if [ -z "$POV_VERSION" ]; then
    POV_VERSION="$(povray --version 2>&1 | head -1)"
fi

# Resolve the scene list to absolute paths.
scenes=()
if [ "$#" -eq 0 ]; then
    shopt -s nullglob
    scenes=("$ROOT"/examples/*.rt)
    shopt -u nullglob
    if [ "${#scenes[@]}" -eq 0 ]; then
        echo "no scenes in $ROOT/examples" >&2
        exit 1
    fi
else
    for arg in "$@"; do
        if [ -f "$arg" ]; then
            scenes+=("$(cd "$(dirname "$arg")" && pwd)/$(basename "$arg")")
        elif [ -f "$ROOT/$arg" ]; then
            scenes+=("$(cd "$(dirname "$ROOT/$arg")" && pwd)/$(basename "$arg")")
        elif [ -f "$ROOT/examples/$arg" ]; then
            scenes+=("$ROOT/examples/$arg")
        elif [ -f "$ROOT/examples/$arg.rt" ]; then
            scenes+=("$ROOT/examples/$arg.rt")
        else
            echo "scene not found: $arg" >&2
            exit 1
        fi
    done
fi

mkdir -p "$OUT_DIR"
LOG="$(mktemp)"
MESH_TMP="$(mktemp -d)"
trap 'rm -rf "$LOG" "$MESH_TMP"' EXIT

# for_povray SCENE: the scene POV-Ray should read. A scene using trace's `mesh_file`
# extension is rewritten: each mesh file is converted by `trace convert` into a mesh2 include
# (TraceMesh_<stem>) and `mesh_file { "f.obj"` becomes `object { TraceMesh_f`.
for_povray() {
    local scene="$1"
    if ! grep -q 'mesh_file' "$scene"; then
        echo "$scene"
        return
    fi
    cargo build --release --quiet --manifest-path "$ROOT/Cargo.toml"
    python3 - "$scene" "$MESH_TMP" "$ROOT/target/release/trace" <<'PY'
import os, re, subprocess, sys
scene, tmp, trace = sys.argv[1:]
text = open(scene).read()
includes = []
def repl(m):
    path = m.group(1)
    stem = re.sub(r"[^A-Za-z0-9]", "_", os.path.splitext(os.path.basename(path))[0])
    name = "TraceMesh_" + stem
    inc = os.path.join(tmp, name + ".inc")
    if not os.path.exists(inc):
        subprocess.run([trace, "convert", os.path.join(os.path.dirname(scene), path),
                        "-o", inc, "--name", name], check=True, capture_output=True)
    if '#include "%s"' % inc not in includes:
        includes.append('#include "%s"' % inc)
    return "object { " + name
text = re.sub(r'mesh_file\s*\{\s*"([^"]+)"', repl, text)
out = os.path.join(tmp, os.path.basename(scene))
open(out, "w").write("\n".join(includes) + "\n" + text)
print(out)
PY
}

# render SCENE OUT SWITCH...: run POV-Ray from the scene's folder.
render() {
    local scene="$1" out="$2"
    shift 2
    local dir rel_out
    dir="$(dirname "$scene")"
    rel_out="$(realpath --relative-to="$dir" "$out")"
    rm -f "$out"
    local input
    input="$(for_povray "$scene")"
    [ "$input" = "$scene" ] && input="$(basename "$scene")"
    # The output path is given relative to the scene's folder, exactly as
    # COMMANDS.md records it.
    if ! (cd "$dir" &&
          povray "+I$input" "+O$rel_out" "${COMMON[@]}" "$@") >"$LOG" 2>&1 ||
       [ ! -s "$out" ]; then
        cat "$LOG" >&2
        echo "povray failed on $scene" >&2
        exit 1
    fi
    # POV-Ray stamps the render time into the EXR header ("creation"), the only
    # bytes that change between runs. Overwrite it with a fixed string of the
    # same length (so no offset moves) to make the references reproducible.
    perl -0777 -pi -e \
        's/creation\x00string\x00\x14\x00\x00\x00\d{4}-\d\d-\d\d \d\d:\d\d:\d\dZ/creation\x00string\x00\x14\x00\x00\x001970-01-01 00:00:00Z/' \
        "$out"
}

for scene in "${scenes[@]}"; do
    name="$(basename "$scene")"
    name="${name%.*}"
    echo "rendering $name" >&2
    render "$scene" "$OUT_DIR/$name.exr" "${PLAIN[@]}"
    render "$scene" "$OUT_DIR/$name.aa.exr" "${AA[@]}"
    render "$scene" "$OUT_DIR/$name.am2.exr" "${AM2[@]}"
done

# COMMANDS.md lists the commands for every reference in the folder, so a run on
# a subset of scenes keeps the others documented. The scene is found in
# examples/ unless it was given by path in this run.
{
    echo "# POV-Ray golden references"
    echo
    echo "Generated by \`scripts/golden.sh\`; do not edit by hand."
    echo
    echo "- POV-Ray: \`$POV_VERSION\`"
    echo "- Output: OpenEXR (\`+FE\`), half-float linear RGB, ${WIDTH}x${HEIGHT}."
    echo "- \`cd\` paths are relative to the repository root, \`+I\`/\`+O\` paths to the scene's folder."
    echo "- The EXR header's \`creation\` timestamp is then overwritten with"
    echo "  \`1970-01-01 00:00:00Z\` so that re-running gives byte-identical files."
    echo "- \`NAME.exr\`: one centre ray per pixel (\`${PLAIN[*]}\`)."
    echo "- \`NAME.aa.exr\`: anti-aliasing method 1, threshold 0, depth 3, no jitter"
    echo "  (\`${AA[*]}\`): every pixel is (centre + 3x3 grid) / 10."
    echo "- \`NAME.am2.exr\`: anti-aliasing method 2, threshold 0.1, depth 3, no jitter"
    echo "  (\`${AM2[*]}\`): corners shared between pixels, squares split where they differ."
    echo "- A scene using trace's \`mesh_file\` extension is given to POV-Ray rewritten: each"
    echo "  mesh file becomes a mesh2 include (\`trace convert FILE -o TraceMesh_STEM.inc"
    echo "  --name TraceMesh_STEM\`) and \`mesh_file { \"FILE\"\` becomes \`object { TraceMesh_STEM\`."
    echo
    echo "## Commands"
    echo
    echo '```sh'
    for exr in "$OUT_DIR"/*.exr; do
        [ -e "$exr" ] || continue
        file="$(basename "$exr")"
        case "$file" in
            *.aa.exr) name="${file%.aa.exr}"; switches=("${AA[@]}") ;;
            *.am2.exr) name="${file%.am2.exr}"; switches=("${AM2[@]}") ;;
            *)        name="${file%.exr}";    switches=("${PLAIN[@]}") ;;
        esac
        scene="$ROOT/examples/$name.rt"
        for s in "${scenes[@]}"; do
            b="$(basename "$s")"
            if [ "${b%.*}" = "$name" ]; then scene="$s"; fi
        done
        dir="$(dirname "$scene")"
        rel_out="$(realpath --relative-to="$dir" "$OUT_DIR/$file")"
        echo "cd ${dir#"$ROOT"/} && povray +I$(basename "$scene") +O$rel_out ${COMMON[*]} ${switches[*]}"
    done
    echo '```'
} >"$OUT_DIR/COMMANDS.md"

echo "wrote ${#scenes[@]} scene(s) to ${OUT_DIR#"$ROOT"/}" >&2

#!/usr/bin/env bash
# Memory figure for instancing: peak resident memory of a scene with 1 instance of a
# 100k-triangle mesh2 against the same scene with 1,000 instances (declared once, used with
# `object { Mesh transform }`). Instances share the mesh and its BVH, so the ratio should stay
# near 1 (the project's bar: at most 1.3).
#
# Usage: scripts/memory.sh            (env: SIZE=N for an N×N vertex grid, default 224 → 99,458 triangles)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SIZE="${SIZE:-224}"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
cargo build --release --quiet --manifest-path "$ROOT/Cargo.toml"
TRACE="$ROOT/target/release/trace"

python3 - "$SIZE" "$TMP" <<'PY'
import math, sys
n, out = int(sys.argv[1]), sys.argv[2]
verts = []
for j in range(n):
    for i in range(n):
        x, z = i / (n - 1) - 0.5, j / (n - 1) - 0.5
        verts.append("<%.5f,%.5f,%.5f>" % (x, 0.05 * math.sin(12 * x) * math.cos(9 * z), z))
faces = []
for j in range(n - 1):
    for i in range(n - 1):
        a = j * n + i
        faces.append("<%d,%d,%d>" % (a, a + n, a + 1))
        faces.append("<%d,%d,%d>" % (a + 1, a + n, a + n + 1))
mesh = "#declare Terrain = mesh2 {\n vertex_vectors { %d,\n%s }\n face_indices { %d,\n%s }\n pigment { rgb <0.6,0.7,0.4> } }\n" % (
    len(verts), ",\n".join(verts), len(faces), ",\n".join(faces))
head = """#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 30, -30> look_at 0 angle 50 right x*image_width/image_height }
light_source { <20, 40, -30>, rgb 1 }
"""
def scene(count):
    k = int(math.ceil(math.sqrt(count)))
    body = []
    for c in range(count):
        x, z = c % k - k / 2, c // k - k / 2
        body.append("object { Terrain rotate y*%d translate <%.2f, 0, %.2f> }" % (c * 37 % 360, x * 1.2, z * 1.2))
    return head + mesh + "\n".join(body) + "\n"
open(out + "/one.rt", "w").write(scene(1))
open(out + "/many.rt", "w").write(scene(1000))
print("triangles per mesh: %d" % len(faces))
PY

peak_kb() { /usr/bin/time -f %M "$@" 2>&1 >/dev/null | tail -1; }
one=$(peak_kb "$TRACE" "$TMP/one.rt" -o "$TMP/one.png" --width 160 --height 120 --aa off --quiet)
many=$(peak_kb "$TRACE" "$TMP/many.rt" -o "$TMP/many.png" --width 160 --height 120 --aa off --quiet)
echo "peak RSS, 1 instance:      $((one / 1024)) MiB"
echo "peak RSS, 1000 instances:  $((many / 1024)) MiB"
python3 -c "print('ratio: %.3f (bar: 1.3)' % ($many / $one))"

#!/usr/bin/env bash
# Scaling with object count: N random spheres (N = 1k, 10k, 100k by default), rendered by
# trace and POV-Ray in the same run at the same size (320x240, no anti-aliasing); prints
# end-to-end wall times and their ratio. Usage: scripts/spheres.sh [N ...]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
cargo build --release --quiet --manifest-path "$ROOT/Cargo.toml"
TRACE="$ROOT/target/release/trace"
[ "$#" -eq 0 ] && set -- 1000 10000 100000
echo "| spheres | trace (s) | POV-Ray (s) | POV-Ray / trace | mean FLIP |"
echo "|---:|---:|---:|---:|---:|"
for n in "$@"; do
    python3 - "$n" "$TMP/s$n.pov" <<'PY'
import random, sys
n, out = int(sys.argv[1]), sys.argv[2]
random.seed(1)
side = 40.0
r = 0.5 * side / n ** (1 / 3)
lines = ["#version 3.7;", "global_settings { assumed_gamma 1.0 }",
         "camera { location <0, 30, -70> look_at 0 angle 50 right x*image_width/image_height }",
         "light_source { <30, 60, -40>, rgb 1 }", "plane { y, -25 pigment { rgb 0.8 } }"]
for i in range(n):
    x, y, z = (random.uniform(-side / 2, side / 2) for _ in range(3))
    c = [random.random() for _ in range(3)]
    lines.append("sphere { <%.4f,%.4f,%.4f>, %.4f pigment { rgb <%.3f,%.3f,%.3f> } }" % (x, y, z, r, *c))
open(out, "w").write("\n".join(lines) + "\n")
PY
    s=$(date +%s.%N); "$TRACE" "$TMP/s$n.pov" -o "$TMP/t$n.exr" --width 320 --height 240 --aa off --quiet; e=$(date +%s.%N)
    tt=$(python3 -c "print(f'{$e-$s:.3f}')")
    s=$(date +%s.%N); (cd "$TMP" && povray "+Is$n.pov" "+Op$n.exr" +FE +W320 +H240 -D -GA -A -J >/dev/null 2>&1); e=$(date +%s.%N)
    pt=$(python3 -c "print(f'{$e-$s:.3f}')")
    flip=$("$TRACE" compare "$TMP/p$n.exr" "$TMP/t$n.exr" | awk '/mean FLIP/ {print $3}')
    echo "| $n | $tt | $pt | $(python3 -c "print(f'{$pt/$tt:.1f}')") | $flip |"
done

#!/usr/bin/env bash
# One big image on many objects: a 3840×2160 JPEG as the image_map of 96 boxes (as a real
# users' scene does), rendered at 320×240 with each renderer's defaults otherwise; prints wall
# time and peak resident memory of trace (and of BASELINE, an older trace binary, if given)
# and of POV-Ray 3.7 in one run, with the ratios. trace decodes a file once and keeps its
# texels once per colour setting, at the file's precision (4 bytes a pixel for 8-bit files).
#
# Usage: scripts/images.sh [BASELINE_TRACE]      (needs python3 with PIL to make the JPEG)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
cargo build --release --quiet --manifest-path "$ROOT/Cargo.toml"
TRACE="$ROOT/target/release/trace"

python3 - "$TMP" <<'PY'
import math, random, sys
from PIL import Image
out = sys.argv[1]
w, h = 3840, 2160
rnd = random.Random(1)
img = Image.new("RGB", (w, h))
img.putdata([(int(127.5 + 127.5 * math.sin(20 * x / w + 5 * y / h)), 255 * x // w,
              rnd.randrange(256)) for y in range(h) for x in range(w)])
img.save(out + "/big.jpg", quality=90)
lines = ["#version 3.7;", "global_settings { assumed_gamma 1.0 }",
         "camera { location <0, 0, -30> look_at 0 angle 60 }",
         "light_source { <-20, 30, -40> rgb 1 }"]
for i in range(96):
    x, y = (i % 12) - 5.5, (i // 12) - 3.5
    lines.append('box { 0, 1 pigment { image_map { jpeg "big.jpg" interpolate 2 } } '
                 'translate <%g, %g, 0> scale 2 }' % (x * 1.2, y * 1.2))
open(out + "/boxes.pov", "w").write("\n".join(lines) + "\n")
PY

cd "$TMP"
measure() { # label, command…
    local label=$1; shift
    /usr/bin/time -f "%e %M" -o time.txt "$@" >/dev/null 2>&1
    read -r secs kb < time.txt
    printf '%s %s %s\n' "$label" "$secs" "$kb"
}
{
    measure trace "$TRACE" boxes.pov -o t.png +W320 +H240 -q
    if [ $# -ge 1 ]; then measure baseline "$1" boxes.pov -o b.png +W320 +H240 -q; fi
    measure povray povray +Iboxes.pov +Op.png +W320 +H240 -D
} > rows.txt
awk '
    { s[$1] = $2; m[$1] = $3 / 1024; order[NR] = $1 }
    END {
        print "| renderer | time | peak memory | time / POV-Ray | memory / POV-Ray |"
        print "|---|---:|---:|---:|---:|"
        for (i = 1; i <= NR; i++) {
            r = order[i]
            printf "| %s | %.2f s | %.0f MiB | %.3f | %.3f |\n", r, s[r], m[r], s[r] / s["povray"], m[r] / m["povray"]
        }
    }' rows.txt

#!/usr/bin/env bash
# Renders every example (or the scenes given) with trace and with POV-Ray 3.7 in the same run,
# at the same size and anti-aliasing, and prints a markdown table: mean FLIP and RMSE of
# trace's image against POV-Ray's, and both end-to-end times (parse + render + write).
#
# Usage: scripts/crosscheck.sh [SCENE.rt ...]     (env: WIDTH, HEIGHT, RUNS)
# Modes: "off" = trace --aa off vs povray -A; "aa" = trace --aa 0.0 --aa-depth 3 vs
# povray +A0.0 +R3 -J. Each time is the best of RUNS runs (default 3). Both write the same
# file: an EXR of half floats (POV-Ray's +FE; trace's --bits 16).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WIDTH="${WIDTH:-320}"
HEIGHT="${HEIGHT:-240}"
RUNS="${RUNS:-3}"
command -v povray >/dev/null || { apt-get update && apt-get install -y povray; }
cargo build --release --quiet --manifest-path "$ROOT/Cargo.toml"
TRACE="$ROOT/target/release/trace"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

# Every example POV-Ray can read (mesh_file is trace's own extension).
if [ "$#" -eq 0 ]; then
    for f in "$ROOT"/examples/*.rt; do
        grep -q 'mesh_file' "$f" || set -- "$@" "$f"
    done
fi

# best_time CMD...: runs the command RUNS times, prints the fastest wall time in seconds.
best_time() {
    local best=""
    for _ in $(seq "$RUNS"); do
        local s e
        s=$(date +%s.%N)
        "$@" >/dev/null 2>&1
        e=$(date +%s.%N)
        best=$(python3 -c "import sys; t=$e-$s; b='$best'; print(t if not b else min(t, float(b)))")
    done
    printf '%.3f' "$best"
}

echo "| scene | AA | mean FLIP | RMSE | trace (s) | POV-Ray (s) | POV-Ray / trace |"
echo "|---|---|---:|---:|---:|---:|---:|"
for scene in "$@"; do
    scene="$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")"
    name="$(basename "$scene" .rt)"
    for mode in off aa; do
        if [ "$mode" = off ]; then
            targs=(--aa off); pargs=(-A -J)
        else
            targs=(--aa 0.0 --aa-depth 3 --aa-method 1); pargs=(+A0.0 +R3 -J)
        fi
        tout="$TMP/$name.$mode.trace.exr"
        pout="$TMP/$name.$mode.pov.exr"
        tt=$(best_time "$TRACE" "$scene" -o "$tout" --width "$WIDTH" --height "$HEIGHT" "${targs[@]}" --bits 16 --quiet)
        pt=$(cd "$(dirname "$scene")" && best_time povray "+I$scene" "+O$pout" +FE "+W$WIDTH" "+H$HEIGHT" -D -GA "${pargs[@]}")
        cmp="$("$TRACE" compare "$pout" "$tout")"
        flip=$(echo "$cmp" | awk '/mean FLIP/ {print $3}')
        rmse=$(echo "$cmp" | awk '/RMSE/ {print $2}')
        ratio=$(python3 -c "print(f'{$pt/$tt:.1f}')")
        echo "| $name | $mode | $flip | $rmse | $tt | $pt | $ratio |"
    done
done

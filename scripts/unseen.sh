#!/usr/bin/env bash
# Renders the scenes of tests/unseen (written by someone who had not seen trace's code, using
# POV-Ray's standard include files; t1-t10 with the image files of tests/unseen/img) with
# trace and POV-Ray 3.7 at 320x240 without
# anti-aliasing, and prints each scene's mean FLIP. Needs povray and povray-includes.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
INC="${INC:-/usr/share/povray-3.7/include}"
cargo build --release --quiet --manifest-path "$ROOT/Cargo.toml"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
# (From a copy: some scenes write data files beside themselves.)
cp "$ROOT"/tests/unseen/*.pov "$TMP/"
cp -r "$ROOT"/tests/unseen/img "$TMP/"
cd "$TMP"
echo "| scene | mean FLIP |"
echo "|---|---:|"
for f in *.pov; do
    n="${f%.pov}"
    "$ROOT/target/release/trace" "$f" -o "$TMP/$n.t.png" --width 320 --height 240 --aa off -q -L "$INC" 2>/dev/null
    povray "+I$f" "+O$TMP/$n.p.png" +W320 +H240 -A -D -GA "+L$INC" >/dev/null 2>&1
    flip=$("$ROOT/target/release/trace" compare "$TMP/$n.p.png" "$TMP/$n.t.png" | awk '/mean FLIP/ {print $3}')
    echo "| $n | $flip |"
done

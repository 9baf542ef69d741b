#!/usr/bin/env bash
# POV-Ray 3.7's renders of the radiosity test scenes (tests/radiosity/*.pov), and how much
# POV-Ray's own renders of them differ from run to run.
#
# Usage: scripts/radiosity.sh [NAME ...]   (default: every scene in tests/radiosity)
#
# For each scene NAME, at 160x120 without anti-aliasing, it writes
#   golden/radiosity/NAME.exr   POV-Ray with one thread (+WT1: the only reproducible run)
# and measures POV-Ray's spread: the mean FLIP between that render and two renders with two
# threads (whose samples depend on the threads' timing), and between those two. The largest
# of the three goes to golden/radiosity/spread.txt ("NAME FLIP" lines), which the test
# (cli/tests/integration/radiosity.rs) takes as its tolerance: trace must be as close to
# POV-Ray's one-thread picture as POV-Ray's own runs are to each other (and never needs to
# be closer than 0.01).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$ROOT/golden/radiosity"
mkdir -p "$OUT"
cargo build --release --quiet --manifest-path "$ROOT/Cargo.toml"
TRACE="$ROOT/target/release/trace"
names=("$@")
if [ "${#names[@]}" -eq 0 ]; then
    for f in "$ROOT"/tests/radiosity/*.pov; do names+=("$(basename "${f%.pov}")"); done
fi
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
SWITCHES=(+FE +W160 +H120 -A -J -D -GA)
flip() { "$TRACE" compare "$1" "$2" | awk '/mean FLIP/ {print $3}'; }
touch "$OUT/spread.txt"
for name in "${names[@]}"; do
    echo "rendering $name" >&2
    (cd "$ROOT/tests/radiosity" &&
        povray "+I$name.pov" "+O$OUT/$name.exr" "${SWITCHES[@]}" +WT1 >/dev/null 2>&1 &&
        povray "+I$name.pov" "+O$TMP/a.exr" "${SWITCHES[@]}" +WT2 >/dev/null 2>&1 &&
        povray "+I$name.pov" "+O$TMP/b.exr" "${SWITCHES[@]}" +WT2 >/dev/null 2>&1)
    # (The EXR header's creation time is the only byte that changes between runs.)
    perl -0777 -pi -e \
        's/creation\x00string\x00\x14\x00\x00\x00\d{4}-\d\d-\d\d \d\d:\d\d:\d\dZ/creation\x00string\x00\x14\x00\x00\x001970-01-01 00:00:00Z/' \
        "$OUT/$name.exr"
    spread="$(printf '%s\n' "$(flip "$TMP/a.exr" "$OUT/$name.exr")" \
        "$(flip "$TMP/b.exr" "$OUT/$name.exr")" "$(flip "$TMP/a.exr" "$TMP/b.exr")" | sort -g | tail -1)"
    grep -v "^$name " "$OUT/spread.txt" >"$TMP/spread" || true
    echo "$name $spread" >>"$TMP/spread"
    sort "$TMP/spread" >"$OUT/spread.txt"
    echo "$name: POV-Ray's spread $spread" >&2
done

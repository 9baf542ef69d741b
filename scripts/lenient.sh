#!/usr/bin/env bash
# POV-Ray 3.7's renders of the leniency scenes (tests/lenient/*.pov): what POV-Ray's parser
# lets pass that a strict grammar would not, one scene each (its first lines say which, and
# what POV-Ray warns). Writes tests/lenient/povray/NAME.png at 64x48 without anti-aliasing;
# cli/tests/integration/lenient.rs renders each scene with trace and compares.
#
# Usage: scripts/lenient.sh [NAME...]   (default: every scene)
set -euo pipefail
cd "$(dirname "$0")/.."
command -v povray > /dev/null || (apt-get update -qq && apt-get install -y -qq povray povray-includes)
include=/usr/share/povray-3.7/include
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp tests/lenient/*.pov tests/lenient/*.inc "$work"
mkdir -p tests/lenient/povray
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
    for f in tests/lenient/*.pov; do names+=("$(basename "$f" .pov)"); done
fi
for name in "${names[@]}"; do
    (cd "$work" && povray "+I$name.pov" "+O$name.png" +W64 +H48 -A -J -D -GA +FN8 "+L$include" > /dev/null 2>&1) ||
        { echo "POV-Ray refused $name.pov" >&2; exit 1; }
    cp "$work/$name.png" "tests/lenient/povray/$name.png"
done
echo "wrote ${#names[@]} references in tests/lenient/povray/ ($(povray --version 2>&1 | grep -m1 "^POV-Ray" || echo POV-Ray))"

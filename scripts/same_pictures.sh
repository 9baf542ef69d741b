#!/usr/bin/env bash
# Byte-identical pictures across a change that should not alter any: renders every example
# (examples/*.rt) with two trace binaries under each anti-aliasing method (off, 1, 2, 3 with
# sampled area lights and focal blur) to EXR (linear, exact) and compares the files byte for
# byte. A redesign that moves code (the transport layer, issue 40) must pass it.
#
# Usage: scripts/same_pictures.sh OLD_TRACE NEW_TRACE [WIDTH HEIGHT]   (default 160 120)
# Prints each differing render and a summary; exits 1 if any differ or fail.
set -uo pipefail
old=$1 new=$2 w=${3:-160} h=${4:-120}
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
settings=("--aa off" "--aa 0.3 --aa-method 1" "--aa 0.3 --aa-method 2"
          "--aa 0.3 --aa-method 3 --area-lights sampled --focal-blur sampled")
renders=0 differ=0 failed=0
for scene in examples/*.rt; do
    name=$(basename "$scene" .rt)
    for i in "${!settings[@]}"; do
        read -r -a flags <<< "${settings[$i]}"
        a="$work/$name.$i.old.exr" b="$work/$name.$i.new.exr"
        "$old" "$scene" -o "$a" --width "$w" --height "$h" "${flags[@]}" --quiet > /dev/null 2>&1
        ra=$?
        "$new" "$scene" -o "$b" --width "$w" --height "$h" "${flags[@]}" --quiet > /dev/null 2>&1
        rb=$?
        renders=$((renders + 1))
        if [ $ra -ne $rb ]; then
            echo "exit codes differ: $name (${settings[$i]}): $ra vs $rb"; failed=$((failed + 1))
        elif [ $ra -eq 0 ] && ! cmp -s "$a" "$b"; then
            echo "differs: $name (${settings[$i]})"; differ=$((differ + 1))
        fi
        rm -f "$a" "$b"
    done
done
echo "$renders renders of $(ls examples/*.rt | wc -l) examples at ${w}x$h: $differ differ, $failed exit codes differ"
[ $differ -eq 0 ] && [ $failed -eq 0 ]

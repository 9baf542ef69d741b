#!/usr/bin/env bash
# Embree reference numbers for the mesh BVH benchmark (benches/bvh.rs): the same height-field
# meshes (10k, 100k, 1M triangles) and the same camera, random and shadow rays, traced with
# Intel Embree on one thread. Prints one machine-readable line per measurement: build time
# (best and median of 5), rays per second (best and median of 5 repetitions of at least
# 0.1 s each) and checksums (hits and sum of hit t; occluded count) to compare with trace's.
# Embree build qualities low, medium (its default) and high are all reported.
#
# What it does: installs Debian's libembree-dev with apt-get if no Embree 3 or 4 header is
# found, compiles benches/embree/embree_bench.c with gcc -O2 -march=native (plain -O2 if the
# compiler rejects -march=native) into a temporary directory, and runs it.
#
# Usage: scripts/embree.sh [size ...]     (default sizes: 10000 100000 1000000)
#   env: EMBREE_THREADS=n   Embree build threads (default 1; 0 = all cores)
#        EMBREE_CONFIG=...  extra Embree device configuration (e.g. verbose=1 shows the ISA)
# The 1M-triangle builds need a few hundred MB of memory.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SRC="$ROOT/benches/embree/embree_bench.c"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

# The Embree major version whose header is installed (4 preferred), or nothing.
embree_major() {
    for v in 4 3; do
        if [ -f "/usr/include/embree$v/rtcore.h" ] || [ -f "/usr/local/include/embree$v/rtcore.h" ]; then
            echo "$v"
            return
        fi
    done
}

MAJOR="$(embree_major)"
if [ -z "$MAJOR" ]; then
    echo "embree.sh: Embree not found; installing libembree-dev with apt-get" >&2
    SUDO=""
    if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then
        SUDO="sudo"
    fi
    if ! { $SUDO apt-get update -qq && \
           DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq libembree-dev; } \
           >"$TMP/apt.log" 2>&1; then
        cat "$TMP/apt.log" >&2
        echo "embree.sh: error: could not install libembree-dev (needs apt-get and root)" >&2
        exit 1
    fi
    MAJOR="$(embree_major)"
    if [ -z "$MAJOR" ]; then
        echo "embree.sh: error: libembree-dev installed but no embree3/embree4 header found" >&2
        exit 1
    fi
fi

CFLAGS=(-O2 -std=c11 -Wall -Wextra -DEMBREE_MAJOR="$MAJOR")
LIBS=(-lembree"$MAJOR" -lm)
if ! gcc "${CFLAGS[@]}" -march=native "$SRC" -o "$TMP/embree_bench" "${LIBS[@]}" 2>"$TMP/cc.log"; then
    echo "embree.sh: -march=native failed, compiling without it" >&2
    if ! gcc "${CFLAGS[@]}" "$SRC" -o "$TMP/embree_bench" "${LIBS[@]}"; then
        echo "embree.sh: error: could not compile $SRC against Embree $MAJOR" >&2
        exit 1
    fi
fi

"$TMP/embree_bench" "$@"

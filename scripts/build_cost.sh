#!/usr/bin/env bash
# First-build cost of trace at one or more commits, measured in one run: a fresh clone per
# commit, an empty target folder, then `cargo build --release` (wall time, binary size) and
# `cargo test --no-run` (the build the test command needs on top), and the target folder's size.
# Dependencies come from the local cargo registry (no download is timed).
#
# Usage: scripts/build_cost.sh COMMIT...      (e.g. scripts/build_cost.sh 62586ac HEAD)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
echo "| commit | release build (s) | binary (MB) | + test build (s) | target/ (MB) |"
echo "|---|---:|---:|---:|---:|"
for commit in "$@"; do
    dir="$(mktemp -d)"
    git clone --quiet "$ROOT" "$dir/trace"
    git -C "$dir/trace" checkout --quiet "$commit"
    cd "$dir/trace"
    cargo fetch --quiet >/dev/null 2>&1 || true
    s=$(date +%s.%N); cargo build --release --quiet 2>/dev/null; e=$(date +%s.%N)
    release=$(python3 -c "print(f'{$e - $s:.0f}')")
    size=$(python3 -c "import os; print(f'{os.path.getsize(\"target/release/trace\") / 1e6:.1f}')")
    s=$(date +%s.%N); cargo test --no-run --quiet >/dev/null 2>&1; e=$(date +%s.%N)
    tests=$(python3 -c "print(f'{$e - $s:.0f}')")
    target=$(du -sm target | cut -f1)
    echo "| $(git rev-parse --short HEAD) | $release | $size | $tests | $target |"
    cd "$ROOT"
    rm -rf "$dir"
done

#!/usr/bin/env bash
# Runs the GNU parallel recipes of docs/farm.md on this machine and checks their results.
#
# Usage: scripts/farm/parallel-test.sh [TRACE]
#   TRACE is the trace binary (default: target/release/trace in the repository).
#
# (a) tiles: a still rendered whole, then as 4 strips by 2 parallel workers and merged with
#     `trace merge`: the merged file must equal the whole render byte for byte.
# (b) frames: a 4-frame animation rendered by one `trace` run, then one job per frame
#     (+KFI1 +KFF4 +SFn +EFn) on 2 workers: the same file names (anim1.png .. anim4.png) and
#     the same bytes; frame n must also equal a still at clock (n-1)/3.
# (c) ssh: the recipes for other machines with two stand-in hosts (a fake ssh that runs each
#     "host" in its own folder): a 10-frame animation with padded names (anim01.png ..
#     anim10.png) in a shared folder (--workdir) and sent back (--basefile, --return,
#     --cleanup), and the 4 strips sent back and merged. Skipped without rsync.
# Exits non-zero if any check fails.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
TRACE="${1:-$ROOT/target/release/trace}"
if [[ ! -x "$TRACE" ]]; then
    echo "error: no trace binary at $TRACE (build it with: cargo build --release)" >&2
    exit 2
fi
TRACE="$(cd "$(dirname "$TRACE")" && pwd)/$(basename "$TRACE")"
if ! command -v parallel >/dev/null 2>&1; then
    echo "error: GNU parallel is not installed (Debian/Ubuntu: apt-get install parallel)" >&2
    exit 2
fi
if ! parallel --version 2>/dev/null | grep -q 'GNU parallel'; then
    echo "error: 'parallel' is not GNU parallel (moreutils has another one): apt-get install parallel" >&2
    exit 2
fi

WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"
export PARALLEL_HOME="$WORK/.parallel"   # keep ~/.parallel untouched
PAR=(parallel --will-cite --halt now,fail=1)

FAILED=0
ok() { echo "  ok: $*"; }
fail() { echo "  FAIL: $*"; FAILED=1; }
same() { # FILE_A FILE_B WHAT
    if cmp -s "$1" "$2"; then ok "$3"; else fail "$3 ($1 and $2 differ)"; fi
}

W=160
H=120
cp "$ROOT/scripts/farm/test-anim.pov" anim.pov

# Strips of whole 32-row blocks (as in docs/farm.md): "Y0 Y1" per line.
strips() { # HEIGHT COUNT
    awk -v h="$1" -v n="$2" 'BEGIN {
        b = int((h + 31) / 32)
        for (i = 0; i < n; i++) {
            y0 = int(i * b / n) * 32
            y1 = (i == n - 1) ? h : int((i + 1) * b / n) * 32
            print y0, y1
        }
    }'
}

echo "trace: $TRACE"
echo "$("${PAR[@]}" --version | head -n 1)"

echo "(a) tiles of a still: 4 strips on 2 workers, then trace merge"
"$TRACE" anim.pov +W$W +H$H -o whole.png -q
mkdir parts
strips $H 4 | "${PAR[@]}" -S 2/: --colsep ' ' \
    "$TRACE" anim.pov +W$W +H$H --region 0,{1},$W,{2} -o parts/strip-{#}.png -q
echo "  strips: $(strips $H 4 | tr '\n' ' ')"
n_parts=$(find parts -name 'strip-*.png' | wc -l)
if [[ $n_parts -eq 4 ]]; then ok "4 parts written"; else fail "$n_parts parts written, 4 expected"; fi
for p in parts/strip-*.png; do
    if cmp -s "$p" whole.png; then fail "$p is the whole image, not a part"; fi
done
"$TRACE" merge -o merged.png parts/strip-*.png 2>&1 | sed 's/^/  /'
same merged.png whole.png "merged strips = whole render"

echo "(b) frames of an animation: one job per frame (+KFI1 +KFF4 +SFn +EFn) on 2 workers"
mkdir single farm
cp anim.pov single/
cp anim.pov farm/
"$TRACE" single/anim.pov +W$W +H$H +KFI1 +KFF4 -q
seq 1 4 | "${PAR[@]}" -S 2/: \
    "$TRACE" farm/anim.pov +W$W +H$H +KFI1 +KFF4 +SF{} +EF{} -q
expected="anim.pov anim1.png anim2.png anim3.png anim4.png"
for dir in single farm; do
    names="$(cd "$dir" && ls | tr '\n' ' ' | sed 's/ $//')"
    if [[ "$names" == "$expected" ]]; then
        ok "$dir/ holds POV-Ray's names: $names"
    else
        fail "$dir/ holds: $names (expected: $expected)"
    fi
done
for n in 1 2 3 4; do
    same "farm/anim$n.png" "single/anim$n.png" "frame $n of the farm = frame $n of one run"
done
for n in 1 2 3; do
    if cmp -s "single/anim$n.png" "single/anim$((n + 1)).png"; then
        fail "frames $n and $((n + 1)) are identical (the clock does not move)"
    fi
done
for n in 1 2 3 4; do
    clock=$(awk -v n=$n 'BEGIN { printf "%.17g", (n - 1) / 3 }')
    "$TRACE" anim.pov +W$W +H$H +K"$clock" -o "k$n.png" -q
    same "k$n.png" "single/anim$n.png" "frame $n = still at clock $clock"
done

echo "(c) frames and strips over \"ssh\" on 2 stand-in hosts: --workdir, or --basefile --return --cleanup"
if ! command -v rsync >/dev/null 2>&1; then
    echo "  skipped: GNU parallel transfers files with rsync, which is not installed"
else
    mkdir -p bin hosts ssh-run single10
    # ssh [OPTIONS] HOST [--] COMMAND: runs COMMAND with hosts/HOST as its home and folder.
    cat > bin/fakessh <<'EOF'
#!/usr/bin/env bash
while [[ $# -gt 0 && $1 == -* ]]; do
    case $1 in -l|-p|-o|-i|-F) shift 2 ;; *) shift ;; esac
done
host=$1
shift
[[ ${1-} == -- ]] && shift
home="$FAKE_HOSTS/${host#*@}"
mkdir -p "$home"
# A real ssh login sets SHELL to the login shell; GNU parallel's remote side needs it.
cd "$home" && HOME="$home" SHELL="$(command -v bash)" exec bash -c "$*"
EOF
    chmod +x bin/fakessh
    export FAKE_HOSTS="$WORK/hosts"
    cp anim.pov single10/
    "$TRACE" single10/anim.pov +W$W +H$H +KFI1 +KFF10 -q
    # A shared folder: --workdir runs every job in the same folder (as an NFS mount would).
    mkdir shared
    cp anim.pov shared/
    (cd shared && seq -f %02g 1 10 | "${PAR[@]}" --ssh "$WORK/bin/fakessh" -S 1/host1,1/host2 \
        --workdir "$PWD" "$TRACE" anim.pov +W$W +H$H +KFI1 +KFF10 +SF{} +EF{} -q)
    for n in $(seq -f %02g 1 10); do
        same "shared/anim$n.png" "single10/anim$n.png" "shared folder: anim$n.png = frame $n of one run"
    done
    cp anim.pov ssh-run/
    (cd ssh-run && seq -f %02g 1 10 | "${PAR[@]}" --ssh "$WORK/bin/fakessh" -S 1/host1,1/host2 \
        --basefile anim.pov --return anim{}.png --cleanup \
        "$TRACE" anim.pov +W$W +H$H +KFI1 +KFF10 +SF{} +EF{} -q)
    for n in $(seq -f %02g 1 10); do
        same "ssh-run/anim$n.png" "single10/anim$n.png" "returned anim$n.png = frame $n of one run"
    done
    mkdir ssh-tiles
    cp anim.pov ssh-tiles/
    (cd ssh-tiles && strips $H 4 | "${PAR[@]}" --ssh "$WORK/bin/fakessh" -S 1/host1,1/host2 \
        --colsep ' ' --basefile anim.pov --return big-{#}.png --cleanup \
        "$TRACE" anim.pov +W$W +H$H --region 0,{1},$W,{2} -o big-{#}.png -q)
    "$TRACE" merge -o ssh-tiles/big.png ssh-tiles/big-*.png 2>&1 | sed 's/^/  /'
    same ssh-tiles/big.png whole.png "returned strips merged = whole render"
    used=$(find hosts -mindepth 1 -maxdepth 1 -type d | wc -l)
    if [[ $used -eq 2 ]]; then ok "both hosts were used"; else fail "$used hosts used, 2 expected"; fi
    left=$(find hosts -type f | wc -l)
    if [[ $left -eq 0 ]]; then ok "--cleanup left no file on the hosts"; else fail "$left files left on the hosts"; fi
fi

if [[ $FAILED -ne 0 ]]; then
    echo "FAILED"
    exit 1
fi
echo "all checks passed"

#!/usr/bin/env bash
# Checks the Slurm scripts and the Kubernetes jobs of scripts/farm/ on this machine, without a
# scheduler: stand-ins replace srun (runs the command) and scontrol (notes the requeue).
#
# Usage: scripts/farm/batch-test.sh [TRACE]
#   TRACE is the trace binary (default: target/release/trace in the repository).
#
# (a) slurm-frames.sh for array tasks 1..4 of a 4-frame animation: the frames equal those of
#     one `trace` run. slurm-tiles.sh for tasks 0..3 of 4 strips: `trace merge` of the parts
#     equals the whole render.
# (b) SIGTERM (Slurm's --signal) during a task of each script: the task exits with 130 and
#     requeues itself; running it again finishes the file, equal to an uninterrupted render.
# (c) the shell commands of k8s-frames.yaml and k8s-tiles.yaml (read with PyYAML, run with
#     /bin/sh and the volume's paths moved to a temporary folder) for indexes 0..3: the
#     same checks as (a). Skipped without PyYAML.
# Exits non-zero if any check fails.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
FARM="$ROOT/scripts/farm"
TRACE="${1:-$ROOT/target/release/trace}"
if [[ ! -x "$TRACE" ]]; then
    echo "error: no trace binary at $TRACE (build it with: cargo build --release)" >&2
    exit 2
fi
TRACE="$(cd "$(dirname "$TRACE")" && pwd)/$(basename "$TRACE")"

WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"

FAILED=0
ok() { echo "  ok: $*"; }
fail() { echo "  FAIL: $*"; FAILED=1; }
same() { # FILE_A FILE_B WHAT
    if cmp -s "$1" "$2"; then ok "$3"; else fail "$3 ($1 and $2 differ)"; fi
}

mkdir bin
cat > bin/srun <<'EOF'
#!/usr/bin/env bash
while [[ $# -gt 0 && $1 == -* ]]; do shift; done
exec "$@"
EOF
cat > bin/scontrol <<'EOF'
#!/usr/bin/env bash
echo "$*" >> "$SCONTROL_LOG"
EOF
chmod +x bin/srun bin/scontrol
ln -s "$TRACE" bin/trace
export PATH="$WORK/bin:$PATH" SCONTROL_LOG="$WORK/scontrol.log"
touch "$SCONTROL_LOG"

W=160
H=120
cp "$ROOT/scripts/farm/test-anim.pov" anim.pov
mkdir single
cp anim.pov single/
trace single/anim.pov +W$W +H$H +KFI1 +KFF4 -q
trace anim.pov +W$W +H$H -o whole.png -q

# A Slurm array task: TASK_ID JOB_ID SCRIPT ARGS...
task() {
    local id=$1 job=$2 script=$3
    shift 3
    SLURM_ARRAY_TASK_ID=$id SLURM_JOB_ID=$job SLURM_CPUS_PER_TASK=2 SLURM_MEM_PER_NODE=2048 \
        bash "$FARM/$script" "$@"
}

echo "(a) Slurm array tasks"
for n in 1 2 3 4; do
    task $n 10$n slurm-frames.sh anim.pov 4 frames/anim.png +W$W +H$H -q
done
names="$(cd frames && ls | tr '\n' ' ' | sed 's/ $//')"
if [[ "$names" == "anim1.png anim2.png anim3.png anim4.png" ]]; then
    ok "slurm-frames.sh wrote $names"
else
    fail "slurm-frames.sh wrote: $names"
fi
for n in 1 2 3 4; do
    same "frames/anim$n.png" "single/anim$n.png" "task $n = frame $n of one run"
done
for i in 0 1 2 3; do
    task $i 20$i slurm-tiles.sh anim.pov $W $H 4 parts/big.png -q > /dev/null
done
trace merge -o merged.png parts/big-*.png 2>&1 | sed 's/^/  /'
same merged.png whole.png "slurm-tiles.sh strips merged = whole render"

echo "(b) SIGTERM before the time limit: the task requeues itself, the next run finishes"
BIG="+W2400 +H800 +A0"
trace_under() { # PID: the trace process among its descendants (srun's stand-in execs it)
    local p=$1 c
    for _ in 1 2 3 4 5; do
        c=$(pgrep -P "$p" | head -n 1)
        [[ -n $c ]] || return 1
        if [[ $(cat "/proc/$c/comm" 2> /dev/null) == trace ]]; then
            echo "$c"
            return 0
        fi
        p=$c
    done
    return 1
}
interrupt() { # WHAT DIR TASK_ID JOB_ID SCRIPT ARGS...: starts the task, sends SIGTERM to trace once it has
    # written rows (a hidden scratch file, not empty, in DIR)
    local what=$1 dir=$2 job=$4
    shift 2
    : > "$SCONTROL_LOG"
    task "$@" > "$what.log" 2>&1 &
    local pid=$! child="" started=""
    for _ in $(seq 1 600); do
        child=$(trace_under "$pid" || true)
        if [[ -n $child && -d $dir && -n $(find "$dir" -name '.*' -type f -size +0) ]]; then
            started=1
            break
        fi
        sleep 0.05
    done
    if [[ -z $started ]]; then
        wait "$pid" || true
        fail "$what: the render had not started (or had ended) when the signal was due"
        return
    fi
    kill -TERM "$child"
    local status=0
    wait "$pid" || status=$?
    if [[ $status -eq 130 ]]; then ok "$what: exit status 130 after SIGTERM"; else fail "$what: exit status $status after SIGTERM"; fi
    if grep -q "holds the rows finished" "$what.log"; then
        ok "$what: $(grep -o 'stopped after [0-9]* of [0-9]* rows' "$what.log")"
    else
        fail "$what: no part written ($(tail -n 1 "$what.log"))"
    fi
    if grep -q "^requeue $job\$" "$SCONTROL_LOG"; then ok "$what: scontrol requeue $job"; else fail "$what: no requeue of job $job"; fi
}
interrupt frame big 2 301 slurm-frames.sh anim.pov 4 big/anim.png $BIG
task 2 301 slurm-frames.sh anim.pov 4 big/anim.png $BIG -q
mkdir ref
trace anim.pov $BIG +KFI1 +KFF4 +SF2 +EF2 -o ref/anim.png -q
same big/anim2.png ref/anim2.png "frame continued after SIGTERM = uninterrupted frame"
interrupt strip bigparts 1 401 slurm-tiles.sh anim.pov 2400 800 2 bigparts/big.png +A0
task 1 401 slurm-tiles.sh anim.pov 2400 800 2 bigparts/big.png +A0 -q > /dev/null
task 0 400 slurm-tiles.sh anim.pov 2400 800 2 bigparts/big.png +A0 -q > /dev/null
trace merge -o bigmerged.png bigparts/big-*.png 2> /dev/null
trace anim.pov $BIG -o bigwhole.png -q
same bigmerged.png bigwhole.png "strip continued after SIGTERM, merged = whole render"

echo "(c) the Kubernetes jobs' commands"
if ! python3 -c 'import yaml' 2> /dev/null; then
    echo "  skipped: needs python3 with PyYAML (apt-get install python3-yaml)"
else
    mkdir -p k8s/bin k8s/scenes
    ln -s "$TRACE" k8s/bin/trace
    cp anim.pov k8s/scenes/scene.pov
    # Prints the job's container command, and its environment as shell assignments.
    job() { # FILE
        python3 - "$1" "$WORK/k8s" <<'EOF'
import shlex, sys, yaml
path, root = sys.argv[1], sys.argv[2]
job = next(d for d in yaml.safe_load_all(open(path)) if d and d["kind"] == "Job")
spec = job["spec"]
assert spec["completionMode"] == "Indexed", "not an Indexed Job"
pod = spec["template"]["spec"]
(container,) = pod["containers"]
claims = {v["name"]: v["persistentVolumeClaim"]["claimName"] for v in pod["volumes"]}
assert [m["name"] for m in container["volumeMounts"]] == list(claims), "volume names"
assert container["command"] == ["/bin/sh", "-c"], "command"
for e in container["env"]:
    if "value" in e:
        print(f"export {e['name']}={shlex.quote(e['value'].replace('/farm', root))}")
print(f"export COMPLETIONS={spec['completions']}")
print(f"SCRIPT={shlex.quote(container['args'][0].replace('/farm', root))}")
EOF
    }
    for file in k8s-frames.yaml k8s-tiles.yaml; do
        if out=$(job "$FARM/$file"); then ok "$file: an Indexed Job with a volume and /bin/sh -c"; else fail "$file: $out"; fi
    done
    (
        eval "$(job "$FARM/k8s-frames.yaml")"
        if [[ $COMPLETIONS != "$FINAL_FRAME" ]]; then
            echo "  FAIL: k8s-frames.yaml: completions $COMPLETIONS, FINAL_FRAME $FINAL_FRAME"
            exit 1
        fi
        for i in 0 1 2 3; do
            JOB_COMPLETION_INDEX=$i CPUS=2 MEMORY_MI=2048 FINAL_FRAME=4 OPTIONS="+W$W +H$H -q" \
                /bin/sh -c "$SCRIPT"
        done
    ) || FAILED=1
    for n in 1 2 3 4; do
        same "k8s/frames/anim$n.png" "single/anim$n.png" "k8s-frames index $((n - 1)) = frame $n of one run"
    done
    (
        eval "$(job "$FARM/k8s-tiles.yaml")"
        if [[ $COMPLETIONS != "$STRIPS" ]]; then
            echo "  FAIL: k8s-tiles.yaml: completions $COMPLETIONS, STRIPS $STRIPS"
            exit 1
        fi
        for i in 0 1 2 3; do
            JOB_COMPLETION_INDEX=$i CPUS=2 MEMORY_MI=2048 STRIPS=4 WIDTH=$W HEIGHT=$H OPTIONS=-q \
                /bin/sh -c "$SCRIPT"
        done
    ) || FAILED=1
    trace merge -o k8s/big.png k8s/parts/big-*.png 2>&1 | sed 's/^/  /'
    same k8s/big.png whole.png "k8s-tiles strips merged = whole render"
fi

if [[ $FAILED -ne 0 ]]; then
    echo "FAILED"
    exit 1
fi
echo "all checks passed"

#!/bin/bash
# One frame of an animation per Slurm array task (docs/farm.md).
#
#   sbatch --array=1-100 scripts/farm/slurm-frames.sh SCENE FINAL_FRAME OUTPUT [TRACE OPTIONS...]
#   sbatch --array=1-100 scripts/farm/slurm-frames.sh scene.pov 100 frames/anim.png +W1920 +H1080
#
# Task N renders frame N of the animation 1..FINAL_FRAME (+KFI1 +KFF<FINAL> +SF<N> +EF<N>), so
# its clock and its file name (frames/anim007.png) are those of the whole animation. Give
# the same FINAL_FRAME when you submit only some frames again (--array=7,42).
#
# Before the time limit Slurm sends SIGTERM (--signal below): trace writes the rows it
# finished, exits with 130, and the task requeues itself; the next run continues the frame
# (+C, trace's --continue). A frame already complete is not rendered again.
#
# TRACE=/path/to/trace overrides the trace on PATH.
#SBATCH --job-name=trace-frames
#SBATCH --cpus-per-task=8
#SBATCH --mem=4G
#SBATCH --time=02:00:00
#SBATCH --signal=TERM@180
#SBATCH --requeue
#SBATCH --open-mode=append
#SBATCH --output=trace-frames-%A_%a.log
set -euo pipefail

if [[ $# -lt 3 ]]; then
    echo "usage: sbatch --array=1-N $0 SCENE FINAL_FRAME OUTPUT [TRACE OPTIONS...]" >&2
    exit 2
fi
scene=$1
final=$2
output=$3
shift 3
frame=${SLURM_ARRAY_TASK_ID:?run this with sbatch --array}
trace=${TRACE:-trace}
mkdir -p "$(dirname "$output")"

# Threads from --cpus-per-task; --max-memory a little below --mem (trace also bounds itself
# by the job's control group; this leaves room for the rest). Options given after OUTPUT win.
limits=()
step=(--ntasks=1)
if [[ -n ${SLURM_CPUS_PER_TASK-} ]]; then
    limits+=(+WT"$SLURM_CPUS_PER_TASK")
    step+=(--cpus-per-task="$SLURM_CPUS_PER_TASK")   # (srun of Slurm 22.05 does not inherit it)
fi
if [[ -n ${SLURM_MEM_PER_NODE-} && " $* " != *" --max-memory"* ]]; then
    limits+=(--max-memory "$((SLURM_MEM_PER_NODE * 9 / 10))M")
fi

# srun makes trace a job step, so the --signal above reaches it.
status=0
srun "${step[@]}" "$trace" "$scene" +KFI1 +KFF"$final" +SF"$frame" +EF"$frame" +C \
    -o "$output" ${limits[@]+"${limits[@]}"} "$@" || status=$?

if [[ $status -eq 130 ]]; then
    echo "frame $frame stopped before the time limit: requeueing to continue it"
    scontrol requeue "$SLURM_JOB_ID"
fi
exit "$status"

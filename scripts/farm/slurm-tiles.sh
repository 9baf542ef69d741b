#!/bin/bash
# One horizontal strip of a large still per Slurm array task; merge them in a job that waits
# for the array (docs/farm.md).
#
#   jobid=$(sbatch --parsable --array=0-15 scripts/farm/slurm-tiles.sh \
#       scene.pov 7680 4320 16 parts/big.png [TRACE OPTIONS...])
#   sbatch --dependency=afterok:${jobid%%;*} --wrap 'trace merge -o big.png parts/big-*.png'
#
# Task I (0 .. STRIPS-1) renders strip I of STRIPS into parts/big-I.png: rows Y0..Y1 of the
# WIDTHxHEIGHT image, cut on the 32-row blocks trace renders (so no block is rendered twice).
# STRIPS must not exceed HEIGHT/32. Give the same STRIPS when you submit some strips again
# (--array=3,7).
#
# Before the time limit Slurm sends SIGTERM (--signal below): trace writes the rows it
# finished, exits with 130, and the task requeues itself; the next run continues the strip
# (+C, trace's --continue).
#
# TRACE=/path/to/trace overrides the trace on PATH.
#SBATCH --job-name=trace-tiles
#SBATCH --cpus-per-task=8
#SBATCH --mem=8G
#SBATCH --time=02:00:00
#SBATCH --signal=TERM@180
#SBATCH --requeue
#SBATCH --open-mode=append
#SBATCH --output=trace-tiles-%A_%a.log
set -euo pipefail

if [[ $# -lt 5 ]]; then
    echo "usage: sbatch --array=0-N-1 $0 SCENE WIDTH HEIGHT STRIPS PARTS.png [TRACE OPTIONS...]" >&2
    exit 2
fi
scene=$1
width=$2
height=$3
strips=$4
parts=$5
shift 5
i=${SLURM_ARRAY_TASK_ID:?run this with sbatch --array}
trace=${TRACE:-trace}

# Strip i of n over b rows of 32-pixel blocks (the last strip ends at the image's bottom).
b=$(((height + 31) / 32))
y0=$((i * b / strips * 32))
y1=$(((i + 1) * b / strips * 32))
if [[ $((i + 1)) -eq $strips ]]; then
    y1=$height
fi
if [[ $i -ge $strips || $y0 -ge $y1 ]]; then
    echo "strip $i of $strips is empty (at most $b strips for a height of $height)" >&2
    exit 2
fi
part="${parts%.*}-$i.${parts##*.}"
mkdir -p "$(dirname "$part")"
echo "strip $i of $strips: rows $y0 to $y1 -> $part"

# Threads from --cpus-per-task; --max-memory a little below --mem (trace also bounds itself
# by the job's control group; this leaves room for the rest). Options given after PARTS win.
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
srun "${step[@]}" "$trace" "$scene" +W"$width" +H"$height" --region "0,$y0,$width,$y1" +C \
    -o "$part" ${limits[@]+"${limits[@]}"} "$@" || status=$?

if [[ $status -eq 130 ]]; then
    echo "strip $i stopped before the time limit: requeueing to continue it"
    scontrol requeue "$SLURM_JOB_ID"
fi
exit "$status"

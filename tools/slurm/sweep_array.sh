#!/bin/bash
# A qacc sweep as a Slurm job array: task I of N runs shard I/N into OUT/shard-I; when every
# task is done, merge the shards (docs/SWEEP.md):
#
#   sbatch --array=1-8 tools/slurm/sweep_array.sh sweeps/widths.json out/widths
#   qacc sweep --merge out/widths/shard-* --out out/widths/merged     # after the array ends
#
# The reference cache ($QACC_CACHE, default ~/.cache/qacc) may be on a shared file system:
# entries are written to a temporary file and renamed, so tasks never read a partial one.
#SBATCH --job-name=qacc-sweep
#SBATCH --cpus-per-task=2
#SBATCH --output=qacc-sweep-%A_%a.log
set -euo pipefail
SPEC=${1:?usage: sbatch --array=1-N tools/slurm/sweep_array.sh SPEC.json OUTDIR}
OUT=${2:?usage: sbatch --array=1-N tools/slurm/sweep_array.sh SPEC.json OUTDIR}
QACC=${QACC:-build/qacc}
I=${SLURM_ARRAY_TASK_ID:?not running as a Slurm array task}
N=${SLURM_ARRAY_TASK_COUNT:?not running as a Slurm array task}
exec "$QACC" sweep "$SPEC" --shard "$I/$N" --out "$OUT/shard-$I" --threads "${SLURM_CPUS_PER_TASK:-1}" --no-report

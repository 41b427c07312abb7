#!/bin/bash
# A study as a Slurm job array, stopped and requeued, against one process (docs/ensembles.md):
#   1. SCENE run by one process into WORK/single;
#   2. the same as a job array of N shards (scripts/slurm-array) into WORK/array; once task 1 has
#      run a few seconds it is sent `scancel --signal=TERM`: it must checkpoint, exit 75 and
#      requeue itself, then resume from its checkpoint;
#   3. `vorodg merge WORK/array`; summary.json must be the single run's byte for byte, and every
#      other file the same with times masked (compare_outputs.py).
# Skipped (exit 77) where no Slurm answers (`sinfo`); scripts/slurm-single-node sets one up.
#
#   slurm_job_array_check.sh VORODG SCENE WORK [N]
set -euo pipefail
vorodg=$(realpath "$1") scene=$2 work=$3 shards=${4:-3}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "${here}/../.." && pwd)

if ! command -v sinfo >/dev/null || ! timeout 10 sinfo -h -o '%t' 2>/dev/null | grep -qE 'idle|mix|alloc'; then
  echo "slurm_job_array_check: no Slurm answers here (sinfo): skipped"
  exit 77
fi
rm -rf "${work}"
mkdir -p "${work}"
work=$(realpath "${work}")
cd "${work}"

"${vorodg}" run "${scene}" -o "${work}/single" --threads 1 --quiet > single.log 2>&1

job=$(sbatch --parsable --array=0-$((shards - 1)) "${root}/scripts/slurm-array" "${scene}" \
      "${work}/array" "${vorodg}")
echo "array job ${job}: ${shards} shards"
state() { squeue -h -j "$1" -o '%T' 2>/dev/null | head -1; }
# Task 1: wait until it has run a few seconds, then the scheduler's warning by hand.
for _ in $(seq 600); do
  [[ "$(state "${job}_1")" == RUNNING ]] && break
  sleep 1
done
sleep 8
scancel --signal=TERM "${job}_1"
echo "sent TERM to ${job}_1"
for _ in $(seq 1800); do
  [[ -z "$(squeue -h -j "${job}" 2>/dev/null)" ]] && break
  sleep 2
done
[[ -z "$(squeue -h -j "${job}" 2>/dev/null)" ]] || { echo "the array did not finish"; exit 1; }

log="slurm-${job}_1.out"
cat "${log}"
grep -q "interrupted and checkpointed: requeued" "${log}" || { echo "task 1 was not stopped by the TERM"; exit 1; }
grep -q "resumed at step" "${log}" || { echo "task 1 did not resume from its checkpoint"; exit 1; }

"${vorodg}" merge "${work}/array" > merge.log 2>&1
cmp single/summary.json array/summary.json
/usr/bin/python3 "${root}/scripts/compare_outputs.py" single array
echo "slurm job array: the same results as one process, task 1 stopped, requeued and resumed"

#!/usr/bin/env bash
# Example Slurm batch script: a dashbed stress campaign spread over several nodes with MPI.
#
#   sbatch tools/slurm_stress.sh worlds/default.yaml 10000
#
# One MPI rank per node, each rank using every core of its node with threads (dashbed shares a
# node's cores among the ranks on it when --threads is not given). Rank 0 gathers the outcomes
# and writes the results to $OUT; the results are identical for any number of nodes. dashbed
# must be built with -DDASHBED_MPI=ON (tools/setup.sh does) against the cluster's OpenMPI, and
# the repository (assets/, worlds/) must be on a file system every node sees, or DASHBED_HOME
# must point to a copy of it.
#
#SBATCH --job-name=dashbed-stress
#SBATCH --nodes=4                # machines
#SBATCH --ntasks-per-node=1      # one MPI rank per machine ...
#SBATCH --cpus-per-task=16       # ... with this many worker threads
#SBATCH --time=02:00:00
#SBATCH --output=dashbed-stress-%j.log
set -euo pipefail

world=${1:-worlds/default.yaml}
trials=${2:-10000}
out=${OUT:-stress-$SLURM_JOB_ID}
root=${DASHBED_HOME:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
# sbatch runs a copy of this script: prefer the directory it was submitted from
[[ -x "$root/build/dashbed" ]] || root=$SLURM_SUBMIT_DIR

# mpirun reads the allocation from Slurm (nodes, ranks per node); --bind-to none lets each
# rank's threads use all the cores given to it. --min-success makes the job fail below 99 %.
mpirun --bind-to none "$root/build/dashbed" stress "$world" \
  --trials "$trials" --seed 1 --sigma-xy 0.002 --sigma-yaw 0.02 \
  --threads "$SLURM_CPUS_PER_TASK" --out "$out" --min-success 0.99

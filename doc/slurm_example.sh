#!/bin/bash
# A glissade scene on a cluster node with Slurm (doc/parallel.md). Submit
# with `sbatch doc/slurm_example.sh prm/case3_rings.prm`; the output goes
# where the scene's Output/Directory says, written by process 0.
#
# Every process holds the whole scene and works on its share of the cells,
# of the factorisation (MUMPS) and of the contact products: use the cores
# of one node first (--ntasks on one node); a second node adds cores but
# not memory per process (doc/parallel.md, "What is shared out").
#SBATCH --job-name=glissade
#SBATCH --nodes=1
#SBATCH --ntasks=4
#SBATCH --cpus-per-task=1
#SBATCH --mem-per-cpu=6G
#SBATCH --time=02:00:00
#SBATCH --output=glissade-%j.log

set -euo pipefail
scene=${1:?usage: sbatch doc/slurm_example.sh scene.prm [--set ...]}
shift

# One BLAS thread per process (glissade sets it too when it finds itself
# among several processes) and one deal.II thread per core of the task.
export OPENBLAS_NUM_THREADS=1
export DEAL_II_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}

# Where memory is short, the factors out of core: each process writes its
# share of MUMPS's factors to the node's local scratch (Slurm's $TMPDIR,
# the entry's default, when the cluster sets it) and reads it back at each
# solve; the files are removed at the end. Uncomment to use:
# set -- "$@" --set "Linear solver/Factors out of core=true"

# srun starts the processes under Slurm's PMI; `mpirun -np $SLURM_NTASKS`
# works as well where Open MPI was built with Slurm support.
srun --mpi=pmix build/glissade "$scene" "$@"

#!/usr/bin/env bash
# Installs what glissade needs on Debian bookworm (as root, only what is
# missing), then configures and builds it in ./build (Release).
#
#   bash scripts/setup.sh          the program and its scripts: what a study
#                                  needs (README, first command)
#   bash scripts/setup.sh --all    also the test programs, the benchmarks and
#                                  the test suite's tools (README, second
#                                  command; CI)
set -euo pipefail
cd "$(dirname "$0")/.."

all=false
for argument in "$@"; do
  case "$argument" in
    --all) all=true ;;
    *) echo "scripts/setup.sh: unknown argument '$argument' (only --all)" >&2
       exit 2 ;;
  esac
done

# OpenBLAS: UMFPACK spends its time in dense BLAS kernels, and Debian's
# reference BLAS makes the factorisation 2-3 times slower. The suite's
# tools: numdiff compares scene outputs with their references, and
# clang-format-14 is what the test source_formatted checks the formatting
# with. MUMPS (a run on several processes factorises with it) and mpirun
# come with deal.II's dependencies; named here so that a slimmer install
# still has them.
packages="libdeal.ii-dev libopenblas0-pthread libmumps-dev openmpi-bin cmake g++ make python3-matplotlib"
if $all; then
  packages="$packages numdiff clang-format-14"
fi
missing=""
for p in $packages; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "installing:$missing"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi

# -Werror: a warning fails the build (and CI), so that the build stays clean.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGLISSADE_WERROR=ON >/dev/null
if $all; then
  cmake --build build -j2
else
  cmake --build build -j2 --target glissade
fi

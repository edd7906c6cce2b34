#!/usr/bin/env bash
# Installs what glissade needs on Debian bookworm (as root, only what is
# missing), then configures and builds it in ./build (Release).
set -euo pipefail
cd "$(dirname "$0")/.."

# OpenBLAS: UMFPACK spends its time in dense BLAS kernels, and Debian's
# reference BLAS makes the factorisation 2-3 times slower. clang-format-14:
# the test source_formatted checks the formatting with it.
packages="libdeal.ii-dev libopenblas0-pthread numdiff cmake g++ make python3-matplotlib clang-format-14"
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
cmake --build build -j2

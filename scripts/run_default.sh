#!/usr/bin/env bash
# One command: install what is missing, build (Release) and run the default case.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
bash scripts/build.sh
case_file=${1:-prm/bubbling_bed_2d.prm}
ranks=${WETBED_RANKS:-$(nproc)}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun --oversubscribe -np "$ranks" build/wetbed "$case_file"

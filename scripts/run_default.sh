#!/usr/bin/env bash
# One command: install what is missing, build the wetbed executable (Release), run a case
# (default prm/quick_start_2d.prm, serially; another case on all cores), then plot its monitors
# (scripts/plot_run.py) and render its fields (scripts/render_fields.py), and say where
# the pictures are.
# usage: bash scripts/run_default.sh [CASE.prm [wetbed options, e.g. --overwrite]]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
bash scripts/build.sh wetbed
case_file=${1:-prm/quick_start_2d.prm}
# the quick start (150 cells) runs serially: on this shared 2-core machine 2 ranks took
# 3-6x the wall time of 1 (doc/examples.md); a case named here runs on all cores
if [ -z "${1:-}" ] || [ "$case_file" = prm/quick_start_2d.prm ]; then
  ranks=${WETBED_RANKS:-1}
else
  ranks=${WETBED_RANKS:-$(nproc)}
fi
shift || true
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Ctrl-C: mpirun passes it on and kills the ranks after this many seconds (Open MPI's
# default 1); the ranks abandon their step and write a checkpoint within it
export OMPI_MCA_odls_base_sigkill_timeout=${OMPI_MCA_odls_base_sigkill_timeout:-10}
mpirun --oversubscribe -np "$ranks" build/wetbed "$case_file" "$@"
# the case's output/folder (relative to this folder, as wetbed takes it; default output)
folder=$(sed -n 's/^[[:space:]]*set[[:space:]]\{1,\}folder[[:space:]]*=[[:space:]]*\([^#]*\).*/\1/p' "$case_file" |
  tail -n 1 | sed 's/[[:space:]]*$//')
folder=${folder:-output}
python3 scripts/plot_run.py "$folder"
python3 scripts/render_fields.py "$folder"
echo
echo "wetbed: results in $folder/ (monitors.csv, bubbles.csv, fields)"
echo "wetbed: plots in $folder/plots/, pictures of the bed (alpha_s snapshots and animation) in $folder/pictures/"

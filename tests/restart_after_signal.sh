#!/bin/bash
# SIGTERM (what a batch scheduler sends at its time limit) during a run:
# the increment being solved is finished, a checkpoint of it is written,
# and the run stops with exit code 5 and a message; --restart continues
# from that increment. Usage:
#   restart_after_signal.sh glissade scene.prm dir [processes]
# With processes (> 1), both runs go under mpirun with the factors out of
# core, and the signal goes to the glissade processes, as Slurm's srun
# sends it at a time limit (mpirun's own SIGTERM kills its processes after
# a second); every process stops after the same increment, and the
# out-of-core directory is left empty.
set -u
program=$1
scene=$2
dir=$3
processes=${4:-1}
rm -rf "$dir"
mkdir -p "$dir"
# Many small increments: the run is still going when the signal comes.
sets=(--set "Load program/Stage increments=100000"
      --set "Output/VTU interval=0" --set "Output/Progress=true"
      --set "Output/Directory=$dir/run")
launch=()
if [ "$processes" -gt 1 ]; then
  launch=(mpirun --allow-run-as-root --oversubscribe -np "$processes")
  sets+=(--set "Linear solver/Factors out of core=true"
         --set "Linear solver/Out-of-core directory=$dir/factors")
  export OMPI_MCA_btl_vader_single_copy_mechanism=none
  export OMPI_MCA_mpi_yield_when_idle=1
fi
"${launch[@]}" "$program" "$scene" "${sets[@]}" > "$dir/run.log" 2> "$dir/run.err" &
pid=$!
for i in $(seq 1 600); do
  grep -q "^increment *3/" "$dir/run.log" 2> /dev/null && break
  sleep 0.05
done
if [ "$processes" -gt 1 ]; then
  pkill -TERM -P $pid
else
  kill -TERM $pid
fi
wait $pid
status=$?
cat "$dir/run.err"
if [ $status -ne 5 ]; then
  echo "exit code $status after SIGTERM, expected 5"
  exit 1
fi
if ! grep -q "SIGTERM received: stopped after increment [0-9]* of 100000" "$dir/run.err"; then
  echo "no message naming the signal and the increment"
  exit 1
fi
stopped=$(sed -n 's/.*stopped after increment \([0-9]*\) of.*/\1/p' "$dir/run.err")
if [ ! -f "$dir/run/checkpoint.bin" ] || ! grep -q "stopped by SIGTERM" "$dir/run/summary.txt"; then
  echo "no checkpoint or summary written on SIGTERM"
  exit 1
fi
rows=$(wc -l < "$dir/run/history.csv")
if [ "$rows" -ne $((stopped + 2)) ]; then
  echo "history.csv has $rows lines after increment $stopped"
  exit 1
fi
# The restart continues after that increment (one more, then a planned stop).
"${launch[@]}" "$program" "$scene" "${sets[@]}" --restart \
  --set "Checkpoint/Stop after increment=$((stopped + 1))" > "$dir/restart.log" 2>&1
status=$?
if [ $status -ne 0 ] || ! grep -q "restart after increment $stopped " "$dir/restart.log"; then
  echo "the restart failed (exit $status):"
  cat "$dir/restart.log"
  exit 1
fi
if [ "$processes" -gt 1 ] && [ -n "$(ls -A "$dir/factors")" ]; then
  echo "out-of-core files left in $dir/factors: $(ls "$dir/factors")"
  exit 1
fi
echo "stopped by SIGTERM after increment $stopped, exit 5, restarted from it"

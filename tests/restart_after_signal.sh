#!/bin/bash
# SIGTERM (what a batch scheduler sends at its time limit) during a run:
# the increment being solved is finished, a checkpoint of it is written,
# and the run stops with exit code 5 and a message; --restart continues
# from that increment. Usage: restart_after_signal.sh glissade scene.prm dir
set -u
program=$1
scene=$2
dir=$3
rm -rf "$dir"
mkdir -p "$dir"
# Many small increments: the run is still going when the signal comes.
sets=(--set "Load program/Stage increments=100000"
      --set "Output/VTU interval=0" --set "Output/Progress=true"
      --set "Output/Directory=$dir/run")
"$program" "$scene" "${sets[@]}" > "$dir/run.log" 2> "$dir/run.err" &
pid=$!
for i in $(seq 1 600); do
  grep -q "^increment *3/" "$dir/run.log" 2> /dev/null && break
  sleep 0.05
done
kill -TERM $pid
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
"$program" "$scene" "${sets[@]}" --restart \
  --set "Checkpoint/Stop after increment=$((stopped + 1))" > "$dir/restart.log" 2>&1
status=$?
if [ $status -ne 0 ] || ! grep -q "restart after increment $stopped " "$dir/restart.log"; then
  echo "the restart failed (exit $status):"
  cat "$dir/restart.log"
  exit 1
fi
echo "stopped by SIGTERM after increment $stopped, exit 5, restarted from it"

#!/bin/bash
# The peers' rings on one process and under mpirun on N (doc/parallel.md):
# prints, for each run, glissade's summary line, the wall time and the peak
# memory of each process, then the speed-up and the memory ratio.
#
#   benchmarks/processes_rings.sh PROGRAM [CELLS_AROUND [CELLS_RADIAL [N
#                                 [ARGUMENTS...]]]]
#
# Defaults: 800 x 80 cells per ring (259,200 dofs), N = 2. The issue's row
# is 1600 160 (1,030,400 dofs: 1.5 minutes a run here). ARGUMENTS go to
# the run on N processes alone: --set "Linear solver/Factors out of
# core=true" for MUMPS's factors in files.
set -euo pipefail
program=${1:?usage: processes_rings.sh PROGRAM [AROUND [RADIAL [N]]]}
around=${2:-800}
radial=${3:-80}
n=${4:-2}
shift $(($# < 4 ? $# : 4))
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=(
  "$here/peers/glissade_rings.prm"
  --set "Body inner/Mesh/Subdivisions=$around,$radial"
  --set "Body outer/Mesh/Subdivisions=$around,$radial"
  --set "Body outer/Boundary conditions/Nodal loads=outer: -0.4/$around*x/sqrt(x^2+y^2)*t, -0.4/$around*y/sqrt(x^2+y^2)*t"
  --set "Output/VTU interval=0")

# One run: its summary line, and per process "wall_seconds peak_kB".
run() {
  local label=$1
  shift
  "$@" > "$work/$label.log" 2>&1
  grep '^glissade:' "$work/$label.log" | head -1
}
# (GNU time has no per-rank file name: a wrapper writes one per process)
cat > "$work/timed.sh" <<WRAP
#!/bin/bash
exec /usr/bin/time -f '%e %M' -o "$work/time.\${OMPI_COMM_WORLD_RANK:-one}" "\$@"
WRAP
chmod +x "$work/timed.sh"

run one "$work/timed.sh" "$program" "${scene[@]}" \
  --set "Output/Directory=$work/one"
read -r one_wall one_peak < "$work/time.one"
run many mpirun --allow-run-as-root --oversubscribe -np "$n" \
  "$work/timed.sh" "$program" "${scene[@]}" --set "Output/Directory=$work/many" \
  "$@"
many_wall=0
many_peak=0
for f in "$work"/time.[0-9]*; do
  read -r wall peak < "$f"
  many_wall=$(python3 -c "print(max($many_wall, $wall))")
  many_peak=$(python3 -c "print(max($many_peak, $peak))")
done
python3 - "$one_wall" "$one_peak" "$many_wall" "$many_peak" "$n" <<'PY'
import sys
one_wall, one_peak, many_wall, many_peak, n = map(float, sys.argv[1:])
print(f"1 process: {one_wall:.1f} s, peak {one_peak / 1e6:.2f} GB")
print(f"{n:.0f} processes: {many_wall:.1f} s, largest peak {many_peak / 1e6:.2f} GB")
print(f"speed-up {one_wall / many_wall:.2f}, memory per process "
      f"{many_peak / one_peak:.2f} of one process's")
PY
# (at 1e-8: at a million dofs one process differs from itself with one
# thread instead of two by 7.9e-10 on the contact forces)
python3 "$here/../tests/compare_processes.py" "$work/one" "$work/many" \
  --tolerance=1e-8 | tail -1

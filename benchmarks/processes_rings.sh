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
#
# ONE_THREAD=1 before the command holds every process to one thread
# (OMP_NUM_THREADS, OPENBLAS_NUM_THREADS, DEAL_II_NUM_THREADS): the
# speed-up printed is then core for core, N processes against one on one
# core (on a machine of two cores, one process otherwise uses both).
#
# Also printed: each process's resident memory after the phases of a
# Newton iteration (GLISSADE_DEBUG's memory lines, the largest over the
# iterations; the model of doc/parallel.md is checked against them), and
# the bytes each process sends per Newton iteration, counted by Open MPI's
# monitoring (pml_monitoring_enable 2: every message at the transport,
# those of the collectives included, MUMPS's too) in the run on N
# processes and in a second one whose load takes two increments: their
# difference over the difference of their Newton iterations leaves out
# the set-up (and counts a detection and an output per increment in).
set -euo pipefail
program=${1:?usage: processes_rings.sh PROGRAM [AROUND [RADIAL [N]]]}
around=${2:-800}
radial=${3:-80}
n=${4:-2}
shift $(($# < 4 ? $# : 4))
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
threads=()
if [ "${ONE_THREAD:-0}" = 1 ]; then
  export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 DEAL_II_NUM_THREADS=1
  threads=(-x OMP_NUM_THREADS -x OPENBLAS_NUM_THREADS -x DEAL_II_NUM_THREADS)
fi
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

# (an MPI without Open MPI's monitoring component runs without it, and the
# bytes are not printed)
monitoring=()
if ompi_info 2>/dev/null | grep -q "pml: monitoring"; then
  monitoring=(--mca pml_monitoring_enable 2 --mca pml_monitoring_enable_output 3)
fi
monitored() {
  local label=$1
  shift
  mpirun --allow-run-as-root --oversubscribe -np "$n" -x GLISSADE_DEBUG=1 \
    "${threads[@]}" "${monitoring[@]}" \
    ${monitoring:+--mca pml_monitoring_filename "$work/sent.$label"} "$@"
}
run one env GLISSADE_DEBUG=1 "$work/timed.sh" "$program" "${scene[@]}" \
  --set "Output/Directory=$work/one"
read -r one_wall one_peak < "$work/time.one"
run many monitored many \
  "$work/timed.sh" "$program" "${scene[@]}" --set "Output/Directory=$work/many" \
  "$@"
run twice monitored twice "$program" "${scene[@]}" \
  --set "Output/Directory=$work/twice" --set "Load program/Stage increments=2" \
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
python3 - "$work" "$n" <<'PY'
import glob, re, sys
work, n = sys.argv[1], int(sys.argv[2])
phases = ["the assembly", "the factorisations", "the contact correction"]
for label, who in (("one", "1 process"), ("many", f"{n} processes")):
    resident = {}
    for line in open(f"{work}/{label}.log"):
        m = re.search(r"memory after (.*) \(process (\d+)\): resident ([0-9.]+)", line)
        if m:
            key = (m.group(1), int(m.group(2)))
            resident[key] = max(resident.get(key, 0.), float(m.group(3)))
    ranks = sorted({p for _, p in resident})
    print(f"{who}, resident after " + ", ".join(
        f"{phase}: " + " / ".join(f"{resident.get((phase, p), 0.):.2f}"
                                  for p in ranks) + " GB"
        for phase in phases))
def sent(label):
    total = {}
    for path in glob.glob(f"{work}/sent.{label}.*.prof"):
        rank = int(path.split(".")[-2])
        total[rank] = sum(int(m.group(1)) for m in re.finditer(
            r"^[EI]\t\d+\t\d+\t(\d+) bytes", open(path).read(), re.M))
    return total
def iterations(label):
    for line in open(f"{work}/{label}.log"):
        m = re.match(r"glissade: .*?(\d+) Newton iterations", line)
        if m:
            return int(m.group(1))
once, twice = sent("many"), sent("twice")
extra = iterations("twice") - iterations("many")
if extra > 0 and once and twice:
    print(f"{n} processes, bytes sent per Newton iteration: " + ", ".join(
        f"process {p} {(twice[p] - once[p]) / extra / 1e6:.1f} MB"
        for p in sorted(once)) +
        f" ({iterations('many')} and {iterations('twice')} iterations)")
PY
# (at 1e-8: at a million dofs one process differs from itself with one
# thread instead of two by 7.9e-10 on the contact forces)
python3 "$here/../tests/compare_processes.py" "$work/one" "$work/many" \
  --tolerance=1e-8 | tail -1

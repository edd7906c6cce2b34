#!/usr/bin/python3
"""The reference files of the scene tests (tests/CMakeLists.txt,
glissade_scene_test ... COMPARE), written from closed forms, symmetries and
balance laws, never from a run of glissade. Run it after changing one:

    /usr/bin/python3 tests/reference/make_references.py

Each file holds only the columns and rows its test compares (the test
selects them from the output with --columns and --rows); the tolerance is
stated where the test is declared.
"""
import math
import pathlib

HERE = pathlib.Path(__file__).resolve().parent


def write(name, header, rows):
    lines = [",".join(header)]
    lines += [",".join(f"{v:.17g}" if isinstance(v, float) else str(v)
                       for v in row) for row in rows]
    (HERE / name).write_text("\n".join(lines) + "\n")


def chord_gap_percent(n):
    """A half circle in n facets: each spans pi/n, and its chord misses the
    circle by R (1 - cos(pi/(2 n))) at its middle."""
    return 100. * (1. - math.cos(math.pi / (2. * n)))


# The geometric study (prm/geometric_study.prm: a half ring's outer edge in
# n_e elements): Q4's largest gap error, its normal error at a facet's end,
# pi/(2 n_e) in degrees, and the jump between facets, twice that.
write("geometric_q4_chord.csv",
      ["method", "n_e", "max_gap_error_percent", "max_normal_error_degrees",
       "normal_jump_degrees"],
      [["q4", n, chord_gap_percent(n), 90. / n, -180. / n]
       for n in range(16, 31, 2)])

# The trade study's geometric measures on its Q4 sweep
# (tests/data/trade_study_small.prm: 8 16 32 64 elements).
write("trade_q4_chord_gap.csv", ["discretisation", "n", "error"],
      [["q4", n, chord_gap_percent(n)] for n in (8, 16, 32, 64)])
write("trade_q4_chord_normal.csv", ["discretisation", "n", "error"],
      [["q4", n, 90. / n] for n in (8, 16, 32, 64)])

# Case 3 with mortar: each slave node's force lies along its nodal normal,
# radial on the inner ring, so the contact forces' torque about the centre
# is zero: 10 compression and 10 rotation increments.
write("case3_mortar_no_torque.csv", ["variant", "torque_percent"],
      [["mortar", 0] for _ in range(20)])

# Case 1 on the rigid ring: no slave node inside the ring (the distance to
# the circle, compared with numdiff -N: 0 or above), 10 increments.
write("case1_rigid_no_penetration.csv",
      ["variant", "increment", "min_obstacle_distance"],
      [["q4", k, 0] for k in range(1, 11)])

# Case 2's symmetric configuration: the mirror images' displacements and
# forces equal, 10 increments for each variant of the test.
write("case2_mirror_symmetry.csv",
      ["variant", "increment", "symmetry_displacement", "symmetry_force"],
      [[v, k, 0, 0] for v in ("q4", "bspline") for k in range(1, 11)])

# Case 3's rings closed without load: no contact force (increments 0-2).
write("at_rest_no_contact_force.csv",
      ["increment", "interface_Fx", "interface_Fy"],
      [[k, 0, 0] for k in range(3)])

// The mesh generators and the Gmsh reader, against closed forms.

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/body/body_measures.h>
#include <glissade/mesh/mesh_diameter.h>
#include <glissade/mesh/mesh_factory.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <iomanip>
#include <iterator>
#include <map>
#include <set>
#include <vector>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  std::string
  ring_scene(const std::string &type, const unsigned int n_around)
  {
    return "subsection Scene\n set Bodies = ring\nend\n"
           "subsection Body ring\n subsection Mesh\n  set Type = " +
           type +
           "\n  set Center = 0.3, -0.2\n"
           "  set Inner radius = 0.5\n  set Outer radius = 2\n"
           "  set Subdivisions = " +
           std::to_string(n_around) +
           ", 4\n end\n subsection Boundary conditions\n"
           "  set Fixed = inner: xy\n end\nend\n";
  }

  /**
   * A body read from a Gmsh file whose physical lines 'clamp' (x = 0) and
   * 'pull' are held in x and pulled by a unit traction; `materials` is the
   * text of its Material subsection(s).
   */
  std::string
  pulled_gmsh_body(const std::string &body,
                   const std::string &file,
                   const std::string &materials)
  {
    return "subsection Scene\n  set Bodies = " + body +
           "\nend\nsubsection Body " + body +
           "\n  subsection Mesh\n    set Type = gmsh\n    set File = " +
           source_path("tests/data/" + file) + "\n  end\n" + materials +
           R"(  subsection Boundary conditions
    set Fixed = clamp: x; point(0, 0): y
    set Tractions = pull: 1*t, 0
  end
end
subsection Newton
  set Residual tolerance = 1e-13
end
subsection Output
  set Progress = false
end
)";
  }
} // namespace

// A Q4 ring of n cells around is the annulus between two regular n-gons:
// area n/2 sin(2 pi/n) (r_o^2 - r_i^2), exactly.
GLISSADE_TEST(mesh_ring_area)
{
  for (const unsigned int n : {3u, 10u, 40u})
    {
      Simulation simulation(
        SceneReader::read_string(ring_scene("ring", n), "ring"));
      const double area =
        GridTools::volume(simulation.body("ring").triangulation());
      const double exact = 0.5 * n * std::sin(2 * M_PI / n) * (4. - 0.25);
      check_relative(area, exact, 1e-13, "ring area, n = " + std::to_string(n));
    }
  Simulation half(
    SceneReader::read_string(ring_scene("half ring", 40), "ring"));
  const double exact = 0.5 * 40 * std::sin(M_PI / 40) * (4. - 0.25);
  check_relative(GridTools::volume(half.body("ring").triangulation()),
                 exact,
                 1e-13,
                 "half ring area, 40 cells");
}

// Uniaxial tension of a plate read from a Gmsh file whose boundaries are
// named physical lines: u_x(L) = sigma L / E, u_y(H) = -nu sigma H / E
// (plane stress, small strain: the load keeps strains near 1e-6).
GLISSADE_TEST(mesh_gmsh_import)
{
  const std::string prm =
    pulled_gmsh_body("plate", "plate_2x1.msh", R"(  subsection Material
    set Young modulus = 1e6
    set Poisson ratio = 0.25
    set Hypothesis = plane stress
  end
)");
  Simulation simulation(SceneReader::read_string(prm, "gmsh plate"));
  simulation.advance_to(1., "increment 1");
  const Tensor<1, 2> u =
    vertex_displacement(simulation.body("plate"), Point<2>(2., 1.));
  check_relative(u[0], 1. * 2. / 1e6, 1e-5, "u_x at (2, 1)");
  check_relative(u[1], -0.25 * 1. * 1. / 1e6, 1e-5, "u_y at (2, 1)");
  check_relative(support_reaction(simulation.body("plate"), "clamp")[0],
                 -1.,
                 1e-9,
                 "reaction on 'clamp' (N)");
}

// A bar of two materials in series, read from a Gmsh file whose Physical
// Surfaces 'soft' (x < 1) and 'stiff' (x > 1) are material regions, pulled
// by a traction s at x = 2: u_x(1) = s / E_soft, u_x(2) = s (1 / E_soft +
// 1 / E_stiff) (nu = 0: uniaxial, no lateral mismatch; s / E ~ 1e-6 keeps
// the strains small). MSH 2.2 with the soft part on the body's own
// Material, MSH 4.1 with both parts listed as regions.
GLISSADE_TEST(mesh_gmsh_two_material_bar)
{
  for (const std::string version : {"v22", "v41"})
    {
      const bool        both_listed = version == "v41";
      const std::string prm         = pulled_gmsh_body(
        "bar",
        "two_material_bar_" + version + ".msh",
        std::string("  subsection Material\n    set Young modulus = ") +
          (both_listed ? "5e5" : "1e6") +
          "\n    set Poisson ratio = 0\n    set Hypothesis = plane stress\n"
                  "    set Regions = " +
          (both_listed ? "soft, stiff" : "stiff") +
          "\n  end\n  subsection Material stiff\n    set Young modulus = "
                  "3e6\n  end\n" +
          (both_listed ?
                     "  subsection Material soft\n    set Young modulus = 1e6\n  end\n" :
                     ""));
      std::cout << "MSH " << version << ":" << std::endl;
      Simulation simulation(SceneReader::read_string(prm, "two-material bar"));
      simulation.advance_to(1., "increment 1");
      const Body &bar = simulation.body("bar");
      check_relative(vertex_displacement(bar, Point<2>(1., 0.5))[0],
                     1. / 1e6,
                     1e-5,
                     "u_x at the interface x = 1");
      check_relative(vertex_displacement(bar, Point<2>(2., 1.))[0],
                     1. / 1e6 + 1. / 3e6,
                     1e-5,
                     "u_x at x = 2 (elongation)");
      check_relative(support_reaction(bar, "clamp")[0],
                     -1.,
                     1e-9,
                     "reaction (N)");
    }
}

// A thick cylinder under internal pressure p (plane strain, Lame): u_r(b) =
// (1 + nu) p a^2 / (E (b^2 - a^2)) ((1 - 2 nu) b + b^2 / b), a = 1, b = 2,
// on a quarter annulus of 4 x 2 cells read from second-order Gmsh files
// whose mid-side nodes lie on the arcs. Read with a quadratic space the arcs
// are followed (9-node MSH 4.1 with q2, 8-node MSH 2.2 with q8); the same
// corners as straight chords (first-order file, q8) give a body of another
// shape, whose error the curved ones must beat by far.
GLISSADE_TEST(mesh_gmsh_second_order_curved_edges)
{
  const double E = 1000., nu = 0.3, p = 0.01, a = 1., b = 2.;
  const double exact =
    (1. + nu) * p * a * a / (E * (b * b - a * a)) * ((1. - 2. * nu) * b + b);
  const auto run = [&](const std::string &file, const std::string &space) {
    const std::string prm = R"(
subsection Scene
  set Bodies = ring
end
subsection Body ring
  subsection Mesh
    set Type = gmsh
    set File = )" + source_path("tests/data/" + file) +
                            R"(
  end
  subsection Element
    set Space = )" + space + R"(
  end
  subsection Material
    set Young modulus = 1000
    set Poisson ratio = 0.3
  end
  subsection Boundary conditions
    set Fixed = x0: x; y0: y
    set Pressure = inner: 0.01*t
  end
end
subsection Newton
  set Residual tolerance = 1e-12
end
subsection Output
  set Progress = false
end
)";
    Simulation simulation(SceneReader::read_string(prm, file));
    simulation.advance_to(1., "increment 1");
    const Body  &ring = simulation.body("ring");
    const double u_x  = vertex_displacement(ring, Point<2>(2., 0.))[0];
    const double u_y  = vertex_displacement(ring, Point<2>(0., 2.))[1];
    std::cout << "  " << file << " (" << space << "): u_r(2) = " << u_x
              << " at theta = 0, " << u_y << " at theta = pi/2; Lame " << exact
              << std::endl;
    return std::max(std::abs(u_x - exact), std::abs(u_y - exact)) / exact;
  };
  const double q8     = run("quarter_annulus_q8_v22.msh", "q8");
  const double q2     = run("quarter_annulus_q9_v41.msh", "q2");
  const double chords = run("quarter_annulus_chords_v22.msh", "q8");
  std::cout << "  relative errors: q8 " << q8 << ", q2 " << q2 << ", chords "
            << chords << std::endl;
  check(q8 < 2e-3 && q2 < 2e-3,
        "a curved quadratic mesh is off Lame by more than 0.2 %");
  check(chords > 10. * std::max(q8, q2),
        "the curved edges do not change the answer: are they read?");
}



// The mesh diameter from the boundary's convex hull is deal.II's, to the
// bit, on a ring (two boundaries, the inner one inside the hull), a
// randomly distorted rectangle and an L (a boundary that is not convex).
GLISSADE_TEST(mesh_diameter_is_deal_ii_s)
{
  std::vector<std::pair<std::string, Triangulation<2>>> meshes;
  {
    Triangulation<2> ring;
    GridGenerator::hyper_shell(ring, Point<2>(0.3, -0.2), 0.5, 2., 40);
    ring.refine_global(2);
    meshes.emplace_back("ring", std::move(ring));
  }
  {
    Triangulation<2> rectangle;
    GridGenerator::subdivided_hyper_rectangle(rectangle,
                                              {37, 11},
                                              Point<2>(-1, 0),
                                              Point<2>(3, 0.7));
    GridTools::distort_random(0.3, rectangle, true, 7);
    meshes.emplace_back("distorted rectangle", std::move(rectangle));
  }
  {
    Triangulation<2> l_shape;
    GridGenerator::hyper_L(l_shape, -1., 1.);
    l_shape.refine_global(4);
    meshes.emplace_back("L", std::move(l_shape));
  }
  for (const auto &[name, mesh] : meshes)
    {
      const double ours   = mesh_diameter(mesh),
                   theirs = GridTools::diameter(mesh);
      std::cout << "  " << name << ": " << mesh.n_vertices()
                << " vertices, diameter " << std::setprecision(17) << ours
                << " (deal.II " << theirs << ")" << std::endl;
      check(ours == theirs, name + ": the same diameter as deal.II's");
    }
}



// A Gmsh file that lists the 16 x 8 cells of [0, 2] x [0, 1] scrambled
// (tests/data/make_scrambled_block_mesh.py) is read with its cells along
// a Hilbert curve of the square [0, 2]^2 around it, which walks each
// quadrant whole from one cell to its neighbour: the first 64 cells are one
// half of the block (x < 1 or x > 1, a quadrant of the square), and every
// cell but one (the step from one quadrant to the other) shares a face
// with the next. The body is the file's (area 2, the named boundaries'
// faces 8, 8, 16, 16).
GLISSADE_TEST(mesh_gmsh_cells_along_hilbert_curve)
{
  const std::string prm = R"(
subsection Scene
  set Bodies = block
end
subsection Body block
  subsection Mesh
    set Type = gmsh
    set File = )" + source_path("tests/data/block_16x8_scrambled.msh") +
                          R"(
  end
  subsection Boundary conditions
    set Fixed = left: all
  end
end
subsection Output
  set Progress = false
end
)";
  Simulation              simulation(SceneReader::read_string(prm, "block"));
  const Triangulation<2> &mesh = simulation.body("block").triangulation();
  check(mesh.n_active_cells() == 128, "128 cells");
  std::vector<Triangulation<2>::active_cell_iterator> cells;
  for (const auto &cell : mesh.active_cell_iterators())
    cells.push_back(cell);
  const bool   first_left = cells[0]->center()[0] < 1.;
  unsigned int misplaced = 0, steps_apart = 0;
  for (std::size_t c = 0; c < cells.size(); ++c)
    {
      if ((c < 64) != ((cells[c]->center()[0] < 1.) == first_left))
        ++misplaced;
      if (c > 0)
        {
          bool touching = false;
          for (const unsigned int f : cells[c]->face_indices())
            touching = touching || (!cells[c]->at_boundary(f) &&
                                    cells[c]->neighbor(f) == cells[c - 1]);
          steps_apart += touching ? 0 : 1;
        }
    }
  std::cout << "  cells on the wrong side of x = 1 for their place: "
            << misplaced << "; cells not beside the one before: " << steps_apart
            << std::endl;
  check(misplaced == 0, "the first 64 cells are not one half of the block");
  check(steps_apart <= 1,
        "more than one cell does not share a face with the one before");
  check_relative(GridTools::volume(mesh), 2., 1e-14, "area");
  std::map<types::boundary_id, unsigned int> faces;
  for (const auto &cell : mesh.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary())
        ++faces[face->boundary_id()];
  check(faces[1] == 8 && faces[2] == 8 && faces[3] == 16 && faces[4] == 16,
        "the faces of left, right, bottom, top are not 8, 8, 16, 16");
}



// Mesh/Grading: sizes in geometric progression, the last `ratio` times the
// first, summing to the side (closed form: the first of n is L (q - 1) /
// (q^n - 1), q = ratio^(1 / (n - 1))). Q4 cells of a rectangle, the knot
// spans of its NURBS patch and of a patch file's elements alike; a ring,
// which has no grid of intervals, refuses it with the entry.
GLISSADE_TEST(mesh_grading)
{
  const auto body = [](const std::string &mesh) {
    return SceneReader::read_string("subsection Scene\n set Bodies = b\nend\n"
                                    "subsection Body b\n subsection Mesh\n" +
                                      mesh +
                                      "\n end\n subsection Boundary "
                                      "conditions\n  set Fixed = left: xy\n"
                                      " end\nend\n",
                                    "graded.prm")
      .bodies[0]
      .mesh;
  };
  const auto check_progression = [](std::vector<double> sizes,
                                    const double        length,
                                    const double        ratio,
                                    const std::string  &what) {
    const unsigned int n = sizes.size();
    const double       q = std::pow(ratio, 1. / (n - 1.));
    check_relative(sizes.front(),
                   ratio == 1. ? length / n :
                                 length * (q - 1.) / (std::pow(q, n) - 1.),
                   1e-12,
                   what + ": the first size");
    for (unsigned int i = 1; i < n; ++i)
      check_relative(sizes[i] / sizes[i - 1], q, 1e-10, what + ": growth");
  };

  const MeshDescription rectangle =
    body("  set Type = rectangle\n  set Corner 1 = 0, 0\n"
         "  set Corner 2 = 2, 1\n  set Subdivisions = 6, 4\n"
         "  set Grading = 8, 0.5");
  Triangulation<2> mesh;
  MeshFactory::create(rectangle, mesh, "graded.prm");
  std::set<double> x, y;
  for (const auto &vertex : mesh.get_vertices())
    {
      x.insert(vertex[0]);
      y.insert(vertex[1]);
    }
  std::vector<double> widths, heights;
  for (auto i = x.begin(); std::next(i) != x.end(); ++i)
    widths.push_back(*std::next(i) - *i);
  for (auto i = y.begin(); std::next(i) != y.end(); ++i)
    heights.push_back(*std::next(i) - *i);
  check(widths.size() == 6 && heights.size() == 4, "6 by 4 cells");
  check_progression(widths, 2., 8., "Q4 rectangle, x");
  check_progression(heights, 1., 0.5, "Q4 rectangle, y");

  const auto spans = [](const BSplineBasis &basis) {
    std::vector<double> sizes;
    for (unsigned int s = 0; s < basis.n_spans(); ++s)
      sizes.push_back(basis.span_range(s)[1] - basis.span_range(s)[0]);
    return sizes;
  };
  const NurbsPatch patch = MeshFactory::type("rectangle")
                             .exact_patch(rectangle, 2, "graded.prm")
                             .patches.front();
  check_progression(spans(patch.xi), 1., 8., "NURBS rectangle, xi");
  check_progression(spans(patch.eta), 1., 0.5, "NURBS rectangle, eta");

  const MeshDescription file =
    body("  set Type = nurbs patch\n  set File = " +
         source_path("prm/meshes/quarter_annulus.nurbs") +
         "\n  set Subdivisions = 5, 3\n  set Grading = 3, 1");
  const NurbsPatch from_file = MeshFactory::type("nurbs patch")
                                 .exact_patch(file, 2, "graded.prm")
                                 .patches.front();
  check_progression(spans(from_file.xi), 1., 3., "patch file, xi");
  check_progression(spans(from_file.eta), 1., 1., "patch file, eta");

  for (const auto &[mesh_text, expected] :
       std::vector<std::pair<std::string, std::string>>{
         {"  set Type = ring\n  set Grading = 2, 1",
          "Mesh/Grading: applies to Type = rectangle, square and nurbs patch "
          "(this mesh is a ring)"},
         {"  set Type = rectangle\n  set Grading = 1, 0",
          "Mesh/Grading: each ratio must lie between 1e-4 and 1e4"}})
    {
      std::string message = "accepted";
      try
        {
          body(mesh_text);
        }
      catch (const InputError &e)
        {
          message = e.what();
        }
      std::cout << "  " << message << std::endl;
      check(message.find(expected) != std::string::npos,
            "the message does not say '" + expected + "'");
    }
}

// The mesh generators and the Gmsh reader, against closed forms.

#include <deal.II/grid/grid_tools.h>

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include "test_tools.h"

#include <cmath>

using namespace glissade;
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
  Simulation half(SceneReader::read_string(ring_scene("half ring", 40), "ring"));
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
  const std::string prm = R"(
subsection Scene
  set Bodies = plate
end
subsection Body plate
  subsection Mesh
    set Type = gmsh
    set File = )" + source_path("tests/data/plate_2x1.msh") +
                          R"(
  end
  subsection Material
    set Young modulus = 1e6
    set Poisson ratio = 0.25
    set Hypothesis = plane stress
  end
  subsection Boundary conditions
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
  Simulation simulation(SceneReader::read_string(prm, "gmsh plate"));
  simulation.advance_to(1., "increment 1");
  const Tensor<1, 2> u = simulation.body("plate").vertex_displacement(
    Point<2>(2., 1.));
  check_relative(u[0], 1. * 2. / 1e6, 1e-5, "u_x at (2, 1)");
  check_relative(u[1], -0.25 * 1. * 1. / 1e6, 1e-5, "u_y at (2, 1)");
  check_relative(simulation.body("plate").reaction("clamp")[0],
                 -1.,
                 1e-9,
                 "reaction on 'clamp' (N)");
}

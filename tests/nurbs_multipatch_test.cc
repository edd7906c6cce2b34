// NURBS bodies of several patches joined C0 (Mesh/Type = nurbs patch with
// a file of several patches, issue 52): the same space as one patch with a
// knot repeated p times gives the same answer (elasticity and contact
// across the join), the patch test across joins that run against each
// other and join an xi side to an eta side, and the files that are refused.

#include <deal.II/dofs/dof_tools.h>

#include <glissade/body/body_measures.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "nurbs_scene.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /** A body of the patch file `file` (subdivided `n_xi` by `n_eta`). */
  std::string
  file_mesh(const std::string &file,
            const unsigned int n_xi,
            const unsigned int n_eta,
            const std::string &more = "")
  {
    return "  set Type = nurbs patch\n  set File = " + source_path(file) +
           "\n  set Subdivisions = " + std::to_string(n_xi) + ", " +
           std::to_string(n_eta) + more;
  }

  /** The quarter annulus 1 < r < 2 in a rigid hole of radius 2 - 1e-3,
   *  held by its symmetry planes: contact along its outer side. */
  std::string
  ring_in_hole(const std::string &file, const std::string &discretisation)
  {
    return "subsection Scene\n set Bodies = ring\n set Contact pairs = fit\n"
           "end\nsubsection Body ring\n subsection Mesh\n" +
           file_mesh(file, 4, 8) +
           "\n end\n subsection Element\n  set Space = nurbs\n end\n"
           " subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n  set Kinematics = small strain\n"
           " end\n subsection Boundary conditions\n"
           "  set Fixed = start: y; end: x\n end\nend\n"
           "subsection Contact fit\n set Slave body = ring\n"
           " set Slave boundary = outer\n set Discretisation = " +
           discretisation +
           "\n set Alert distance = 0.05\n subsection Obstacle\n"
           "  set Type = hole\n  set Point = 0, 0\n  set Radius = 1.999\n"
           " end\nend\n"
           "subsection Contact solver\n set Tolerance = 1e-13\nend\n"
           "subsection Output\n set Progress = false\n set Plots = false\n"
           " set VTU interval = 0\n set Directory = output/multipatch_hole\n"
           "end\n"
           "subsection Newton\n set Residual tolerance = 1e-11\n"
           " set Displacement tolerance = 1e-11\nend\n";
  }

} // namespace



// The quarter annulus as two patches of 45 degrees joined C0 (and again
// with the second patch's parameters reversed, its side on the join
// running against the first's) spans the same functions as one patch
// whose two arcs a double knot joins C0: Lame's ring gives the same
// unknowns, displacements and errors on all three, to round-off, and
// converges at rate p + 1 = 3 on the two patches; the ring pressed into a
// rigid hole (mortar and knot-to-segment on its outer side, which crosses
// the join) gives the same contact forces and displacement, and Lame's.
GLISSADE_TEST(nurbs_multipatch_same_as_one_patch)
{
  const LameRing lame;
  const auto     u    = [&](const Point<2> &X) { return lame.u(X); };
  const auto     grad = [&](const Point<2> &X) { return lame.grad(X); };
  const std::vector<std::string> files = {
    "prm/meshes/quarter_annulus_c0.nurbs",
    "prm/meshes/quarter_annulus_two_patches.nurbs",
    "prm/meshes/quarter_annulus_two_patches_reversed.nurbs"};
  const std::vector<Point<2>>                 probes = {Point<2>(1., 0.),
                                                        Point<2>(0., 2.),
                                                        Point<2>(1.5 * std::cos(M_PI / 4),
                                                 1.5 * std::sin(M_PI / 4))};
  std::map<unsigned int, std::vector<double>> one_patch;
  for (const std::string &file : files)
    {
      std::vector<double> l2_errors;
      for (const unsigned int n : {2u, 4u, 8u})
        {
          Simulation simulation(SceneReader::read_string(
            nurbs_scene(file_mesh(file, n, n),
                        2,
                        "small strain",
                        " set Fixed = start: y; end: x\n"
                        " set Pressure = inner: 1e-4*t",
                        "multipatch_lame"),
            "multipatch"));
          simulation.advance_to(1., "increment 1");
          const Body &body   = simulation.body("ring");
          const auto  errors = relative_errors(body, u, grad, 5);
          l2_errors.push_back(errors.first);
          std::vector<double> figures = {double(body.n_unknowns()),
                                         errors.first,
                                         errors.second};
          for (const Point<2> &X : probes)
            for (unsigned int c = 0; c < 2; ++c)
              figures.push_back(vertex_displacement(body, X)[c]);
          std::cout << "  " << file.substr(file.rfind('/') + 1) << ", " << n
                    << " x " << 2 * n << " elements: " << body.n_unknowns()
                    << " unknowns, L2 error " << errors.first << ", H1 "
                    << errors.second;
          if (file == files[0])
            one_patch[n] = figures;
          else
            {
              check(figures[0] == one_patch[n][0],
                    "the patches have the one patch's unknowns");
              const double difference =
                largest_difference(figures, one_patch[n]);
              std::cout << "; off the one patch's figures by " << difference;
              check(difference < 1e-9,
                    "the patches give the one patch's figures");
            }
          std::cout << std::endl;
        }
      const double rate = std::log2(l2_errors[1] / l2_errors[2]);
      std::cout << "  L2 rate " << rate << " (theory 3)" << std::endl;
      check(std::abs(rate - 3.) < 0.3, "the L2 rate is off p + 1 = 3");
    }

  // Contact along a side that crosses the join: Lame's ring free inside,
  // u_r(2) = -1e-3 outside (a rigid hole).
  const double E = lame.E, nu = lame.nu, a = lame.a, b = lame.b;
  const double delta = 1e-3, lambda = E * nu / ((1. + nu) * (1. - 2. * nu)),
               mu       = E / (2. * (1. + nu));
  const double B_fit    = -delta / (b * mu / (a * a * (lambda + mu)) + 1. / b);
  const double A_fit    = mu * B_fit / (a * a * (lambda + mu));
  const double u_inside = A_fit * a + B_fit / a;
  for (const std::string discretisation : {"node-to-segment", "mortar"})
    {
      std::vector<double> reference;
      for (const std::string &file : {files[0], files[2]})
        {
          Simulation simulation(
            SceneReader::read_string(ring_in_hole(file, discretisation),
                                     "multipatch hole"));
          simulation.run();
          Tensor<1, 2> force;
          for (const auto &node :
               simulation.contact().contact_pairs()[0]->nodes())
            if (node.active)
              force += node.force();
          const double inside =
            vertex_displacement(simulation.body("ring"), Point<2>(1., 0.))[0];
          const std::vector<double> figures = {inside, force[0], force[1]};
          const double error = std::abs(inside - u_inside) / std::abs(u_inside);
          std::cout << "  " << discretisation << ", "
                    << file.substr(file.rfind('/') + 1) << ": u_r(1) " << inside
                    << " (Lame " << u_inside << ", relative error " << error
                    << "), contact force (" << force[0] << ", " << force[1]
                    << ")";
          if (reference.empty())
            reference = figures;
          else
            {
              const double difference = largest_difference(figures, reference);
              std::cout << "; off the one patch's by " << difference;
              check(difference < 1e-9,
                    discretisation + ": the patches give the one patch's "
                                     "contact");
            }
          std::cout << std::endl;
          if (discretisation == "mortar")
            check(error < 1e-4, "mortar: u_r(1) within 1e-4 of Lame");
        }
    }
}



// The patch test across joins: the L of three patches (one joined against
// the other's direction, one by its xi side to an eta side, a middle
// control point moved), an affine displacement prescribed on its outline,
// small and large strain: reproduced to round-off at the Gauss points and
// at the output's nodes; the unknowns those of 3 patches of 5 x 5 control
// points with the 2 joins' 5 once.
GLISSADE_TEST(nurbs_multipatch_patch_test)
{
  const std::string ux = affine_field_x, uy = affine_field_y;
  const auto        exact = affine_field;
  for (const std::string kinematics : {"small strain", "large strain"})
    {
      Simulation simulation(SceneReader::read_string(
        nurbs_scene(file_mesh("prm/meshes/l_shape_three_patches.nurbs", 3, 3),
                    2,
                    kinematics,
                    " set Prescribed displacement = outline: xy: " + ux + ", " +
                      uy,
                    "multipatch_l"),
        "L"));
      simulation.advance_to(1., "increment 1");
      const Body &body = simulation.body("ring");
      check(body.n_unknowns() == 2 * (3 * 25 - 2 * 5),
            "the unknowns are the body's distinct control points");
      const double worst = largest_nodal_error(body, exact);
      const auto   errors =
        relative_errors(body, exact, affine_field_gradient, 4);
      std::cout << "  " << kinematics << ": " << body.n_unknowns()
                << " unknowns, largest nodal error " << worst
                << " (the field reaches 0.08), relative L2 error "
                << errors.first << ", H1 " << errors.second << std::endl;
      check(worst < 1e-12 * 0.08 && errors.first < 1e-12 &&
              errors.second < 1e-11,
            kinematics + ": the patch test fails across the joins");
    }
}



// A file of several patches that is wrong stops with its file and what is
// wrong: no join where patches touch, joined sides that do not meet,
// weights or knots that differ along a join (Subdivisions and Grading that
// split an xi side and the eta side it is joined to differently), a side
// joined twice, a boundary on a joined side, a boundary line without its
// patches, a patch that is not there.
GLISSADE_TEST(nurbs_multipatch_file_errors)
{
  std::filesystem::create_directories("output/nurbs_bad_multipatch");
  const auto copy_of = [](const std::string &file) {
    std::ifstream in(source_path(file));
    return std::string((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
  };
  const std::string l_shape = copy_of("prm/meshes/l_shape_three_patches.nurbs");
  const std::string annulus =
    copy_of("prm/meshes/quarter_annulus_two_patches.nurbs");
  // (the last occurrence: the second patch's copy of a point on the join)
  const auto bad =
    [](std::string text, const std::string &from, const std::string &to) {
      const auto at = text.rfind(from);
      check(at != std::string::npos, "the file has '" + from + "'");
      text.replace(at, from.size(), to);
      const std::string path = "output/nurbs_bad_multipatch/" +
                               std::to_string(std::hash<std::string>()(text)) +
                               ".nurbs";
      std::ofstream(path) << text;
      return path;
    };
  const auto scene = [](const std::string &path, const std::string &more) {
    return nurbs_scene("  set Type = nurbs patch\n  set File = " + path +
                         "\n  set Subdivisions = 3, 3" + more,
                       2,
                       "small strain",
                       " set Fixed = " +
                         std::string(path.find("l_shape") != std::string::npos ?
                                       "outline" :
                                       "start") +
                         ": xy",
                       "bad_multipatch");
  };
  const std::string join = "join 1 xi1 2 xi1\njoin 1 eta1 3 xi1\n";
  for (const auto &[path, more, expected] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
         {bad(l_shape, join, ""),
          "",
          "patch 1's side xi1 touches patch 2 where no 'join' line joins "
          "them"},
         {bad(l_shape, join, "join 1 xi1 2 xi0\njoin 1 eta1 3 xi1\n"),
          "",
          "the join of patch 1's side xi1 and patch 2's side xi0: the sides "
          "do not meet"},
         {bad(l_shape, join, join + "join 2 xi1 3 xi1\n"),
          "",
          "patch 2's side xi1 is joined twice"},
         {bad(l_shape, "boundary outline 1 xi0", "boundary outline 1 xi1"),
          "",
          "patch 1's side xi1 is joined to another patch"},
         {bad(l_shape,
              "boundary outline 1 xi0 1 eta0 2 xi0 2 eta0 2 eta1 3 xi0 3 eta0 "
              "3 eta1",
              "boundary outline xi0"),
          "",
          "a file of several patches names the patch of each side"},
         {bad(l_shape, "join 1 eta1 3 xi1", "join 1 eta1 4 xi1"),
          "",
          "'4' is not a patch of the file (1 to 3)"},
         {bad(annulus,
              "1.0606601717798214 1.0606601717798212 1",
              "1.0606601717798214 1.0606601717798212 2"),
          "",
          "the join of patch 1's side eta1 and patch 2's side eta0: the "
          "weights of control point 2 along the sides are not in the "
          "proportion"},
         {source_path("prm/meshes/l_shape_three_patches.nurbs"),
          "\n  set Subdivisions = 2, 3",
          "the join of patch 1's side eta1 and patch 3's side xi1: the sides "
          "have 4 and 5 control points"},
         {source_path("prm/meshes/l_shape_three_patches.nurbs"),
          "\n  set Grading = 2, 1",
          "the join of patch 1's side eta1 and patch 3's side xi1: the knots "
          "along the sides differ"}})
    {
      const std::string message = refusal(scene(path, more));
      std::cout << "  " << message << std::endl;
      check(message.find(expected) != std::string::npos,
            "expected a message with '" + expected + "'");
      check(message.find(".nurbs") != std::string::npos,
            "the message names the file");
    }
}

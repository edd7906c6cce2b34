// Isogeometric bodies (Element/Space = nurbs, issue 52): the exact
// geometry of the patches, the patch test, Lame's ring converging at the
// rates of degree p, and what a NURBS body refuses.

#include <deal.II/base/quadrature_lib.h>

#include <glissade/base/input_error.h>
#include <glissade/body/body_measures.h>
#include <glissade/fe/nurbs_space.h>
#include <glissade/mesh/nurbs_patch.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <tuple>

#include "nurbs_scene.h"
#include "plane_strain_ring.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;


namespace
{
  /** The L2 and H1 rates of the last halving of h: p + 1 and p within
   *  `tolerance`. */
  void
  check_rates(const std::vector<std::pair<double, double>> &errors,
              const unsigned int                            degree,
              const double                                  tolerance)
  {
    const unsigned int k  = errors.size() - 1;
    const double       r0 = std::log2(errors[k - 1].first / errors[k].first);
    const double       r1 = std::log2(errors[k - 1].second / errors[k].second);
    std::cout << "  degree " << degree << ": rates L2 " << r0 << " (theory "
              << degree + 1 << "), H1 " << r1 << " (theory " << degree << ")"
              << std::endl;
    check(std::abs(r0 - (degree + 1)) <= tolerance, "the L2 rate is off p + 1");
    check(std::abs(r1 - degree) <= tolerance, "the H1 rate is off p");
  }
} // namespace

// The patches are the shapes: every point of a ring's patch lies on its
// circle of radius r(xi) (rational weights; no polynomial does this), the
// functions sum to one, their derivatives are the finite differences of
// their values, and the knots fall on the mesh types' vertices.
GLISSADE_TEST(nurbs_patches_are_exact)
{
  double worst_radius = 0., worst_sum = 0., worst_derivative = 0.,
         worst_vertex = 0.;
  for (const unsigned int degree : {2u, 3u, 4u})
    for (const bool closed : {false, true})
      {
        const Point<2>     c(0.3, -0.2);
        const unsigned int n_around = closed ? 10 : 5, n_through = 3;
        const double       t0 = closed ? 0. : 0.2, t1 = closed ? 2 * M_PI : 2.9;
        const NurbsPatch   patch = NurbsPatch::annulus(
          c, 1., 1.5, t0, t1, closed, degree, n_through, n_around);
        check(patch.xi.n_spans() == n_through &&
                patch.eta.n_spans() == n_around,
              "one span per cell");
        NurbsPatch::Evaluation e, ep;
        const double           h = 1e-6;
        for (unsigned int sv = 0; sv < n_around; ++sv)
          for (unsigned int su = 0; su < n_through; ++su)
            {
              const auto u = patch.xi.span_range(su);
              const auto v = patch.eta.span_range(sv);
              for (const double s : {0., 0.13, 0.5, 0.77, 1.})
                for (const double t : {0., 0.29, 0.61, 1.})
                  {
                    const double pu = u[0] + s * (u[1] - u[0]),
                                 pv = v[0] + t * (v[1] - v[0]);
                    patch.evaluate(su, sv, pu, pv, e);
                    const double r = 1. + 0.5 * (su + s) / n_through;
                    worst_radius   = std::max(worst_radius,
                                            std::abs((e.point - c).norm() - r));
                    double sum     = 0.;
                    for (const double R : e.values)
                      sum += R;
                    worst_sum = std::max(worst_sum, std::abs(sum - 1.));
                    // (central differences inside the span)
                    if (s > 0. && s < 1. && t > 0. && t < 1.)
                      for (unsigned int d = 0; d < 2; ++d)
                        {
                          const double du = d == 0 ? h : 0.,
                                       dv = d == 1 ? h : 0.;
                          NurbsPatch::Evaluation em;
                          patch.evaluate(su, sv, pu + du, pv + dv, ep);
                          patch.evaluate(su, sv, pu - du, pv - dv, em);
                          for (unsigned int k = 0; k < e.values.size(); ++k)
                            worst_derivative =
                              std::max(worst_derivative,
                                       std::abs((ep.values[k] - em.values[k]) /
                                                  (2 * h) -
                                                e.parametric_gradients[k][d]));
                        }
                    // the mesh's vertex at the span's corner
                    if ((s == 0. || s == 1.) && (t == 0. || t == 1.))
                      {
                        const double theta =
                          t0 + (t1 - t0) * (sv + t) / n_around;
                        const Point<2> vertex =
                          c + Tensor<1, 2>(
                                {r * std::cos(theta), r * std::sin(theta)});
                        worst_vertex =
                          std::max(worst_vertex, (e.point - vertex).norm());
                      }
                  }
            }
      }
  std::cout << "  largest |(|X - c| - r)|: " << worst_radius
            << "; largest |sum R - 1|: " << worst_sum
            << "; largest |dR - finite difference|: " << worst_derivative
            << "; largest distance of a knot point from its vertex: "
            << worst_vertex << std::endl;
  check(worst_radius < 1e-13, "a ring's patch leaves its circle");
  check(worst_sum < 1e-13, "the functions do not sum to one");
  check(worst_derivative < 1e-6, "the derivatives are not the values'");
  check(worst_vertex < 1e-12, "the knots are not at the mesh's vertices");
}

// The patch test: a displacement affine in x, y prescribed on the whole
// boundary is the answer everywhere inside, at small strain and at large
// strain (a uniform deformation gradient), for p = 2 and 3. On a distorted
// polynomial patch (weights 1: a rectangle, its inner control points
// moved) to 1e-12: Gauss's rule integrates the terms exactly. On a ring
// (rational weights) only to the rule's accuracy on rational functions,
// which is reported, and bounded by 1e-5.
GLISSADE_TEST(nurbs_patch_test)
{
  const std::string ux = affine_field_x, uy = affine_field_y;
  const auto        exact = affine_field;
  for (const bool ring : {false, true})
    for (const std::string kinematics : {"small strain", "large strain"})
      for (const unsigned int degree : {2u, 3u})
        {
          std::string conditions = " set Prescribed displacement = ";
          for (const std::string &side :
               ring ?
                 std::vector<std::string>{"inner", "outer", "start", "end"} :
                 std::vector<std::string>{"left", "right", "bottom", "top"})
            conditions += side + ": xy: " + ux + ", " + uy + "; ";
          conditions.resize(conditions.size() - 2);
          const std::string label = std::string(ring ? "ring" : "rectangle") +
                                    std::to_string(degree) + kinematics[0];
          Simulation simulation(SceneReader::read_string(
            ring ? quarter_ring(degree, 5, 3, kinematics, conditions, label) :
                   nurbs_scene("  set Type = rectangle\n"
                               "  set Corner 1 = -0.5, 0.2\n"
                               "  set Corner 2 = 1.5, 1.2\n"
                               "  set Subdivisions = 6, 4\n"
                               "  set Distortion = 0.3",
                               degree,
                               kinematics,
                               conditions,
                               label),
            "patch"));
          simulation.advance_to(1., "increment 1");
          const Body &body = simulation.body("ring");
          if (!ring)
            {
              // (the patch is distorted: its inner knot points are off the
              // regular 6 x 4 lattice)
              double off = 0.;
              for (const auto &X : body.triangulation().get_vertices())
                off = std::max(
                  off,
                  std::hypot(X[0] + 0.5 - std::round((X[0] + 0.5) * 3.) / 3.,
                             X[1] - 0.2 - std::round((X[1] - 0.2) * 4.) / 4.));
              std::cout << "  largest distance of a knot point from the "
                           "regular lattice: "
                        << off << std::endl;
              check(off > 0.01, "the patch is not distorted");
            }
          // The nodal view at every node of the output's elements...
          const double worst = largest_nodal_error(body, exact);
          // and at Gauss points, from the control points
          const auto errors =
            relative_errors(body, exact, affine_field_gradient, degree + 2);
          std::cout << "  " << label << ": largest nodal error " << worst
                    << " (the field reaches 0.08); relative L2 error "
                    << errors.first << ", H1 " << errors.second << std::endl;
          const double bound = ring ? 1e-5 : 1e-12;
          check(worst < bound * 0.08 && errors.first < bound &&
                  errors.second < 10 * bound,
                label + ": the patch test fails");
        }
}

// Lame's thick ring with its exact geometry: L2 errors at h^(p+1) and H1
// at h^p for p = 2 and 3 (small strain, a = 1, b = 2, E = 1000, nu = 0.3,
// plane strain, pressure 1e-4 inside; a quarter with symmetric supports).
GLISSADE_TEST(nurbs_lame_ring_rates)
{
  const LameRing lame;
  const auto     u    = [&](const Point<2> &X) { return lame.u(X); };
  const auto     grad = [&](const Point<2> &X) { return lame.grad(X); };
  for (const unsigned int degree : {2u, 3u})
    {
      std::vector<std::pair<double, double>> errors;
      const std::vector<unsigned int>        meshes = {2, 4, 8, 16};
      for (const unsigned int n : meshes)
        {
          Simulation simulation(SceneReader::read_string(
            quarter_ring(degree,
                         2 * n,
                         n,
                         "small strain",
                         " set Fixed = start: y; end: x\n"
                         " set Pressure = inner: 1e-4*t",
                         "lame_" + std::to_string(degree) + "_" +
                           std::to_string(n)),
            "lame"));
          simulation.advance_to(1., "increment 1");
          errors.push_back(
            relative_errors(simulation.body("ring"), u, grad, degree + 3));
          std::cout << "  degree " << degree << ", " << 2 * n << " x " << n
                    << " elements, " << simulation.body("ring").n_unknowns()
                    << " unknowns: L2 error " << errors.back().first
                    << ", H1 error " << errors.back().second << std::endl;
        }
      check_rates(errors, degree, 0.25);
    }
}

// Lame's ring at large strain: the quarter ring 1 < R < 2 (neo-Hookean,
// plane strain) under an inner follower pressure of 0.1 E (the inner wall
// stretched by 26 %, the answer 35 % off Lame's), against the plane-strain
// reference of the radial map r = f(R) (tests/plane_strain_ring.h: the
// ring's ordinary differential equation integrated to round-off), not the
// code's. The NURBS displacement converges to it at the rates of degree p.
GLISSADE_TEST(nurbs_large_strain_ring_rates)
{
  const double                    pressure = 100.;
  const PlaneStrainNeoHookeanRing ring(1000., 0.3, 1., 2., pressure);
  std::cout << "  reference: u_r(1) = " << ring.radius(1.) - 1.
            << ", u_r(2) = " << ring.radius(2.) - 2. << std::endl;
  const auto u = [&](const Point<2> &X) {
    const double R = X.norm();
    return (ring.radius(R) / R - 1.) * Tensor<1, 2>(X);
  };
  const auto grad = [&](const Point<2> &X) {
    const double       R = X.norm();
    const Tensor<1, 2> e_r({X[0] / R, X[1] / R}), e_t({-X[1] / R, X[0] / R});
    return (ring.radial_stretch(R) - 1.) * outer_product(e_r, e_r) +
           (ring.radius(R) / R - 1.) * outer_product(e_t, e_t);
  };
  for (const unsigned int degree : {2u, 3u})
    {
      std::vector<std::pair<double, double>> errors;
      for (const unsigned int n : {2u, 4u, 8u, 16u})
        {
          Simulation simulation(SceneReader::read_string(
            quarter_ring(degree,
                         2 * n,
                         n,
                         "large strain",
                         " set Fixed = start: y; end: x\n"
                         " set Pressure = inner: " +
                           std::to_string(pressure) + "*t",
                         "large_strain_lame_" + std::to_string(degree) + "_" +
                           std::to_string(n)),
            "large strain ring"));
          // four increments: Newton from the previous load's answer
          for (const double t : {0.25, 0.5, 0.75, 1.})
            simulation.advance_to(t, "increment");
          errors.push_back(
            relative_errors(simulation.body("ring"), u, grad, degree + 3));
          std::cout << "  degree " << degree << ", " << 2 * n << " x " << n
                    << " elements, " << simulation.body("ring").n_unknowns()
                    << " unknowns: L2 error " << errors.back().first
                    << ", H1 error " << errors.back().second << std::endl;
        }
      check_rates(errors, degree, 0.3);
      check(errors.back().first < 1e-4, "the finest L2 error is above 1e-4");
    }
}

// What a NURBS body does not take names the entry and why.
GLISSADE_TEST(nurbs_input_errors)
{
  const std::string ring = quarter_ring(
    2, 4, 2, "small strain", " set Fixed = start: y; end: x", "refused");
  const auto with = [&](const std::string &from, const std::string &to) {
    std::string scene = ring;
    const auto  at    = scene.find(from);
    check(at != std::string::npos, "the scene has '" + from + "'");
    return scene.replace(at, from.size(), to);
  };
  for (const auto &[scene, expected] :
       std::vector<std::pair<std::string, std::string>>{
         {nurbs_scene("  set Type = gmsh\n  set File = x.msh",
                      2,
                      "small strain",
                      " set Fixed = left: xy",
                      "gmsh"),
          "needs a mesh type with an exact geometry"},
         {with("set Space = nurbs\n  set Degree = 2",
               "set Space = q1\n  set Degree = 3"),
          "Element/Degree: applies to Space = nurbs only"},
         {with("set Fixed = start: y; end: x",
               "set Fixed = start: y; end: x; "
               "point(1.0606601717798212, 1.0606601717798212): x"),
          "is inside body 'ring', whose dofs are control points, not nodes: "
          "its point supports and loads act at points of its boundary"},
         {with("set Fixed = start: y; end: x", "set Fixed = start: y"),
          "a rigid-body motion is free (body 'ring': a translation along (1, "
          "0)). Its supports do not hold it, and there is no contact pair"}})
    {
      const std::string message = refusal(scene);
      std::cout << "  " << message << std::endl;
      check(message.find(expected) != std::string::npos,
            "expected a message with '" + expected + "'");
    }
}

// A patch read from a file (Mesh/Type = nurbs patch): the quarter annulus
// of prm/meshes/quarter_annulus.nurbs, its one element split by knot
// insertion, is Lame's ring again (the file's boundary names, L2 rate 3),
// and each mistake a file can hold is refused with its file and line or
// element.
GLISSADE_TEST(nurbs_patch_file)
{
  const LameRing    lame;
  const auto        u     = [&](const Point<2> &X) { return lame.u(X); };
  const auto        grad  = [&](const Point<2> &X) { return lame.grad(X); };
  const std::string file  = source_path("prm/meshes/quarter_annulus.nurbs");
  const auto        scene = [&](const std::string &patch_file,
                         const unsigned int n,
                         const unsigned int degree,
                         const std::string &label) {
    return nurbs_scene("  set Type = nurbs patch\n  set File = " + patch_file +
                         "\n  set Subdivisions = " + std::to_string(n) + ", " +
                         std::to_string(2 * n),
                       degree,
                       "small strain",
                       " set Fixed = start: y; end: x\n"
                              " set Pressure = inner: 1e-4*t",
                       label);
  };
  std::vector<double> errors;
  for (const unsigned int n : {4u, 8u})
    {
      Simulation simulation(
        SceneReader::read_string(scene(file, n, 2, "file_" + std::to_string(n)),
                                 "patch file"));
      simulation.advance_to(1., "increment 1");
      errors.push_back(
        relative_errors(simulation.body("ring"), u, grad, 5).first);
      std::cout << "  " << n << " x " << 2 * n
                << " elements: L2 error against Lame " << errors.back()
                << std::endl;
    }
  const double rate = std::log2(errors[0] / errors[1]);
  std::cout << "  L2 rate " << rate << " (theory 3)" << std::endl;
  check(errors[1] < 5e-4 && std::abs(rate - 3.) <= 0.3,
        "the file's ring is not Lame's");

  // Mistakes, each in a copy of the file.
  std::ifstream     in(file);
  const std::string good((std::istreambuf_iterator<char>(in)),
                         std::istreambuf_iterator<char>());
  std::filesystem::create_directories("output/nurbs_bad_files");
  const auto bad = [&](const std::string &from, const std::string &to) {
    std::string text = good;
    const auto  at   = text.find(from);
    check(at != std::string::npos, "the file has '" + from + "'");
    text.replace(at, from.size(), to);
    const std::string path = "output/nurbs_bad_files/" +
                             std::to_string(std::hash<std::string>()(to)) +
                             ".nurbs";
    std::ofstream(path) << text;
    return path;
  };
  for (const auto &[path, degree, expected] :
       std::vector<std::tuple<std::string, unsigned int, std::string>>{
         {bad("knots xi 0 0 0 1 1 1", "knots xi 0 0 0.5 0.2 1 1"),
          2,
          "knots xi: knot 4 is below the one before it"},
         {bad("knots eta 0 0 0 1 1 1", "knots eta 0 0 1 1 1 1"),
          2,
          "repeated degree + 1 = 3 times"},
         {bad("knots eta 0 0 0 1 1 1\n", "knots eta 0 0 0 0.5 0.5 0.5 1 1 1\n"),
          2,
          "the inner knot 0.5 is repeated 3 times, more than the degree"},
         {bad("2   2   0.7071067811865476", "2 2 -0.5"),
          2,
          "line 16: control point 6: the weight must be positive"},
         {bad("control points 3 3", "control points 4 3"),
          2,
          "control point 10: expected 'x y w'"},
         {bad("knots xi 0 0 0 1 1 1", "knots xi 0 0 0 0.5 1 1 1"),
          2,
          "control points: 3 along xi, where its 7 knots and degree 2 make "
          "4 functions"},
         {bad("boundary inner xi0", "boundary inner xi2"),
          2,
          "side 'xi2' is none of xi0, xi1, eta0, eta1"},
         {bad("degrees 2 2", "degree 2 2"), 2, "'degree' is not one of"},
         {bad("1   0   1\n1.5 0   1\n2   0   1",
              "2   0   1\n1.5 0   1\n1   0   1"),
          2,
          "the patch is inverted or folded in its element (0, 0)"},
         {file, 3, "Element/Degree: is 3, but the patch of"}})
    {
      std::string message = "accepted";
      try
        {
          Simulation simulation(
            SceneReader::read_string(scene(path, 1, degree, "bad_file"),
                                     "patch file"));
        }
      catch (const InputError &e)
        {
          message = e.what();
        }
      std::cout << "  " << message << std::endl;
      check(message.find(expected) != std::string::npos,
            "expected a message with '" + expected + "'");
    }
}

// prm/nurbs_ring.prm, as its header says: u_r at r = 1 and 2 within 1e-6
// of Lame's on 8 x 4 elements of degree 3, and the supports' balance: the
// 'start' side carries the pressure's resultant on the quarter, p a.
GLISSADE_TEST(nurbs_ring_scene)
{
  Simulation simulation(
    SceneReader::read_file(source_path("prm/nurbs_ring.prm"),
                           {"Output/Directory=output/nurbs_ring_scene",
                            "Output/Progress=false",
                            "Output/Plots=false"}));
  simulation.advance_to(1., "increment 1");
  const Body  &ring = simulation.body("ring");
  const double E = 1000., nu = 0.3, A = 1e-4 / 3., B = 4. * A;
  for (const double r : {1., 2.})
    check_relative(vertex_displacement(ring, Point<2>(r, 0.))[0],
                   (1. + nu) / E * ((1. - 2. * nu) * A * r + B / r),
                   1e-6,
                   "u_r(" + std::to_string(r) + ")");
  check_relative(support_reaction(ring, "start")[1],
                 -1e-4,
                 1e-10,
                 "the reaction of 'start'");
}

// A NURBS body under a dynamic scheme (consistent mass over the control
// points): the blade of prm/blade_casing.prm (5 x 100, clamped at y = 200,
// plane stress) as a patch of 2 x 20 elements of degree 2 and 3, launched
// in its first cantilever mode, swings at Euler-Bernoulli's omega_1 within
// 3 % (shear and rotary inertia: a few tenths of a percent; Newmark's
// trapezoidal rule at 40 steps a period: 0.2 %) and keeps its energy (the
// trapezoidal rule and Moreau-Jean's theta = 1/2 conserve it on a linear
// problem; at large strain to 1e-5 of it over ten periods).
GLISSADE_TEST(nurbs_blade_first_bending_frequency)
{
  const BladeFirstMode mode   = blade_first_mode(110000., 4.4e-9, 5.);
  const double         period = 2. * M_PI / mode.omega_1;
  for (const auto &[scheme, degree, mass] :
       std::vector<std::tuple<std::string, unsigned int, std::string>>{
         {"newmark", 2, "consistent"},
         {"newmark", 3, "consistent"},
         {"moreau-jean", 2, "consistent"},
         {"newmark", 2, "lumped"}})
    {
      const std::string scene =
        "subsection Scene\n set Bodies = blade\nend\n"
        "subsection Body blade\n subsection Mesh\n"
        "  set Type = rectangle\n  set Corner 1 = -2.5, 200\n"
        "  set Corner 2 = 2.5, 300\n  set Subdivisions = 2, 20\n end\n"
        " subsection Element\n  set Space = nurbs\n  set Degree = " +
        std::to_string(degree) +
        "\n end\n subsection Material\n  set Hypothesis = plane stress\n"
        "  set Young modulus = 110000\n  set Poisson ratio = 0.3\n"
        "  set Density = 4.4e-9\n end\n"
        " subsection Boundary conditions\n  set Fixed = bottom: xy\n end\n"
        " set Initial velocity = " +
        mode.shape +
        ", 0\nend\n"
        "subsection Time integration\n set Scheme = " +
        scheme +
        "\n set Newmark gamma = 0.5\n set Newmark beta = 0.25\n"
        " set Mass = " +
        mass +
        "\nend\n"
        "subsection Load program\n set Stage end times = " +
        std::to_string(10.5 * period) +
        "\n set Stage increments = 420\nend\n"
        "subsection Output\n set Progress = false\n set Plots = false\n"
        " set VTU interval = 0\n set Directory = output/nurbs_blade_" +
        scheme + std::to_string(degree) + mass +
        "\n set History = energies()\nend\n";
      Simulation    simulation(SceneReader::read_string(scene, "blade"));
      const Body   &blade    = simulation.body("blade");
      const auto    tip      = vertex_value_dofs(blade, Point<2>(0., 300.));
      double        energy_0 = 0., energy_drift = 0.;
      ZeroCrossings crossings;
      simulation.on_increment = [&](unsigned int, double t) {
        const double energy =
          blade.inertia()->kinetic_energy() + strain_energy(blade);
        if (t == 0. || energy_0 == 0.)
          energy_0 = energy;
        energy_drift = std::max(energy_drift, std::abs(energy - energy_0));
        crossings.record(t, blade.nodal_displacement()(tip[0]));
      };
      simulation.run();
      check(crossings.times.size() >= 20, "the tip did not swing ten times");
      const double measured = crossings.angular_frequency();
      std::cout << "  " << scheme << ", degree " << degree << ", " << mass
                << " mass: first bending frequency " << measured
                << " rad/s, Euler-Bernoulli " << mode.omega_1
                << " rad/s; largest energy change " << energy_drift / energy_0
                << " of " << energy_0 << std::endl;
      check_relative(measured, mode.omega_1, 0.03, "against Euler-Bernoulli's");
      check(energy_drift <= 1e-5 * energy_0, "the energy is not kept");
    }
}

// Points of a NURBS body's boundary held or loaded (point(x, y) supports,
// point loads, nodal loads), through the functions nonzero there: at a
// knot inside a side two or three control points carry the point.
// - A block under a uniform traction, held by its bottom in y and at the
//   bottom's middle point in x (a knot, not a control point): the affine
//   exact solution (plane strain, sigma_yy = -1) to round-off, and the
//   point support's reaction zero.
// - The block held by its bottom, loaded by a point load at a knot of its
//   top and by nodal loads on its top: the bottom's reaction balances them
//   (1e-10); held in x at one point only, that point's reaction is the
//   whole x load.
GLISSADE_TEST(nurbs_point_supports_and_loads)
{
  const std::string block = "  set Type = rectangle\n  set Corner 1 = 0, 0\n"
                            "  set Corner 2 = 2, 1\n  set Subdivisions = 4, 2";
  for (const unsigned int degree : {2u, 3u})
    {
      Simulation simulation(SceneReader::read_string(
        nurbs_scene(block,
                    degree,
                    "small strain",
                    "  set Fixed = bottom: y; point(1, 0): x\n"
                    "  set Tractions = top: 0, -1*t",
                    "point_support"),
        "point support"));
      simulation.advance_to(1., "increment 1");
      const Body  &body = simulation.body("ring");
      const double E = 1000., nu = 0.3;
      const double e_yy = -(1. - nu * nu) / E, e_xx = nu * (1. + nu) / E;
      double       error = 0.;
      for (const auto &X : body.triangulation().get_vertices())
        {
          const Tensor<1, 2> u = vertex_displacement(body, X);
          error                = std::max(
            error,
            (u - Tensor<1, 2>({e_xx * (X[0] - 1.), e_yy * X[1]})).norm() /
              std::abs(e_yy));
        }
      const Tensor<1, 2> at_point = support_reaction(body, "point(1, 0)");
      std::cout << "  p = " << degree
                << ": traction on a block held at point(1, 0) in x: largest "
                   "vertex error "
                << error << " of |e_yy|, the point's x reaction " << at_point[0]
                << std::endl;
      check(error <= 1e-10, "the affine solution is not exact");
      check(std::abs(at_point[0]) <= 1e-10, "the point support takes a force");

      Simulation loaded(SceneReader::read_string(
        nurbs_scene(block,
                    degree,
                    "small strain",
                    "  set Fixed = bottom: xy\n"
                    "  set Point loads = point(0.5, 1): 0.3*t, -1*t\n"
                    "  set Nodal loads = top: 0.1*t, -0.2*t",
                    "point_load"),
        "point load"));
      loaded.advance_to(1., "increment 1");
      const Tensor<1, 2> bottom =
        support_reaction(loaded.body("ring"), "bottom");
      // (five vertices on the top)
      const Tensor<1, 2> applied({0.3 + 5 * 0.1, -1. - 5 * 0.2});
      std::cout << "  p = " << degree << ": point and nodal loads " << applied
                << ", the bottom's reaction " << bottom << std::endl;
      check((bottom + applied).norm() <= 1e-10 * applied.norm(),
            "the bottom does not balance the loads");

      // Held in x at one point only: that point takes the whole x load.
      Simulation sheared(SceneReader::read_string(
        nurbs_scene(block,
                    degree,
                    "small strain",
                    "  set Fixed = bottom: y; point(1, 0): x\n"
                    "  set Point loads = point(1.5, 1): 0.5*t, 0",
                    "point_reaction"),
        "point reaction"));
      sheared.advance_to(1., "increment 1");
      const double held =
        support_reaction(sheared.body("ring"), "point(1, 0)")[0];
      std::cout << "  p = " << degree
                << ": x load 0.5 at the top, the x reaction at point(1, 0) "
                << held << std::endl;
      check(std::abs(held + 0.5) <= 1e-10, "the point support's reaction");
    }
}

// Contact with isogeometric bodies (Element/Space = nurbs): the master is
// the body's exact NURBS boundary (Surface = nurbs), a slave's points are
// its boundary's Greville points (knot-to-segment). Checked here against a
// uniform stress (the contact patch test on non-matching patches) and a
// balance law; the linearisation against finite differences is in
// contact_tangent_test.cc (contact_tangent_nurbs_*), Newton's rate in
// contact_newton_test.cc (contact_newton_rate_nurbs), the exact circle in
// geometric_study_test.cc (geometric_study_nurbs_exact).

#include <glissade/base/input_error.h>
#include <glissade/body/body_measures.h>
#include <glissade/contact/surfaces/master_chain.h>
#include <glissade/contact/surfaces/nurbs_boundary.h>
#include <glissade/fe/nurbs_space.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "contact_patch.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /** The patch test's blocks (contact_patch.h), the master a NURBS
   *  body of degree p; the slave too (`nurbs_slave`) or Q1. */
  std::string
  nurbs_patch_scene(const unsigned int upper_cells,
                    const unsigned int lower_cells,
                    const bool         upper_is_slave,
                    const unsigned int degree,
                    const std::string &discretisation,
                    const bool         nurbs_slave)
  {
    const std::string nurbs = "nurbs\n  set Degree = " + std::to_string(degree);
    return patch_scene(upper_cells,
                       lower_cells,
                       upper_is_slave,
                       false,
                       "condensed",
                       "nurbs",
                       nurbs_slave ? nurbs : "q1",
                       nurbs,
                       discretisation);
  }

  /**
   * The consistent loads of a uniform traction t on the slave boundary's
   * control points, t int R_A ds over the current boundary (Gauss, 8
   * points a span), against the contact forces the pair puts on them: the
   * largest difference over the largest load.
   */
  double
  consistent_load_error(const ContactPair &pair, const Tensor<1, 2> &traction)
  {
    const Body       &slave  = pair.slave();
    const auto       &space  = dynamic_cast<const NurbsSpace &>(slave.space());
    const auto        forces = pair.contact_forces()[0];
    const std::string boundary = slave.name() == "upper" ? "bottom" : "top";
    const MasterChain chain    = MasterChain::build(slave, boundary, "test");
    NurbsBoundary     curve    = NurbsBoundary::build(space, chain);
    std::vector<MasterCurve::Point> current;
    for (unsigned int k = 0; k < curve.control_points.size(); ++k)
      current.push_back({{curve.control_points[k][0] +
                            slave.displacement()(curve.control_dofs[k][0]),
                          curve.control_points[k][1] +
                            slave.displacement()(curve.control_dofs[k][1])}});
    curve.curve->update(current);
    std::vector<double> integral(current.size(), 0.);
    const QGauss<1>     rule(8);
    for (unsigned int i = 0; i < curve.curve->n_segments(); ++i)
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          const double s   = rule.point(q)[0];
          const auto   dc  = curve.curve->derivative(i, s);
          const double jxw = std::hypot(dc[0], dc[1]) * rule.weight(q);
          MasterCurve::NodeWeightsAndDerivatives weights;
          curve.curve->weights_and_derivatives(i, s, weights);
          for (const auto &w : weights)
            integral[w.node] += w.value * jxw;
        }
    double largest = 0., error = 0.;
    for (unsigned int k = 0; k < current.size(); ++k)
      for (unsigned int c = 0; c < 2; ++c)
        {
          const double load = traction[c] * integral[k];
          largest           = std::max(largest, std::abs(load));
          error =
            std::max(error, std::abs(forces(curve.control_dofs[k][c]) - load));
        }
    return error / largest;
  }
} // namespace

namespace
{
  /** What the NURBS-on-NURBS patch test measures in one configuration. */
  struct NurbsPatchFigures
  {
    std::string  label;
    unsigned int active = 0, points = 0;
    /** The contact force in y against the top's support, relative. */
    double balance = 0.;
    /** The slave's control forces against the consistent loads of the
     *  applied traction, relative to the largest. */
    double load_error = 0.;
    /** Each point's reaction over its area against the applied traction
     *  (the contact tables' pressure), relative. */
    double point_error = 0.;
  };

  /**
   * The patch test with NURBS on both sides, p = 2 and 3, 5 elements on 8
   * and 7 on 13, each block as slave, by `discretisation`: its figures,
   * printed.
   */
  std::vector<NurbsPatchFigures>
  nurbs_patch_figures(const std::string &discretisation)
  {
    std::vector<NurbsPatchFigures> all;
    for (const unsigned int degree : {2u, 3u})
      for (const auto &[upper_cells, lower_cells] :
           std::vector<std::pair<unsigned int, unsigned int>>{{5, 8}, {7, 13}})
        for (const bool upper_is_slave : {true, false})
          {
            NurbsPatchFigures f;
            f.label = discretisation + ", p = " + std::to_string(degree) +
                      ", " + std::to_string(upper_cells) + " elements on " +
                      std::to_string(lower_cells) + ", slave " +
                      (upper_is_slave ? "upper" : "lower");
            Simulation simulation(
              SceneReader::read_string(nurbs_patch_scene(upper_cells,
                                                         lower_cells,
                                                         upper_is_slave,
                                                         degree,
                                                         discretisation,
                                                         true),
                                       "nurbs patch"));
            for (unsigned int k = 1; k <= 2; ++k)
              simulation.advance_to(0.5 * k, "increment " + std::to_string(k));
            const auto        &pair = *simulation.contact().contact_pairs()[0];
            const Tensor<1, 2> support =
              support_reaction(simulation.body("upper"), "top");
            const double sign = upper_is_slave ? -1. : 1.;
            // Balance in y (the left sides' x supports take what x force
            // the transfer leaves).
            Tensor<1, 2> total;
            for (const auto &node : pair.nodes())
              if (node.active)
                {
                  ++f.active;
                  total += pair.reported_force(node);
                }
            f.points = pair.nodes().size();
            f.balance =
              std::abs(total[1] - sign * support[1]) / std::abs(support[1]);
            f.load_error = consistent_load_error(
              pair, applied_traction(simulation, upper_is_slave));
            // Each point's reaction over its area (reference: a collocation
            // area, or int R_A with mortar), against the top's force over
            // its reference width, 1, as the stretch is uniform.
            const std::vector<double> area = pair.tributary_areas();
            for (unsigned int k = 0; k < f.points; ++k)
              {
                const ContactNode &node = pair.nodes()[k];
                const auto         r    = pair.reported_reaction(node);
                const Tensor<1, 2> traction =
                  (r[0] * node.tangent + r[1] * node.normal) / area[k];
                f.point_error =
                  std::max(f.point_error,
                           (traction - sign * support).norm() / support.norm());
              }
            std::cout << "  " << f.label << ": " << f.active << " of "
                      << f.points
                      << " points in contact; contact force against the "
                         "support "
                      << f.balance
                      << "; control forces off the consistent loads by up "
                         "to "
                      << f.load_error
                      << " of the largest; the points' traction off the "
                         "applied one by up to "
                      << f.point_error << std::endl;
            all.push_back(f);
          }
    return all;
  }
} // namespace



// The contact patch test on non-matching NURBS patches (5 elements on 8
// and 7 on 13, each side as slave, p = 2 and 3), knot-to-segment on the
// exact master: every Greville point is in contact, the contact force balances
// the top's support in y to 1e-9, and the figure of the uniform traction's
// transfer is reported: the forces on the slave's control points against
// the consistent loads of that traction (t int R_A ds).
// Knot-to-segment is a collocation: it does not pass this test exactly (no
// node-to-segment scheme does; mortar does, contact.md), the figure says
// by how much.
GLISSADE_TEST(nurbs_contact_patch_test)
{
  for (const NurbsPatchFigures &f : nurbs_patch_figures("node-to-segment"))
    {
      check(f.active == f.points, f.label + ": every point in contact");
      check(f.balance <= 1e-9, f.label + ": the contact force balances");
    }
}



namespace
{
  /**
   * Two quarter rings, plane strain, small strain, E = 1000, nu = 0.3:
   * the inner one from r = 1 to 1.5, the outer one from 1.5 - delta to 2,
   * overlapping by delta at the start (an interference fit), each held by
   * its symmetry lines (start: y, end: x). The inner ring's outer side is
   * the slave, the outer ring's inner side the master; `space` for both,
   * `cells` elements around and 4 through each ring.
   */
  std::string
  shrink_fit_scene(const std::string &space,
                   const std::string &surface,
                   const unsigned int cells,
                   const double       delta,
                   const std::string &discretisation = "node-to-segment")
  {
    const auto ring =
      [&](const std::string &name, const double inner, const double outer) {
        return "subsection Body " + name +
               "\n subsection Mesh\n  set Type = half ring\n"
               "  set Inner radius = " +
               std::to_string(inner) +
               "\n  set Outer radius = " + std::to_string(outer) +
               "\n  set Start angle = 0\n  set End angle = 90\n"
               "  set Subdivisions = " +
               std::to_string(cells) +
               ", 4\n end\n subsection Element\n  set Space = " + space +
               "\n end\n subsection Material\n  set Young modulus = 1000\n"
               "  set Poisson ratio = 0.3\n  set Kinematics = small strain\n"
               " end\n subsection Boundary conditions\n"
               "  set Fixed = start: y; end: x\n end\nend\n";
      };
    return "subsection Scene\n set Bodies = inner, outer\n"
           " set Contact pairs = fit\nend\n" +
           ring("inner", 1., 1.5) + ring("outer", 1.5 - delta, 2.) +
           "subsection Contact fit\n set Slave body = inner\n"
           " set Slave boundary = outer\n set Master body = outer\n"
           " set Master boundary = inner\n set Surface = " +
           surface + "\n set Discretisation = " + discretisation +
           "\n set Alert distance = 0.05\nend\n"
           "subsection Contact solver\n set Tolerance = 1e-13\nend\n"
           "subsection Load program\n set Stage increments = 1\nend\n"
           "subsection Output\n set Progress = false\n"
           " set Directory = output/nurbs_shrink_fit\nend\n"
           "subsection Newton\n set Residual tolerance = 1e-11\n"
           " set Displacement tolerance = 1e-11\nend\n";
  }

  /**
   * Lame's interference fit in plane strain: u = A r + B / r in each
   * ring, sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2, free at r = a and
   * r = c, the interface closed, b + u_inner(b) = b' + u_outer(b'),
   * b' = b - delta, and the contact forces equal and opposite: each ring's
   * stress acts on its own reference side, so b sigma_inner(b) =
   * b' sigma_outer(b') (the textbook's equal pressures differ from it by
   * delta / b, 7e-4 here, which these rings resolve).
   * Returns {u_r(a), u_r(c), the pressure}.
   */
  std::array<double, 3>
  lame_interference_fit(const double a,
                        const double b,
                        const double c,
                        const double delta,
                        const double E,
                        const double nu)
  {
    const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    const double mu     = E / (2. * (1. + nu));
    const double bp     = b - delta;
    // Unknowns (A1, B1, A2, B2); rows: sigma(a) = 0, sigma1(b) =
    // sigma2(b'), sigma(c) = 0, u1(b) - u2(b') = -delta.
    FullMatrix<double> M(4, 4);
    Vector<double>     rhs(4), x(4);
    const auto         sigma = [&](const double r) {
      return std::array<double, 2>{{2. * (lambda + mu), -2. * mu / (r * r)}};
    };
    M(0, 0) = sigma(a)[0];
    M(0, 1) = sigma(a)[1];
    M(1, 0) = b * sigma(b)[0];
    M(1, 1) = b * sigma(b)[1];
    M(1, 2) = -bp * sigma(bp)[0];
    M(1, 3) = -bp * sigma(bp)[1];
    M(2, 2) = sigma(c)[0];
    M(2, 3) = sigma(c)[1];
    M(3, 0) = b;
    M(3, 1) = 1. / b;
    M(3, 2) = -bp;
    M(3, 3) = -1. / bp;
    rhs(3)  = -delta;
    M.gauss_jordan();
    M.vmult(x, rhs);
    return {{x(0) * a + x(1) / a,
             x(2) * c + x(3) / c,
             -(sigma(b)[0] * x(0) + sigma(b)[1] * x(1))}};
  }
} // namespace

// The same patch test with mortar (Discretisation = mortar) on the NURBS
// master's exact boundary and a Q1 slave: each slave node's traction (its
// force over its current tributary length) is the applied one to 1e-8,
// as on the other masters (mortar_patch_test).
GLISSADE_TEST(nurbs_contact_mortar_patch_test)
{
  for (const unsigned int degree : {2u, 3u})
    for (const auto &[upper_cells, lower_cells] :
         std::vector<std::pair<unsigned int, unsigned int>>{{5, 8}, {7, 13}})
      for (const bool upper_is_slave : {true, false})
        {
          const std::string label =
            "mortar, NURBS master p = " + std::to_string(degree) + ", " +
            std::to_string(upper_cells) + " elements on " +
            std::to_string(lower_cells) + ", Q1 slave " +
            (upper_is_slave ? "upper" : "lower");
          Simulation simulation(
            SceneReader::read_string(nurbs_patch_scene(upper_cells,
                                                       lower_cells,
                                                       upper_is_slave,
                                                       degree,
                                                       "mortar",
                                                       false),
                                     "nurbs mortar patch"));
          for (unsigned int k = 1; k <= 2; ++k)
            simulation.advance_to(0.5 * k, "increment " + std::to_string(k));
          unsigned int       n_checked = 0;
          const double       error     = largest_traction_error(simulation,
                                                      upper_is_slave,
                                                      n_checked,
                                                      label);
          const unsigned int n_slave_nodes =
            simulation.contact().contact_pairs()[0]->nodes().size();
          check(n_checked == n_slave_nodes, label + ": every node in contact");
          check(error <= 1e-8, label + ": the traction is not uniform");
        }
}



// The patch test with NURBS on both sides and mortar (the slave's
// multiplier lambda_A R_A on its own boundary, nurbs_slave_mortar.cc): 5
// elements on 8 and 7 on 13, each block as slave, p = 2 and 3. A uniform
// lambda is a uniform traction: the forces on the slave's control points
// are the consistent loads of the applied traction (t int R_A ds) and each
// point's lambda_A (its force over int R_A) the applied traction, both to
// 1e-8; knot-to-segment's figures on the same patches are
// nurbs_contact_patch_test's.
GLISSADE_TEST(nurbs_contact_mortar_on_nurbs_patch_test)
{
  for (const NurbsPatchFigures &f : nurbs_patch_figures("mortar"))
    {
      check(f.active == f.points, f.label + ": every point in contact");
      check(f.balance <= 1e-9, f.label + ": the contact force balances");
      check(f.load_error <= 1e-8,
            f.label + ": the control forces are the consistent loads");
      check(f.point_error <= 1e-8,
            f.label + ": every lambda_A is the applied traction");
    }
}



// An interference fit of two quarter rings against Lame's closed form
// (plane strain): the radial displacements of the free inner side (r = 1)
// and outer side (r = 2), NURBS rings (p = 2, the exact circles, knot-to-
// segment on the exact master) beside Q1 rings (faceted master) on the same
// elements. The Q1 rings' chords cut the circle, which the interference
// of 1e-3 feels: the fit is tighter or looser by the sagitta (7 % at 8
// elements a quarter, O(h^2)); the NURBS rings converge to Lame.
GLISSADE_TEST(nurbs_contact_interference_fit)
{
  const double delta = 1e-3;
  const auto   exact = lame_interference_fit(1., 1.5, 2., delta, 1000., 0.3);
  std::cout << "  Lame: u_r(1) = " << exact[0] << ", u_r(2) = " << exact[1]
            << ", p = " << exact[2] << std::endl;
  std::map<std::string, std::vector<double>> errors;
  for (const unsigned int cells : {8u, 16u, 32u})
    for (const auto &[space, discretisation] :
         std::vector<std::pair<std::string, std::string>>{
           {"nurbs", "node-to-segment"},
           {"nurbs", "mortar"},
           {"q1", "node-to-segment"}})
      {
        const std::string surface = space == "nurbs" ? "nurbs" : "faceted";
        const std::string label   = space + ", " + discretisation;
        Simulation        simulation(SceneReader::read_string(
          shrink_fit_scene(space, surface, cells, delta, discretisation),
          "interference fit"));
        simulation.run();
        const auto radial = [&](const std::string &body, const double r) {
          return vertex_displacement(simulation.body(body), Point<2>(r, 0.))[0];
        };
        const double u_a = radial("inner", 1.), u_c = radial("outer", 2.);
        const double error =
          std::max(std::abs(u_a - exact[0]) / std::abs(exact[0]),
                   std::abs(u_c - exact[1]) / std::abs(exact[1]));
        errors[label].push_back(error);
        std::cout << "  " << label << ", " << cells
                  << " elements around: u_r(1) = " << u_a
                  << ", u_r(2) = " << u_c << ", largest relative error "
                  << error << std::endl;
      }
  const auto &q1 = errors["q1, node-to-segment"];
  for (const std::string nurbs : {"nurbs, node-to-segment", "nurbs, mortar"})
    {
      for (unsigned int k = 0; k < q1.size(); ++k)
        expect(errors[nurbs][k] < 0.1 * q1[k],
               nurbs + ": ten times closer to Lame than Q1 rings");
      expect(errors[nurbs].back() <= 2e-5,
             nurbs + ": within 2e-5 of Lame at 32 elements");
    }
  // Mortar's weighted gaps and forces carry the curve's normal across each
  // function's support: the rings' converged figures at every mesh (what
  // knot-to-segment approaches, -3.893813e-4 at 64 elements, 2.4e-6 from
  // Lame's small-strain closure on the reference sides).
  for (const double error : errors["nurbs, mortar"])
    expect(error <= 3e-6, "nurbs, mortar: within 3e-6 of Lame at every mesh");
  // The Q1 rings' error is the chords' sagitta, O(h^2).
  const double q1_rate = std::log(q1[0] / q1[2]) / std::log(4.);
  std::cout << "  Q1 rate " << q1_rate << std::endl;
  expect(q1_rate > 1.8 && q1_rate < 2.2, "Q1 rings converge like h^2");
}

// A NURBS quarter ring (r = 1 to 1.5, plane strain, small strain) pushed
// into a rigid circular hole of radius 1.5 - 1e-3: its outer side's radial
// displacement is -1e-3 where it touches, and Lame's ring free at r = 1
// gives u_r(1) and the pressure. Mortar on the ring's own boundary against
// the obstacle (nurbs_slave_mortar.cc, the obstacle's closest points) and
// knot-to-segment at 8 and 16 elements around.
GLISSADE_TEST(nurbs_contact_ring_in_rigid_hole)
{
  const double delta = 1e-3, a = 1., b = 1.5, E = 1000., nu = 0.3;
  const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
  const double mu     = E / (2. * (1. + nu));
  // u = A r + B / r: sigma_rr(a) = 2 (lambda + mu) A - 2 mu B / a^2 = 0,
  // u(b) = -delta.
  const double B        = -delta / (b * mu / (a * a * (lambda + mu)) + 1. / b);
  const double A        = mu * B / (a * a * (lambda + mu));
  const double u_a      = A * a + B / a;
  const double pressure = -(2. * (lambda + mu) * A - 2. * mu * B / (b * b));
  std::cout << "  Lame: u_r(1) = " << u_a << ", p = " << pressure << std::endl;
  for (const std::string discretisation : {"node-to-segment", "mortar"})
    for (const unsigned int cells : {8u, 16u})
      {
        const std::string scene =
          "subsection Scene\n set Bodies = ring\n set Contact pairs = fit\n"
          "end\nsubsection Body ring\n subsection Mesh\n"
          "  set Type = half ring\n  set Inner radius = 1\n"
          "  set Outer radius = 1.5\n  set Start angle = 0\n"
          "  set End angle = 90\n  set Subdivisions = " +
          std::to_string(cells) +
          ", 4\n end\n subsection Element\n  set Space = nurbs\n end\n"
          " subsection Material\n  set Young modulus = 1000\n"
          "  set Poisson ratio = 0.3\n  set Kinematics = small strain\n"
          " end\n subsection Boundary conditions\n"
          "  set Fixed = start: y; end: x\n end\nend\n"
          "subsection Contact fit\n set Slave body = ring\n"
          " set Slave boundary = outer\n set Discretisation = " +
          discretisation +
          "\n set Alert distance = 0.05\n subsection Obstacle\n"
          "  set Type = hole\n  set Point = 0, 0\n  set Radius = " +
          std::to_string(b - delta) +
          "\n end\nend\n"
          "subsection Contact solver\n set Tolerance = 1e-13\nend\n"
          "subsection Output\n set Progress = false\n"
          " set Directory = output/nurbs_ring_in_rigid_hole\nend\n"
          "subsection Newton\n set Residual tolerance = 1e-11\n"
          " set Displacement tolerance = 1e-11\nend\n";
        Simulation simulation(SceneReader::read_string(scene, "ring in hole"));
        simulation.run();
        const double u =
          vertex_displacement(simulation.body("ring"), Point<2>(1., 0.))[0];
        Tensor<1, 2> on_ring;
        for (const auto &node :
             simulation.contact().contact_pairs()[0]->nodes())
          if (node.active)
            on_ring += node.force();
        const double u_error = std::abs(u - u_a) / std::abs(u_a);
        const double force_error =
          std::max(std::abs(-on_ring[0] - pressure * b),
                   std::abs(-on_ring[1] - pressure * b)) /
          (pressure * b);
        std::cout << "  " << discretisation << ", " << cells
                  << " elements: u_r(1) = " << u << " (relative error "
                  << u_error << "), the contact force on the quarter off p b "
                  << "by " << force_error << std::endl;
        if (discretisation == "mortar")
          {
            expect(u_error <= 3e-6,
                   "mortar: u_r(1) within 3e-6 of Lame at " +
                     std::to_string(cells) + " elements");
            expect(force_error <= 1e-5,
                   "mortar: the contact force within 1e-5 of p b at " +
                     std::to_string(cells) + " elements");
          }
      }
}



// What contact with a NURBS body does not do yet is refused before
// anything is computed, with the entry and the reason: a surface through
// a NURBS master's vertices (which carry no displacement), a nurbs surface
// on a body of another space, mortar on a NURBS slave of degree 4,
// self-contact.
GLISSADE_TEST(nurbs_contact_input_errors)
{
  const std::string fit = shrink_fit_scene("nurbs", "nurbs", 8, 1e-3);
  const auto        replaced =
    [](std::string scene, const std::string &from, const std::string &to) {
      const auto at = scene.find(from);
      check(at != std::string::npos, "the scene has '" + from + "'");
      return scene.replace(at, from.size(), to);
    };
  const auto with = [&](const std::string &from, const std::string &to) {
    return replaced(fit, from, to);
  };
  const auto refusal = [](const std::string &scene) -> std::string {
    try
      {
        Simulation simulation(SceneReader::read_string(scene, "scene.prm"));
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "accepted";
  };
  for (const auto &[scene, expected] :
       std::vector<std::pair<std::string, std::string>>{
         {with("set Surface = nurbs", "set Surface = bspline"),
          "Contact fit/Surface: the master body 'outer' uses the element "
          "space 'nurbs'"},
         {shrink_fit_scene("q1", "nurbs", 8, 1e-3),
          "a nurbs surface is the exact boundary of a master body of NURBS "
          "elements"},
         {replaced(with("set Space = nurbs",
                        "set Space = nurbs\n  set Degree = 4"),
                   "set Discretisation = node-to-segment",
                   "set Discretisation = mortar"),
          "Contact fit/Discretisation: mortar contact with a NURBS slave is "
          "built for degrees 2 and 3"},
         {with("set Master body = outer\n set Master boundary = inner",
               "set Master body = inner\n set Master boundary = outer"),
          "self-contact of a NURBS body"},
         {replaced(shrink_fit_scene("q1", "faceted", 8, 1e-3, "mortar"),
                   "set Discretisation = mortar",
                   "set Discretisation = mortar\n"
                   " set Mortar multipliers = standard"),
          "Contact fit/Mortar multipliers: standard multipliers are built "
          "for a NURBS slave; mortar on the faces of body 'inner' is dual "
          "only"}})
    {
      const std::string message = refusal(scene);
      std::cout << "  " << message << std::endl;
      check(message.find(expected) != std::string::npos,
            "expected a message with '" + expected + "'");
    }
}

// prm/nurbs_interference_fit.prm, as its header says: the fit's free
// sides within 2e-5 of Lame's radial displacements, and the contact
// force on the quarter, p b in each direction (the pressure's resultant
// on a quarter arc of radius b), within 1e-5; knot-to-segment as the file
// has it, and mortar on both NURBS boundaries (the nodes' reported forces
// the resultants of their forces, which follow the curve's normal).
GLISSADE_TEST(nurbs_interference_fit_scene)
{
  // (and with mortar on both NURBS boundaries, as the README says)
  for (const std::string discretisation : {"node-to-segment", "mortar"})
    {
      Simulation simulation(SceneReader::read_file(
        source_path("prm/nurbs_interference_fit.prm"),
        {"Output/Directory=output/nurbs_interference_fit_" + discretisation,
         "Output/Progress=false",
         "Output/Plots=false",
         "Contact fit/Discretisation=" + discretisation}));
      simulation.advance_to(1., "increment 1");
      const auto exact = lame_interference_fit(1., 1.5, 2., 1e-3, 1000., 0.3);
      check_relative(vertex_displacement(simulation.body("inner"),
                                         Point<2>(1., 0.))[0],
                     exact[0],
                     2e-5,
                     discretisation + ": u_r(1)");
      check_relative(vertex_displacement(simulation.body("outer"),
                                         Point<2>(2., 0.))[0],
                     exact[1],
                     2e-5,
                     discretisation + ": u_r(2)");
      Tensor<1, 2> on_inner;
      for (const auto &node : simulation.contact().contact_pairs()[0]->nodes())
        if (node.active)
          on_inner += node.force();
      for (unsigned int c = 0; c < 2; ++c)
        check_relative(-on_inner[c],
                       exact[2] * 1.5,
                       1e-5,
                       discretisation +
                         ": the contact force on the inner quarter, "
                         "component " +
                         std::to_string(c));
    }
}

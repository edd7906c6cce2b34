// A rigid flat punch with sharp edges pressed into an elastic block
// (prm/flat_punch.prm, frictionless, plane strain): Sadowsky's pressure
// p(x) = P / (pi sqrt(a^2 - x^2)) on a half-plane, singular at the edges.
// A node's force is compared with p integrated over its tributary length,
// (P / pi) (asin(x+ / a) - asin(x- / a)), which stays finite at the edge.
// The circular punch on an axisymmetric body against Boussinesq's pressure
// (prm/flat_punch_axisymmetric.prm).

#include <deal.II/base/quadrature_lib.h>

#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>

#include "line_contact_points.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

// Node-to-segment and mortar, h = a / 10 and a / 20 under the punch: the
// nodes within a / 2 of the centre carry Sadowsky's force to 2.6 % and
// 1.0 % of the centre node's (measured, both discretisations; the block is
// finite, 16 a by 8 a, and the edge's singularity pollutes a mesh that
// does not grade towards it), so the finer mesh is held to 1.5 % and to
// halving the coarser one's error at least; the load inside a / 2 to 1 %
// of Sadowsky's share (2 / pi) asin(x / a) on the finer mesh, closer than
// on the coarser; both edges' nodes closed (mortar: the slave faces that
// pass the punch's edges integrated against its ends' tangent lines), the
// forces symmetric about the centre to 1e-8, and the load the bottom's
// reaction.
namespace
{
  void
  check_against_sadowsky(const std::string &discretisation)
  {
    const double a             = 1.;
    double       coarser_error = 0., coarser_share_error = 0.;
    for (const unsigned int per_half_width : {10u, 20u})
      {
        const std::string label =
          discretisation + ", h = a / " + std::to_string(per_half_width);
        std::vector<std::string> overrides =
          own_output_directory("flat_punch_" + discretisation + "_",
                               std::to_string(per_half_width));
        overrides.push_back("Contact punch/Discretisation=" + discretisation);
        overrides.push_back("Output/Progress=false");
        overrides.push_back("Output/VTU interval=0");
        overrides.push_back("Body block/Mesh/Subdivisions=" +
                            std::to_string(16 * per_half_width) + ", " +
                            std::to_string(8 * per_half_width));
        Simulation simulation(
          SceneReader::read_file(source_path("prm/flat_punch.prm"), overrides));
        simulation.run();
        const ContactPair &pair = *simulation.contact().contact_pairs()[0];
        const LineContact  contact(pair);
        const auto         area = pair.tributary_areas();
        const double       P    = contact.load;

        // Every closed node against Sadowsky's force on its tributary.
        double error_inside_half = 0., load_inside_half = 0., widest = 0.;
        double centre_force = 0., largest_force = 0.;
        for (const LineContactPoint &point : contact.points)
          {
            const double x     = point.x;
            const double lower = std::max(-a, x - 0.5 * area[point.node]);
            const double upper = std::min(a, x + 0.5 * area[point.node]);
            const double sadowsky =
              P / M_PI * (std::asin(upper / a) - std::asin(lower / a));
            widest        = std::max(widest, std::abs(x));
            largest_force = std::max(largest_force, point.normal_reaction);
            if (std::abs(x) < 1e-9)
              centre_force = sadowsky;
            if (std::abs(x) <= 0.5 * a + 1e-9)
              {
                error_inside_half =
                  std::max(error_inside_half,
                           std::abs(point.normal_reaction - sadowsky) /
                             sadowsky);
                load_inside_half += point.normal_reaction;
              }
          }
        const double h = a / per_half_width;
        const double share_exact =
          2. / M_PI * std::asin((0.5 * a + 0.5 * h) / a);
        std::cout << "  " << label << ": P = " << P << ", "
                  << contact.points.size() << " closed nodes out to " << widest
                  << " a; within a / 2, the nodes' forces within "
                  << error_inside_half << " of Sadowsky's, the load's share "
                  << load_inside_half / P << " (Sadowsky " << share_exact << ")"
                  << std::endl;
        check(centre_force > 0., label + ": a node at the centre");
        check(std::abs(widest - a) < 1e-3 * a,
              label + ": the nodes under both edges are closed, none beyond");
        const double share_error =
          std::abs(load_inside_half / P - share_exact) / share_exact;
        // (the vertical resultant of the contact forces: mortar's act along
        // the slave's nodal normals, which the block's strain tilts by
        // 1e-4 near the edges)
        check_relative(support_reaction(simulation.body("block"), "bottom")[1],
                       -pair.total_force()[1],
                       1e-8,
                       label +
                         ": the punch's load against the bottom's reaction");

        // The mesh and the punch are symmetric about x = 0: so are the forces
        // (to Newton's tolerance and the mesh's round-off: its nodes are
        // mirrored to 1e-15).
        double asymmetry = 0., off_mirror = 0.;
        for (std::size_t i = 0; i < contact.points.size(); ++i)
          {
            const LineContactPoint &left = contact.points[i];
            const LineContactPoint &right =
              contact.points[contact.points.size() - 1 - i];
            asymmetry =
              std::max(asymmetry,
                       std::abs(left.normal_reaction - right.normal_reaction));
            off_mirror = std::max(off_mirror, std::abs(left.x + right.x));
          }
        std::cout << "  " << label << ": forces symmetric to "
                  << asymmetry / largest_force << " of the largest"
                  << std::endl;
        check(asymmetry <= 1e-8 * largest_force && off_mirror <= 1e-10 * a,
              label + ": the forces are not symmetric about the centre");

        if (per_half_width == 10u)
          {
            coarser_error       = error_inside_half;
            coarser_share_error = share_error;
          }
        else
          {
            check(error_inside_half <= 0.015,
                  label + ": more than 1.5 % off Sadowsky's inside a / 2");
            check(error_inside_half <= 0.5 * coarser_error,
                  "halving h does not halve the error inside a / 2");
            check(share_error <= 0.01,
                  label + ": the load inside a / 2 is more than 1 % off");
            check(share_error < coarser_share_error,
                  "halving h does not bring the load inside a / 2 closer");
          }
      }
  }
} // namespace



GLISSADE_TEST(contact_flat_punch_sadowsky)
{
  check_against_sadowsky("node-to-segment");
}



GLISSADE_TEST(contact_flat_punch_sadowsky_mortar)
{
  check_against_sadowsky("mortar");
}



// The circular punch, axisymmetric (prm/flat_punch_axisymmetric.prm), both
// discretisations, h = a / 20 and a / 40 under the punch: every node
// within a / 2 of the axis against Boussinesq's pressure P / (2 pi a
// sqrt(a^2 - r^2)) as its consistent nodal force, int N_j p 2 pi r dr over
// the node's faces (P the normal reactions' sum, for the full turn).
// Measured: 2.7 % and 1.3 %, the nodes' forces uniformly low (the edge's
// singularity pollutes a mesh that does not grade towards it; the
// cylinder is finite, 8 a by 8 a, and carries 12 % more than a half-space
// for the same sink, so P = 2 E* a delta is not checked), so the finer
// mesh is held to 1.5 % and to halving the coarser one's error at least
// (0.46 of it); the node at the edge closed and none beyond; the load the
// bottom's reaction.
namespace
{
  /** int N_j p 2 pi r dr over the faces [r_j - h, r_j] and [r_j, r_j + h]
   *  (from r = 0 at the axis), p Boussinesq's pressure (well inside the
   *  punch, where it is smooth: ten Gauss points a face). */
  double
  boussinesq_nodal_force(const double P,
                         const double a,
                         const double r_j,
                         const double h)
  {
    static const QGauss<1> gauss(10);
    double                 force = 0.;
    for (const double side : {-1., 1.})
      {
        const double far = r_j + side * h;
        if (far < -1e-12)
          continue;
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double s = gauss.point(q)[0];
            const double r = r_j + s * (far - r_j);
            const double p = P / (2. * M_PI * a * std::sqrt(a * a - r * r));
            force += gauss.weight(q) * h * (1. - s) * p * 2. * M_PI * r;
          }
      }
    return force;
  }
} // namespace



GLISSADE_TEST(contact_flat_punch_boussinesq)
{
  const double a = 1.;
  for (const std::string discretisation : {"node-to-segment", "mortar"})
    {
      double coarser_error = 0.;
      for (const unsigned int per_radius : {20u, 40u})
        {
          const std::string label =
            discretisation + ", h = a / " + std::to_string(per_radius);
          std::vector<std::string> overrides =
            own_output_directory("flat_punch_axisymmetric_" + discretisation +
                                   "_",
                                 std::to_string(per_radius));
          overrides.push_back("Contact punch/Discretisation=" + discretisation);
          overrides.push_back("Output/Progress=false");
          overrides.push_back("Output/VTU interval=0");
          overrides.push_back(
            "Body block/Mesh/Subdivisions=" + std::to_string(8 * per_radius) +
            ", " + std::to_string(8 * per_radius));
          Simulation simulation(SceneReader::read_file(
            source_path("prm/flat_punch_axisymmetric.prm"), overrides));
          simulation.run();
          const ContactPair &pair = *simulation.contact().contact_pairs()[0];
          const auto        &u    = pair.slave().displacement();
          const double       h    = a / per_radius;

          double P = 0., widest = 0.;
          for (const ContactNode &node : pair.nodes())
            if (node.active)
              {
                P += node.reaction[1];
                widest = std::max(widest,
                                  node.reference_position[0] +
                                    node.displacement(u)[0]);
              }
          double error = 0.;
          for (const ContactNode &node : pair.nodes())
            if (node.active && node.reference_position[0] <= 0.5 * a + 1e-9)
              {
                // (on the reference mesh: the closed form is small strain's)
                const double r     = node.reference_position[0];
                const double exact = boussinesq_nodal_force(P, a, r, h);
                error =
                  std::max(error, std::abs(node.reaction[1] - exact) / exact);
              }
          std::cout << "  " << label << ": P = " << P
                    << " (for the full turn), closed nodes out to " << widest
                    << " a; within a / 2, the nodes' forces within " << error
                    << " of Boussinesq's" << std::endl;
          check(std::abs(widest - a) < 1e-3 * a,
                label + ": the node under the edge is closed, none beyond");
          check_relative(support_reaction(simulation.body("block"),
                                          "bottom")[1],
                         -pair.total_force()[1],
                         1e-8,
                         label +
                           ": the punch's load against the bottom's reaction");
          if (per_radius == 20u)
            coarser_error = error;
          else
            {
              check(error <= 0.015,
                    label + ": more than 1.5 % off Boussinesq's inside a / 2");
              check(error <= 0.5 * coarser_error,
                    label +
                      ": halving h does not halve the error inside a / 2");
            }
        }
    }
}



// The plane punch pressed in frictionlessly... then slid by half a face
// with mu = 0.5 (prm/flat_punch.prm with Friction coefficient = 0.5):
// every node slips, and the pressure under a sliding flat punch is
// p(x) ~ (a + x)^(-1/2 - gamma) (a - x)^(-1/2 + gamma) about the punch's
// centre, x along its motion, with tan(pi gamma) = mu (1 - 2 nu) /
// (2 (1 - nu)) (Johnson, Contact Mechanics, the sliding flat punch: the
// friction's tangential traction lifts the surface behind it, so the trailing
// edge carries more). 2 gamma is fitted to the nodes within 0.6 a as the slope
// of ln p + ln(a^2 - x^2) / 2 against ln((a + x) / (a - x)), on blocks of
// half-width and depth D = 8 a, 16 a and 32 a (h = a / 20 along the top,
// the depth graded fiftyfold towards it: the finite block holds the
// tangential load where a half-plane would not, and the exponent comes
// within 1 / D of the half-plane's). Measured (mortar): 2 gamma = 0.0831,
// 0.0875, 0.0900 against 0.0903 (8.0, 3.1 and 0.39 % low; node-to-segment
// 0.0900 at 32 a); held to 2 % at 32 a and falling with D. Every node
// slipping with |r_t| = mu r_n, the friction on the block along the
// punch's motion, the trailing half carrying more, the load the bottom's
// reaction.
GLISSADE_TEST(contact_friction_sliding_flat_punch)
{
  const double a = 1., mu = 0.5, nu = 0.3, slide = 0.025;
  const double two_gamma =
    2. * std::atan(mu * (1. - 2. * nu) / (2. * (1. - nu))) / M_PI;
  double coarser_error = 1.;
  for (const unsigned int D : {8u, 16u, 32u})
    {
      const std::string        label = "D = " + std::to_string(D) + " a";
      std::vector<std::string> overrides =
        own_output_directory("flat_punch_sliding_", std::to_string(D));
      for (const char *entry :
           {"Contact punch/Discretisation=mortar",
            "Contact punch/Friction coefficient=0.5",
            "Contact punch/Obstacle/Motion=0.025*max(0, t - 1), "
            "-0.002*min(t, 1)",
            "Load program/Stage end times=1, 2",
            "Load program/Stage increments=1, 2",
            "Body block/Mesh/Grading=1, 0.02",
            "Output/Progress=false",
            "Output/VTU interval=0"})
        overrides.push_back(entry);
      const double d = D;
      overrides.push_back("Body block/Mesh/Corner 1=" + std::to_string(-d) +
                          ", " + std::to_string(-d));
      overrides.push_back("Body block/Mesh/Corner 2=" + std::to_string(d) +
                          ", 0");
      overrides.push_back(
        "Body block/Mesh/Subdivisions=" + std::to_string(40 * D) + ", 60");
      Simulation simulation(
        SceneReader::read_file(source_path("prm/flat_punch.prm"), overrides));
      simulation.run();
      const ContactPair &pair   = *simulation.contact().contact_pairs()[0];
      const auto        &u      = pair.slave().displacement();
      const auto         area   = pair.tributary_areas();
      const Tensor<1, 2> force  = pair.total_force();
      const double       centre = slide;

      // ln p + ln(a^2 - x^2) / 2 = ln K - gamma ln((a + x) / (a - x)).
      std::vector<double> ys, zs;
      double              slip_law = 0., trailing = 0., leading = 0.;
      unsigned int        not_slipping = 0;
      for (unsigned int k = 0; k < pair.nodes().size(); ++k)
        {
          const ContactNode &node = pair.nodes()[k];
          if (!node.active)
            continue;
          const double x =
            node.reference_position[0] + node.displacement(u)[0] - centre;
          const double r_n = node.reaction[1], r_t = node.reaction[0];
          not_slipping += node.status != BiPotentialSolver::NodeStatus::slip;
          slip_law = std::max(slip_law, std::abs(std::abs(r_t) - mu * r_n));
          (x < 0. ? trailing : leading) += r_n;
          if (std::abs(x) <= 0.6 * a)
            {
              ys.push_back(std::log(r_n / area[k]) +
                           0.5 * std::log(a * a - x * x));
              zs.push_back(std::log((a + x) / (a - x)));
            }
        }
      double mean_y = 0., mean_z = 0.;
      for (unsigned int i = 0; i < ys.size(); ++i)
        {
          mean_y += ys[i] / ys.size();
          mean_z += zs[i] / zs.size();
        }
      double covariance = 0., variance = 0.;
      for (unsigned int i = 0; i < ys.size(); ++i)
        {
          covariance += (zs[i] - mean_z) * (ys[i] - mean_y);
          variance += (zs[i] - mean_z) * (zs[i] - mean_z);
        }
      const double fitted = -2. * covariance / variance;
      const double error  = std::abs(fitted - two_gamma) / two_gamma;
      std::cout << "  " << label << ": 2 gamma fitted to " << ys.size()
                << " nodes " << fitted << " (closed form " << two_gamma << ", "
                << error << " off); trailing half " << trailing
                << ", leading half " << leading << "; |r_t| - mu r_n within "
                << slip_law << ", " << not_slipping << " nodes not slipping"
                << std::endl;
      check(not_slipping == 0 && slip_law <= 1e-8 * std::abs(force[1]),
            label + ": a closed node does not slip at mu r_n");
      check(force[0] > 0.49 * std::abs(force[1]),
            label + ": the friction on the block is not along the punch's "
                    "motion");
      check(trailing > leading,
            label + ": the trailing half does not carry more");
      check_relative(support_reaction(simulation.body("block"), "bottom")[1],
                     -force[1],
                     1e-8,
                     label +
                       ": the punch's load against the bottom's reaction");
      check(error < coarser_error,
            label + ": the exponent is not closer than on the smaller block");
      coarser_error = error;
      if (D == 32u)
        check(error <= 0.02, label + ": 2 gamma more than 2 % off");
    }
}

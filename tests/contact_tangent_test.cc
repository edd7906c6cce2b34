// The consistent linearisation of the contact, against finite differences:
// for every master kind and every law (frictionless, stick, slip), the
// contact tangent assembled from the nodes' linearisation equals the
// central difference of the contact forces F(U) = sum_k H_k(U)^T Q_k(U) r_k
// at fixed reactions, and the gap and slip rows equal the differences of
// the gap and the slip. The configuration is distorted (a curved master,
// slave nodes off the master's nodes, a slip since the increment began).

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <map>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  std::string
  block(const std::string &name,
        const std::string &corner_1,
        const std::string &corner_2,
        const std::string &subdivisions,
        const std::string &space,
        const std::string &fixed = "left: x")
  {
    return "subsection Body " + name +
           "\n subsection Mesh\n  set Type = rectangle\n  set Corner 1 = " +
           corner_1 + "\n  set Corner 2 = " + corner_2 +
           "\n  set Subdivisions = " + subdivisions +
           "\n end\n subsection Element\n  set Space = " + space +
           "\n end\n subsection Material\n  set Young modulus = 1000\n end\n"
           " subsection Boundary conditions\n  set Fixed = " +
           fixed + "\n end\nend\n";
  }

  /** A slave block on a master block, or on a rigid obstacle. */
  std::string
  scene(const std::string &named)
  {
    // <master>_standard: mortar with a NURBS slave on its standard
    // multipliers (Mortar multipliers = standard) instead of the dual ones.
    const std::string suffix = "_standard";
    const bool        standard =
      named.size() > suffix.size() &&
      named.compare(named.size() - suffix.size(), suffix.size(), suffix) == 0;
    const std::string master =
      standard ? named.substr(0, named.size() - suffix.size()) : named;
    // faceted_vertex: slave nodes above the master's nodes (both blocks
    // 4 x 2), met as vertices with their cone (Faceted vertex rule =
    // vertex normal).
    const bool vertex = master == "faceted_vertex";
    // hermite_corner: a Hermite master whose boundary turns a corner (its
    // top and right sides, one curve), the slave block beyond the corner,
    // every slave node in the corner's normal cone: met at the corner
    // node, the gap along the mean of the two sides' normals, which turns
    // with the node's tangent dofs.
    const bool  corner = master == "hermite_corner";
    std::string text   = "subsection Output\n set Progress = false\nend\n";
    // nurbs_slave, nurbs_on_nurbs: the slave a NURBS body (p = 2, its
    // boundary's Greville points the slave points, held so that no rigid
    // motion is free, which a NURBS body needs) on a faceted Q1 master, or
    // on a NURBS master's exact boundary.
    // (with mortar_ before them: mortar on the NURBS slave's own curve)
    const std::string unprefixed =
      master.rfind("mortar_", 0) == 0 ? master.substr(7) : master;
    // nurbs_slave_on_<obstacle>: a NURBS slave on that rigid obstacle.
    const bool nurbs_slave = unprefixed == "nurbs_slave" ||
                             unprefixed == "nurbs_on_nurbs" ||
                             unprefixed.rfind("nurbs_slave_on_", 0) == 0;
    text +=
      nurbs_slave ?
        block("upper", "0, 0.5", "1, 1", "6, 2", "nurbs", "left: x; top: y") :
      corner ? block("upper", "1.05, 0.55", "1.55, 1.05", "6, 2", "q1") :
               block("upper", "0, 0.5", "1, 1", vertex ? "4, 2" : "6, 2", "q1");
    std::string contact =
      "subsection Contact interface\n"
      " set Slave body = upper\n set Slave boundary = bottom\n"
      " set Alert distance = 10\n";
    // mortar_line, mortar_disk: mortar against those obstacles;
    // mortar_bspline, mortar_bspline_spline, mortar_hermite, mortar_nurbs:
    // on the B-spline master (each force transfer), the Hermite master and
    // a NURBS master's exact boundary; mortar_nurbs_slave,
    // mortar_nurbs_on_nurbs: mortar on a NURBS slave's own curve.
    const bool        on_obstacle_mortar = master.rfind("mortar_", 0) == 0;
    const std::string kind = unprefixed.rfind("nurbs_slave_on_", 0) == 0 ?
                               unprefixed.substr(15) :
                               unprefixed;
    if (on_obstacle_mortar)
      contact += " set Discretisation = mortar\n";
    // nurbs_curve_end: the wavy floor ending at x = 0.6, under the block
    // (an open end between two slave nodes).
    const bool curve_obstacle =
      kind == "nurbs_curve" || kind == "nurbs_curve_end";
    if (kind == "line" || kind == "disk" || kind == "hole" ||
        kind == "casing" || curve_obstacle)
      {
        text += "subsection Scene\n set Bodies = upper\n"
                " set Contact pairs = interface\nend\n";
        contact += " subsection Obstacle\n  set Type = " +
                   (curve_obstacle ? std::string("nurbs curve") : kind) +
                   "\n  set Motion = 0.013*t, -0.004*t\n";
        if (curve_obstacle)
          // A wavy rational cubic under the block, turning about a point
          // below it: its curvature changes along the block.
          contact += "  set Curve file = " +
                     source_path(kind == "nurbs_curve" ?
                                   "prm/meshes/wavy_floor.nurbs" :
                                   "prm/meshes/wavy_floor_end.nurbs") +
                     "\n  set Point = 0.5, 0.3\n"
                     "  set Rotation = 0.004 + 0.004*t\n";
        else if (kind == "line")
          contact += "  set Point = 0, 0.49\n  set Normal = 0.1, 1\n";
        else if (kind == "disk")
          contact += "  set Point = 0.5, -1.51\n  set Radius = 2\n";
        else if (kind == "casing")
          // Two lobes 0.3 deep, turning: below the block the casing is
          // between lobes, sloped and of changing curvature, its lowest
          // point r(-pi/2) = 5 + 0.3 cos(0.4) under the centre at 0.49.
          contact += "  set Point = 0.5, 5.766318\n  set Radius = 5\n"
                     "  set Lobes = 2\n  set Lobe depth = 0.3\n"
                     "  set Rotation = 0.2 + 0.05*t\n";
        else
          contact += "  set Point = 0.5, 5.49\n  set Radius = 5\n";
        contact += " end\n";
      }
    else
      {
        const bool hermite = kind == "hermite" || corner;
        // nurbs, nurbs3: the master a NURBS body of degree 2 or 3, its
        // exact boundary the surface.
        const bool nurbs =
          kind == "nurbs" || kind == "nurbs3" || kind == "nurbs_on_nurbs";
        text += "subsection Scene\n set Bodies = upper, lower\n"
                " set Contact pairs = interface\nend\n";
        // (the lower block held, so that no motion of the pair is free)
        text += block("lower",
                      "0, 0",
                      "1, 0.5",
                      "4, 2",
                      hermite ? "hermite" :
                      nurbs   ? "nurbs\n  set Degree = " +
                                std::string(kind == "nurbs3" ? "3" : "2") :
                              "q1",
                      "left: x; bottom: y");
        contact += " set Master body = lower\n set Master boundary = " +
                   std::string(corner ? "top, right" : "top") + "\n";
        // bspline_segment and bspline_spline: the B-spline master with
        // each force transfer; any other name is a Surface of its own.
        if (vertex)
          contact += " set Surface = faceted\n"
                     " set Faceted vertex rule = vertex normal\n";
        else if (master.rfind("bspline_", 0) == 0)
          contact +=
            " set Surface = bspline\n set Force transfer = " +
            std::string(master == "bspline_segment" ? "segment" : "spline") +
            "\n";
        else if (master == "mortar_bspline")
          contact += " set Surface = bspline\n";
        else if (master == "mortar_bspline_spline")
          contact += " set Surface = bspline\n set Force transfer = spline\n";
        else if (master == "mortar_hermite" || corner)
          contact += " set Surface = hermite\n";
        else if (master == "mortar")
          contact += " set Surface = faceted\n set Discretisation = mortar\n";
        else if (nurbs)
          contact += " set Surface = nurbs\n";
        else if (kind == "nurbs_slave")
          contact += " set Surface = faceted\n";
        else
          contact += " set Surface = " + master + "\n";
      }
    if (standard)
      contact += " set Mortar multipliers = standard\n";
    return text + contact + "end\n";
  }

  /**
   * A smooth displacement field on a body's dofs: every value dof gets a
   * function of its node's position, every other dof (Hermite
   * derivatives) a small deterministic value.
   */
  Vector<double>
  distortion(const Body &body, const double shift, const double lift = 0.)
  {
    Vector<double> u(body.n_dofs());
    for (unsigned int i = 0; i < u.size(); ++i)
      u(i) = 0.02 * std::sin(1.7 * i + 0.3);
    const auto &vertices = body.triangulation().get_vertices();
    for (unsigned int v = 0; v < vertices.size(); ++v)
      {
        const auto d =
          BoundaryConditions::vertex_dofs(body.dof_handler(), body.space(), v);
        const double x = vertices[v][0], y = vertices[v][1];
        u(d[0]) = shift + 0.01 * std::sin(3. * x + 2. * y);
        u(d[1]) = 0.03 * std::cos(2.5 * x) - 0.01 * y;
        // Lifted along the normal of the distorted line of height y.
        const double tx = 1. + 0.03 * std::cos(3. * x + 2. * y);
        const double ty = -0.075 * std::sin(2.5 * x);
        const double t  = std::hypot(tx, ty);
        u(d[0]) -= lift * ty / t;
        u(d[1]) += lift * tx / t;
      }
    return u;
  }

  void
  check_contact_tangent(const std::string &master, const std::string &law)
  {
    Simulation   simulation(SceneReader::read_string(scene(master), master));
    ContactPair &pair            = *simulation.contact().contact_pairs()[0];
    std::array<Body *, 2> bodies = {{&pair.slave(), pair.master()}};

    // The increment starts from U_0 = 0.3 distortion and is at U = the
    // distortion (and the slave shifted), so that there is a slip.
    for (unsigned int b = 0; b < 2; ++b)
      if (bodies[b])
        {
          // faceted_vertex: the slave follows the master's shape, lifted
          // by 0.02 along its normal, so that each slave node lies in a
          // master node's normal cone (a ridge: the distorted top is
          // concave; the cone's half angle is about 0.02 here).
          Vector<double> u = master == "faceted_vertex" ?
                               distortion(*bodies[b], 0., b == 0 ? 0.02 : 0.) :
                               distortion(*bodies[b], b == 0 ? 0.04 : 0.);
          Vector<double> u0(u);
          u0 *= 0.3;
          bodies[b]->update(u0);
          bodies[b]->store_state();
          u -= u0;
          bodies[b]->update(u);
        }
    pair.begin_step(0., 1.);

    // The reactions: frictionless (r_t = 0), stick (|r_t| < mu r_n) or
    // slip (|r_t| = mu r_n, mu = 0.3), different at every node.
    unsigned int n_active = 0;
    for (auto &node : pair.nodes())
      if (node.active)
        {
          const double r_n = 1. + 0.4 * std::sin(1.3 * n_active);
          const double r_t =
            law == "frictionless" ? 0. :
            law == "stick"        ? 0.1 * r_n * std::cos(2.1 * n_active) :
                                    (n_active % 2 ? 0.3 : -0.3) * r_n;
          node.reaction = {{r_t, r_n}};
          ++n_active;
        }
    pair.update_geometry();
    check(n_active >= 3, "at least three active nodes");
    if (master.size() > 4 && master.compare(master.size() - 4, 4, "_end") == 0)
      {
        std::cout << "  " << n_active << " of " << pair.nodes().size()
                  << " slave points before the obstacle's end" << std::endl;
        // (the three slave points past x = 0.6 out, and every point
        // before it in, the last one's face crossing the end)
        check(n_active + 3 == pair.nodes().size(),
              "the points before the obstacle's end in contact, those past "
              "it out");
      }
    if (master == "faceted_vertex")
      {
        unsigned int at_vertex = 0;
        for (const auto &node : pair.nodes())
          at_vertex += node.active && node.linearization.vertex_cone > 0.;
        std::cout << "  " << at_vertex << " nodes at a vertex with its cone"
                  << std::endl;
        check(at_vertex >= 2, "at least two nodes at a vertex");
      }
    if (master == "hermite_corner")
      {
        unsigned int at_corner = 0;
        for (const auto &node : pair.nodes())
          at_corner += node.active && node.s == 0.;
        std::cout << "  " << at_corner << " nodes met at the corner"
                  << std::endl;
        check(at_corner >= 3, "at least three nodes met at the corner");
      }

    // The dofs the contact touches, and the assembled tangent over them.
    std::map<std::pair<unsigned int, types::global_dof_index>, unsigned int>
               index;
    const auto add = [&](const DofVector &v) {
      for (const auto &e : v)
        index.emplace(std::make_pair(e.body, e.dof), 0);
    };
    for (const auto &node : pair.nodes())
      if (node.active)
        {
          for (const DofVector *v : {&node.linearization.gap_row,
                                     &node.linearization.slip_row,
                                     &node.linearization.tangential_force,
                                     &node.linearization.normal_force})
            add(*v);
          for (const auto &term : node.linearization.tangent_terms)
            {
              add(term.load);
              add(term.row);
            }
        }
    std::vector<std::pair<unsigned int, types::global_dof_index>> dofs;
    for (auto &[key, i] : index)
      {
        i = dofs.size();
        dofs.push_back(key);
      }
    const unsigned int m = dofs.size();
    FullMatrix<double> tangent(m, m), difference(m, m);
    FullMatrix<double> gap_rows(n_active, m), gap_difference(n_active, m);
    FullMatrix<double> slip_rows(n_active, m), slip_difference(n_active, m);
    unsigned int       k = 0;
    for (const auto &node : pair.nodes())
      if (node.active)
        {
          const auto &l = node.linearization;
          for (const auto &term : l.tangent_terms)
            for (const auto &a : term.load)
              for (const auto &b : term.row)
                tangent(index[{a.body, a.dof}], index[{b.body, b.dof}]) +=
                  a.value * b.value;
          for (const auto &e : l.gap_row)
            gap_rows(k, index[{e.body, e.dof}]) += e.value;
          for (const auto &e : l.slip_row)
            slip_rows(k, index[{e.body, e.dof}]) += e.value;
          ++k;
        }

    // Central differences of F, g and u_t, the nodes keeping their segment.
    const double h     = 1e-6;
    const auto   state = [&](std::vector<double> &forces,
                           std::vector<double> &gaps,
                           std::vector<double> &slips) {
      pair.update_geometry();
      const auto f = pair.contact_forces();
      forces.assign(m, 0.);
      for (unsigned int i = 0; i < m; ++i)
        forces[i] = f[dofs[i].first](dofs[i].second);
      gaps.clear();
      slips.clear();
      for (const auto &node : pair.nodes())
        if (node.active)
          {
            gaps.push_back(node.linearization.gap);
            slips.push_back(node.linearization.slip);
          }
    };
    for (unsigned int j = 0; j < m; ++j)
      {
        Body          &body = *bodies[dofs[j].first];
        Vector<double> step(body.n_dofs());
        step(dofs[j].second) = h;
        std::vector<double> f_plus, f_minus, g_plus, g_minus, s_plus, s_minus;
        body.update(step);
        state(f_plus, g_plus, s_plus);
        step *= -2.;
        body.update(step);
        state(f_minus, g_minus, s_minus);
        step *= -0.5;
        body.update(step);
        check(g_plus.size() == n_active && g_minus.size() == n_active,
              "a node left the contact under the perturbation");
        for (unsigned int i = 0; i < m; ++i)
          difference(i, j) = (f_plus[i] - f_minus[i]) / (2. * h);
        for (unsigned int i = 0; i < n_active; ++i)
          {
            gap_difference(i, j)  = (g_plus[i] - g_minus[i]) / (2. * h);
            slip_difference(i, j) = (s_plus[i] - s_minus[i]) / (2. * h);
          }
      }
    pair.update_geometry();

    const auto compare = [&](const FullMatrix<double> &assembled,
                             const FullMatrix<double> &differenced,
                             const std::string        &what) {
      double error = 0., largest = 0.;
      for (unsigned int i = 0; i < assembled.m(); ++i)
        for (unsigned int j = 0; j < assembled.n(); ++j)
          {
            error =
              std::max(error, std::abs(assembled(i, j) - differenced(i, j)));
            largest = std::max(largest, std::abs(differenced(i, j)));
          }
      std::cout << "  " << master << ", " << law << ": " << what << " ("
                << assembled.m() << " x " << assembled.n()
                << "): largest entry " << largest
                << ", largest difference to the finite differences " << error
                << " (relative " << error / largest << ")" << std::endl;
      // A rigid line's contact tangent is zero: both must be, exactly.
      check(error <= 1e-6 * largest || error == 0.,
            what + " differs from finite differences");
    };
    std::cout << "  " << n_active << " active nodes, " << m << " dofs"
              << std::endl;
    compare(tangent, difference, "contact tangent dF/dU at fixed r");
    compare(gap_rows, gap_difference, "gap rows dg/dU");
    compare(slip_rows, slip_difference, "slip rows du_t/dU");
  }
} // namespace

#define CONTACT_TANGENT_TEST(master, law)         \
  GLISSADE_TEST(contact_tangent_##master##_##law) \
  {                                               \
    check_contact_tangent(#master, #law);         \
  }

CONTACT_TANGENT_TEST(faceted, frictionless)
CONTACT_TANGENT_TEST(faceted, stick)
CONTACT_TANGENT_TEST(faceted, slip)
CONTACT_TANGENT_TEST(faceted_vertex, frictionless)
CONTACT_TANGENT_TEST(faceted_vertex, stick)
CONTACT_TANGENT_TEST(faceted_vertex, slip)
CONTACT_TANGENT_TEST(bspline_segment, frictionless)
CONTACT_TANGENT_TEST(bspline_segment, stick)
CONTACT_TANGENT_TEST(bspline_segment, slip)
CONTACT_TANGENT_TEST(bspline_spline, frictionless)
CONTACT_TANGENT_TEST(bspline_spline, stick)
CONTACT_TANGENT_TEST(bspline_spline, slip)
CONTACT_TANGENT_TEST(hermite, frictionless)
CONTACT_TANGENT_TEST(hermite, stick)
CONTACT_TANGENT_TEST(hermite, slip)
CONTACT_TANGENT_TEST(hermite_corner, frictionless)
CONTACT_TANGENT_TEST(hermite_corner, slip)
CONTACT_TANGENT_TEST(nurbs, frictionless)
CONTACT_TANGENT_TEST(nurbs, stick)
CONTACT_TANGENT_TEST(nurbs, slip)
CONTACT_TANGENT_TEST(nurbs3, frictionless)
CONTACT_TANGENT_TEST(nurbs3, slip)
CONTACT_TANGENT_TEST(nurbs_slave, frictionless)
CONTACT_TANGENT_TEST(nurbs_slave, slip)
CONTACT_TANGENT_TEST(nurbs_on_nurbs, frictionless)
CONTACT_TANGENT_TEST(nurbs_on_nurbs, stick)
CONTACT_TANGENT_TEST(nurbs_on_nurbs, slip)
CONTACT_TANGENT_TEST(mortar, frictionless)
CONTACT_TANGENT_TEST(mortar, stick)
CONTACT_TANGENT_TEST(mortar, slip)
CONTACT_TANGENT_TEST(mortar_bspline, frictionless)
CONTACT_TANGENT_TEST(mortar_bspline, slip)
CONTACT_TANGENT_TEST(mortar_bspline_spline, slip)
CONTACT_TANGENT_TEST(mortar_hermite, frictionless)
CONTACT_TANGENT_TEST(mortar_hermite, slip)
CONTACT_TANGENT_TEST(mortar_nurbs, frictionless)
CONTACT_TANGENT_TEST(mortar_nurbs, slip)
CONTACT_TANGENT_TEST(mortar_nurbs_slave, frictionless)
CONTACT_TANGENT_TEST(mortar_nurbs_slave, slip)
CONTACT_TANGENT_TEST(mortar_nurbs_on_nurbs, frictionless)
CONTACT_TANGENT_TEST(mortar_nurbs_on_nurbs, stick)
CONTACT_TANGENT_TEST(mortar_nurbs_on_nurbs, slip)
CONTACT_TANGENT_TEST(mortar_nurbs_on_nurbs_standard, slip)
CONTACT_TANGENT_TEST(mortar_nurbs_slave_on_disk, frictionless)
CONTACT_TANGENT_TEST(mortar_nurbs_slave_on_disk, stick)
CONTACT_TANGENT_TEST(mortar_nurbs_slave_on_casing, slip)
CONTACT_TANGENT_TEST(mortar_line, slip)
CONTACT_TANGENT_TEST(mortar_disk, frictionless)
CONTACT_TANGENT_TEST(mortar_disk, stick)
CONTACT_TANGENT_TEST(line, frictionless)
CONTACT_TANGENT_TEST(line, stick)
CONTACT_TANGENT_TEST(line, slip)
CONTACT_TANGENT_TEST(disk, frictionless)
CONTACT_TANGENT_TEST(disk, stick)
CONTACT_TANGENT_TEST(disk, slip)
CONTACT_TANGENT_TEST(hole, frictionless)
CONTACT_TANGENT_TEST(hole, stick)
CONTACT_TANGENT_TEST(hole, slip)
CONTACT_TANGENT_TEST(nurbs_curve, frictionless)
CONTACT_TANGENT_TEST(nurbs_curve, stick)
CONTACT_TANGENT_TEST(nurbs_curve, slip)
CONTACT_TANGENT_TEST(mortar_nurbs_curve, slip)
CONTACT_TANGENT_TEST(mortar_nurbs_slave_on_nurbs_curve, slip)
CONTACT_TANGENT_TEST(nurbs_curve_end, slip)
CONTACT_TANGENT_TEST(mortar_nurbs_curve_end, frictionless)
CONTACT_TANGENT_TEST(mortar_nurbs_curve_end, slip)
CONTACT_TANGENT_TEST(mortar_nurbs_slave_on_nurbs_curve_end, slip)
CONTACT_TANGENT_TEST(casing, frictionless)
CONTACT_TANGENT_TEST(casing, stick)
CONTACT_TANGENT_TEST(casing, slip)

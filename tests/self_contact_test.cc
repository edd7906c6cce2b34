// Self-contact (issue 53): a pair whose master is its slave's own body.
// Checked against the balance laws and the geometry of the deformed body,
// not against the code's own figures.

#include <deal.II/dofs/dof_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <tuple>

#include "body_resultant.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /** An output directory of the run's own (own_output_directory). */
  std::vector<std::string>
  own_directory(const std::string &label)
  {
    return own_output_directory("self_contact_", label);
  }

  /**
   * The same, with Newton to 1e-9: at t = 1 the folded ring's residual
   * stalls at 1.5-4.5e-10 under OpenBLAS's Haswell kernel (B-spline
   * mortar), a verdict round-off would decide at the scene's 1e-10.
   */
  std::vector<std::string>
  own_directory_newton_1e9(const std::string &label)
  {
    std::vector<std::string> overrides = own_directory(label);
    overrides.push_back("Newton/Residual tolerance=1e-9");
    return overrides;
  }

  /**
   * A ring (r in [0.7, 1], 96 x 4 Q4 cells) pinched between two rigid
   * plates that close by 0.8 each, until its inner wall is pressed onto
   * itself over a flat stretch: the pair 'inner' is the inner boundary on
   * itself, or one half of it on the other (`slave`, `master`: inner_top,
   * inner_bottom, Mesh/Boundary parts). Held in x at the two points the
   * plates first touch.
   */
  std::string
  pinched_ring(const std::string &surface,
               const bool         found          = false,
               const std::string &slave          = "inner",
               const std::string &master         = "inner",
               const std::string &discretisation = "node-to-segment")
  {
    std::string prm =
      "subsection Scene\n set Bodies = ring\n" +
      std::string(found ? " set Contact pairs = top, bottom\n"
                          " set Contact bodies = ring: inner\n" :
                          " set Contact pairs = top, bottom, inner\n") +
      "end\n"
      "subsection Body ring\n subsection Mesh\n"
      "  set Type = ring\n  set Inner radius = 0.7\n"
      "  set Outer radius = 1\n  set Subdivisions = 96, 4\n" +
      std::string(slave == "inner" ?
                    "" :
                    "  set Boundary parts = inner_top: inner: y > 0; "
                    "inner_bottom: inner: y < 0\n") +
      " end\n subsection Material\n"
      "  set Young modulus = 1000\n  set Poisson ratio = 0.3\n"
      " end\n subsection Boundary conditions\n"
      "  set Fixed = point(0, 1): x; point(0, -1): x\n"
      " end\nend\n";
    for (const auto &[name, side] :
         {std::pair<std::string, std::string>{"top", "1"}, {"bottom", "-1"}})
      prm += "subsection Contact " + name +
             "\n set Slave body = ring\n set Slave boundary = outer\n"
             " set Alert distance = 0.02\n subsection Obstacle\n"
             "  set Type = line\n  set Point = 0, " +
             side + "\n  set Normal = 0, " + (side == "1" ? "-1" : "1") +
             "\n  set Motion = 0, " + (side == "1" ? "-" : "") +
             "0.8*t\n end\nend\n";
    return prm +
           (found ?
              "subsection Automatic contact\n set Self-contact = true\n" :
              "subsection Contact inner\n set Slave body = ring\n"
              " set Slave boundary = " +
                slave + "\n set Master body = ring\n set Master boundary = " +
                master + "\n") +
           " set Surface = " + surface +
           "\n set Discretisation = " + discretisation +
           "\n set Alert distance = 0.02\nend\n"
           "subsection Output\n set Progress = false\nend\n"
           "subsection Newton\n set Residual tolerance = 1e-10\n"
           " set Displacement tolerance = 1e-10\nend\n"
           "subsection Contact solver\n set Tolerance = 1e-13\nend\n";
  }


  /**
   * A self-contact pair's figures: its forces on the body summed (zero:
   * action and reaction are both on it), what it carries, and its deepest
   * active slave gap.
   */
  struct SelfContactFigures
  {
    explicit SelfContactFigures(const ContactPair &pair)
    {
      const auto     forces  = pair.contact_forces();
      Vector<double> on_body = forces[0];
      on_body += forces[1];
      sum     = resultant(pair.slave(), on_body);
      carried = pair.total_force().norm();
      for (const auto &node : pair.nodes())
        if (node.active)
          deepest = std::min(deepest, node.gap);
    }
    Tensor<1, 2> sum;
    double       carried = 0.;
    double       deepest = 0.;
  };


  /**
   * For each dof of a body meshed symmetrically about the origin, the dof
   * of the same component at the support point turned by half a turn, so
   * that v_turned[i] = -v[image[i]] is the field turned by half a turn:
   * v(x) -> -v(-x).
   */
  std::vector<types::global_dof_index>
  half_turn(const Body &body)
  {
    std::map<types::global_dof_index, Point<2>> support;
    DoFTools::map_dofs_to_support_points(body.space().mapping(),
                                         body.dof_handler(),
                                         support);
    const auto &fe = body.dof_handler().get_fe();
    std::map<std::tuple<long, long, unsigned int>, types::global_dof_index> at;
    const auto key = [](const Point<2> &x, const unsigned int component) {
      return std::make_tuple(std::lround(x[0] * 1e9),
                             std::lround(x[1] * 1e9),
                             component);
    };
    std::vector<unsigned int> component(support.size());
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          component[dofs[i]] = fe.system_to_component_index(i).first;
      }
    for (const auto &[dof, x] : support)
      at[key(x, component[dof])] = dof;
    std::vector<types::global_dof_index> image(support.size());
    bool                                 symmetric = true;
    for (const auto &[dof, x] : support)
      {
        const auto turned = at.find(key(-x, component[dof]));
        symmetric         = symmetric && turned != at.end();
        image[dof]        = symmetric ? turned->second : dof;
      }
    check(symmetric, "the mesh is not symmetric about its centre");
    return image;
  }


  /**
   * How far a node of the deformed inner boundary lies behind the polygon
   * of its faces that face it (negative: inside the wall), the nodes next
   * to each face left out: the deepest over every node, from the positions
   * alone.
   */
  double
  deepest_node_behind_facing_faces(const ContactPair &pair)
  {
    const Body           &ring  = pair.slave();
    const auto           &nodes = pair.nodes();
    const auto           &faces = pair.slave_faces();
    const Vector<double> &u     = ring.displacement();
    std::vector<Point<2>> x(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      x[k] = nodes[k].reference_position + nodes[k].displacement(u);
    // Each face's outward normal (the wall's: towards the ring's centre
    // in the reference state), and each node's from its two faces.
    std::vector<Tensor<1, 2>> face_normal(faces.size());
    std::vector<Tensor<1, 2>> node_normal(nodes.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        const auto [a, b] = faces[f];
        const Tensor<1, 2> reference =
          nodes[b].reference_position - nodes[a].reference_position;
        const Tensor<1, 2> mid =
          0.5 * (nodes[a].reference_position + nodes[b].reference_position);
        const double side =
          Tensor<1, 2>({reference[1], -reference[0]}) * (-mid) > 0. ? 1. : -1.;
        const Tensor<1, 2> along = x[b] - x[a];
        face_normal[f] =
          side * Tensor<1, 2>({along[1], -along[0]}) / along.norm();
        node_normal[a] += face_normal[f];
        node_normal[b] += face_normal[f];
      }
    double deepest = 0.;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          const auto [a, b] = faces[f];
          bool near         = (a == k || b == k);
          for (const auto &[c, d] : faces)
            if ((c == k || d == k) && (c == a || c == b || d == a || d == b))
              near = true;
          if (near || face_normal[f] * node_normal[k] >= 0.)
            continue;
          const Tensor<1, 2> along = x[b] - x[a];
          const double       s = (x[k] - x[a]) * along / along.norm_square();
          const double       d = (x[k] - x[a]) * face_normal[f];
          // (no deeper than half a face: deeper is the wall's other side)
          if (s >= 0. && s <= 1. && d > -0.5 * along.norm())
            deepest = std::min(deepest, d);
        }
    return deepest;
  }



  /** The pinched ring's self-contact written as a pair and found by
   *  automatic contact: the same ring and forces, to 1e-10. */
  void
  found_as_written(const std::string &discretisation)
  {
    double                                     difference = 0., scale = 0.;
    std::array<std::unique_ptr<Simulation>, 2> runs;
    for (const bool found : {false, true})
      {
        runs[found] = std::make_unique<Simulation>(SceneReader::read_string(
          pinched_ring("bspline", found, "inner", "inner", discretisation),
          "ring",
          own_directory_newton_1e9((found ? "found " : "written ") +
                                   discretisation)));
        for (unsigned int k = 1; k <= 80; ++k)
          runs[found]->advance_to(k / 80., "increment " + std::to_string(k));
      }
    const ContactPair &found = *runs[1]->contact().contact_pairs()[2];
    check(found.name() == "ring on itself",
          "the pair found is named '" + found.name() + "'");
    for (const bool forces : {false, true})
      {
        const Body    &written_ring = runs[0]->body("ring");
        const Body    &found_ring   = runs[1]->body("ring");
        Vector<double> d = forces ? written_ring.get_contact_forces() :
                                    written_ring.displacement();
        d -=
          forces ? found_ring.get_contact_forces() : found_ring.displacement();
        difference = std::max(difference, d.linfty_norm());
        scale =
          std::max(scale, written_ring.get_contact_forces().linfty_norm());
      }
    std::cout << "  " << discretisation << ": 'ring on itself' active nodes "
              << found.n_active()
              << ", largest difference from the pair written " << difference
              << std::endl;
    check(found.n_active() >= 20, "no self-contact found");
    check(difference <= 1e-10 * scale,
          "automatic self-contact differs from the pair written");
  }


  /**
   * The pinched ring run to t = 1 in 80 increments: the plates' force at
   * each (as a positive load), checked equal and opposite on the two
   * plates at every increment, and when the inner wall first met itself
   * (-1 if never).
   */
  struct PinchedRingRun
  {
    std::vector<double> plate_force;
    double              first_contact = -1.;

    /** The plates' force's change in the first self-contact step. */
    double
    jump_at_first_contact() const
    {
      const unsigned int first = std::lround(first_contact * 80.) - 1;
      return plate_force[first] - plate_force[first - 1];
    }

    /** The largest change of the three steps after it. */
    double
    largest_change_after() const
    {
      const unsigned int first = std::lround(first_contact * 80.) - 1;
      double             after = 0.;
      for (unsigned int k = first + 1; k <= first + 3 && k < 80; ++k)
        after = std::max(after, plate_force[k] - plate_force[k - 1]);
      return after;
    }
  };

  PinchedRingRun
  pinch(Simulation &simulation, const std::string &label)
  {
    const auto    &pairs = simulation.contact().contact_pairs();
    PinchedRingRun run;
    for (unsigned int k = 1; k <= 80; ++k)
      {
        simulation.advance_to(k / 80., "increment " + std::to_string(k));
        run.plate_force.push_back(-pairs[0]->total_force()[1]);
        if (run.first_contact < 0. && pairs[2]->n_active() > 0)
          run.first_contact = k / 80.;
        const double top    = pairs[0]->total_force()[1];
        const double bottom = pairs[1]->total_force()[1];
        check(std::abs(top + bottom) <= 1e-9 * std::abs(top),
              label + ": the plates' forces differ at increment " +
                std::to_string(k));
      }
    return run;
  }


  /**
   * What every quasi-static pinched ring shows, printed and checked: the
   * wall meets itself between t = 0.8 and 0.95, at least 20 nodes hold
   * it, the self-contact's forces on the ring sum to zero (its action and
   * reaction are both on it), no active node's gap is below zero, no node
   * of the wall is behind a face of it that faces it beyond a fraction of
   * a face (read from the deformed positions alone), and the plates' force
   * grows on through the first self-contact without a jump larger than
   * the steps after it make.
   */
  void
  check_pinched_ring(const PinchedRingRun &run,
                     const ContactPair    &inner,
                     const std::string    &label)
  {
    const SelfContactFigures figures(inner);
    const double             behind = deepest_node_behind_facing_faces(inner);
    const double             jump   = run.jump_at_first_contact();
    const double             after  = run.largest_change_after();
    std::cout << "  " << label
              << ": first self-contact at t = " << run.first_contact << ", "
              << inner.n_active() << " nodes active at the end carrying "
              << figures.carried << "; plates " << run.plate_force.back()
              << "; the self-contact's forces on the ring sum to ("
              << figures.sum << "); deepest active gap " << figures.deepest
              << "; deepest node behind a facing face " << behind
              << "; the plates' force changes by " << jump
              << " at first contact, by at most " << after
              << " in the three steps after" << std::endl;
    check(run.first_contact > 0.8 && run.first_contact < 0.95,
          label + ": the inner wall met itself at t = " +
            std::to_string(run.first_contact));
    check(inner.n_active() >= 20, label + ": too few nodes in contact");
    check(figures.sum.norm() <= 1e-10 * figures.carried,
          label + ": the self-contact's forces do not sum to zero");
    check(figures.deepest >= -1e-8 * 0.7,
          label + ": an active node's gap below zero");
    // One pass: the nodes (faces) of the earlier stretch hold the contact,
    // and where the wall folds tighter than a face (the two tips of the
    // flattened hole) a node of the later stretch may pass a face of the
    // earlier one by a fraction of the face (measured 1.1e-3 with a
    // B-spline master and node-to-segment: a fortieth of a face, 0.046).
    check(behind >= -0.05 * 0.046,
          label + ": the inner wall passes through itself");
    check(jump > 0. && jump <= after,
          label + ": the plates' force jumps at first self-contact");
  }


  /**
   * The pinched ring's scene under Newmark: the plates at a tenth of the
   * quasi-static speed (0.08 t, where the ring's waves run at 31), 400
   * steps to t = 10, so that the end is the quasi-static run's t = 1.
   */
  std::string
  under_newmark(std::string prm)
  {
    for (std::string::size_type at;
         (at = prm.find("0.8*t")) != std::string::npos;)
      prm.replace(at, 5, "0.08*t");
    return prm + "subsection Time integration\n set Scheme = newmark\nend\n"
                 "subsection Load program\n set Stage end times = 10\n"
                 " set Stage increments = 400\nend\n";
  }
} // namespace

// The pinched ring: its inner wall meets itself at t = 0.87-0.89 and is
// then pressed flat. The plates' forces are equal and opposite; the
// self-contact's forces on the ring sum to zero (its action and reaction
// are both on the one body); no node of the inner wall is behind a face of
// it that faces it (read from the deformed positions alone); the plates'
// force grows on through the first self-contact without a jump larger than
// the steps after it make; no slave node behind its master.
GLISSADE_TEST(self_contact_pinched_ring)
{
  for (const std::string surface : {"bspline", "faceted"})
    {
      Simulation simulation(
        SceneReader::read_string(pinched_ring(surface),
                                 "pinched ring",
                                 own_directory("pinched " + surface)));
      const PinchedRingRun run = pinch(simulation, surface);
      check_pinched_ring(run,
                         *simulation.contact().contact_pairs()[2],
                         surface);
    }
}

// The pinched ring with mortar self-contact (each face of the inner wall
// integrated against the later stretch of the wall that faces it): the
// same checks as node-to-segment's, and the plates' force of the
// node-to-segment pair on the same master, which it must approach (two
// discretisations of one contact).
GLISSADE_TEST(self_contact_pinched_ring_mortar)
{
  for (const std::string surface : {"faceted", "bspline"})
    {
      double reference = 0.;
      for (const std::string discretisation : {"node-to-segment", "mortar"})
        {
          Simulation           simulation(SceneReader::read_string(
            pinched_ring(surface, false, "inner", "inner", discretisation),
            "pinched ring",
            own_directory_newton_1e9("pinched " + surface + " " +
                                     discretisation)));
          const PinchedRingRun run =
            pinch(simulation, surface + " " + discretisation);
          const std::vector<double> &plate_force = run.plate_force;
          if (discretisation != "mortar")
            {
              reference = plate_force.back();
              continue;
            }
          check_pinched_ring(run,
                             *simulation.contact().contact_pairs()[2],
                             "mortar, " + surface);
          std::cout << "  mortar, " << surface << ": node-to-segment's plates "
                    << reference << std::endl;
          check(std::abs(plate_force.back() - reference) <= 0.01 * reference,
                surface + ": the plates' force is not node-to-segment's");
          if (surface != "faceted")
            continue;
          // The wall as two halves, each the slave of the other in turn:
          // the same contact at every step, to t = 1.
          for (const auto &[slave, master] :
               {std::pair<std::string, std::string>{"inner_top",
                                                    "inner_bottom"},
                {"inner_bottom", "inner_top"}})
            {
              Simulation halves(SceneReader::read_string(
                pinched_ring(surface, false, slave, master, "mortar"),
                "pinched ring",
                own_directory_newton_1e9("pinched mortar " + slave)));
              double     apart = 0.;
              for (unsigned int k = 1; k <= 80; ++k)
                {
                  halves.advance_to(k / 80., "increment " + std::to_string(k));
                  apart = std::max(
                    apart,
                    std::abs(
                      -halves.contact().contact_pairs()[0]->total_force()[1] -
                      plate_force[k - 1]));
                }
              std::cout << "  mortar, " << slave << " on " << master
                        << ": the plates' force from the one boundary's by at "
                           "most "
                        << apart << std::endl;
              check(apart <= 1e-8 * plate_force.back(),
                    slave + " on " + master +
                      ": the halves are not the one boundary");
            }
        }
    }
}

// The same self-contact found by automatic contact (Contact bodies = ring:
// inner, Self-contact = true): the pair 'ring on itself' gives the ring
// the displacements and contact forces of the pair written by hand, with
// node-to-segment and with mortar contact.
GLISSADE_TEST(self_contact_found_by_automatic_contact)
{
  for (const std::string discretisation : {"node-to-segment", "mortar"})
    found_as_written(discretisation);
}

// The inner wall as one boundary on itself, and as two halves (Mesh/
// Boundary parts: y > 0, y < 0), the upper half on the lower and the lower
// on the upper (one pass each), with a faceted master (a B-spline over a
// half is an open curve, whose end conditions at the fold tips are not the
// closed curve's): the same contact, so the same plates' force at every
// step to t = 0.95 and the same ring at t = 0.95, to 1e-8. One pass is not
// symmetric: the slave side carries the contact, and the one boundary
// gives it to the upper half, so its ring is the upper half on the lower's
// and the lower half on the upper's turned by half a turn (the scene's own
// symmetry, which keeps the curves' sense: compared as they are, the rings
// differ by 0.3 % of the largest displacement near the fold tips, and by
// 2e-4 with the mirror image y -> -y, which reverses it). The one
// boundary counts one node more active: a lower node within the alert
// distance and carrying nothing, which the halves hold as a master node
// only. Past t = 0.975 the two are different discretisations: the one
// boundary's order along the chain (CurveSurface::project_facing) makes a
// lower node next to a fold tip, (0.694, -0.091), the slave of the upper
// wall there and it carries (3.4 at t = 0.9875), where in the halves it is
// a master node only; the halves' Newton then stops at t = 0.9875 with 80
// increments (it reaches t = 1 with 100).
GLISSADE_TEST(self_contact_inner_wall_as_two_halves)
{
  std::vector<std::vector<double>>     plates;
  std::vector<Vector<double>>          rings;
  std::vector<unsigned int>            active;
  std::vector<types::global_dof_index> image;
  for (const auto &[slave, master] :
       {std::pair<std::string, std::string>{"inner", "inner"},
        {"inner_top", "inner_bottom"},
        {"inner_bottom", "inner_top"}})
    {
      // (Newton to 1e-9: the halves' residual stalls at 1.2-1.9e-10 from t
      // = 0.9125 on with another BLAS kernel, round-off of the folded wall)
      std::vector<std::string> overrides =
        own_directory(slave + " on " + master);
      overrides.push_back("Newton/Residual tolerance=1e-9");
      Simulation simulation(
        SceneReader::read_string(pinched_ring("faceted", false, slave, master),
                                 slave + " on " + master,
                                 overrides));
      const auto &pairs = simulation.contact().contact_pairs();
      plates.emplace_back();
      for (unsigned int k = 1; k <= 76; ++k)
        {
          simulation.advance_to(k / 80., "increment " + std::to_string(k));
          plates.back().push_back(pairs[0]->total_force()[1]);
        }
      rings.push_back(simulation.body("ring").displacement());
      active.push_back(pairs[2]->n_active());
      if (image.empty())
        image = half_turn(simulation.body("ring"));
    }
  for (const unsigned int halves : {1u, 2u})
    {
      double force = 0., scale = 0.;
      for (unsigned int k = 0; k < plates[0].size(); ++k)
        {
          force = std::max(force, std::abs(plates[halves][k] - plates[0][k]));
          scale = std::max(scale, std::abs(plates[0][k]));
        }
      // The lower half on the upper is the one boundary turned by half a
      // turn.
      Vector<double> d = rings[halves];
      if (halves == 2)
        for (unsigned int i = 0; i < d.size(); ++i)
          d[i] = -rings[2][image[i]];
      d -= rings[0];
      std::cout << "  " << (halves == 1 ? "upper on lower" : "lower on upper")
                << ": " << active[halves]
                << " nodes active (one boundary: " << active[0]
                << "); the plates' force differs by at most " << force / scale
                << " of " << scale << "; the ring's displacement at t = 0.95"
                << (halves == 1 ? "" : ", turned by half a turn,") << " by "
                << d.linfty_norm() / rings[0].linfty_norm() << " of its largest"
                << std::endl;
      check(active[halves] >= 20, "too few nodes in contact");
      check(force <= 1e-8 * scale,
            "the plates' force differs from the one boundary's");
      check(d.linfty_norm() <= 1e-8 * rings[0].linfty_norm(),
            "the ring differs from the one boundary's");
    }
}

// The pinched ring under Newmark, the plates ten times slower (0.08 t to
// t = 10, 400 steps): the inner wall meets itself and is pressed flat with
// no step whose contact works positively (before the forces over a step,
// from t = 9.2 the contact's work of a step was positive and grew 2.5
// times a step until a cell inverted), the self-contact's forces summing
// to zero on the ring, no slave node behind its master, and the plates'
// force at the end within 5 % of the quasi-static one at the same
// squeeze (the plates move at 0.08 where the ring's waves run at 31).
GLISSADE_TEST(self_contact_pinched_ring_under_newmark)
{
  const std::string        prm       = under_newmark(pinched_ring("bspline"));
  std::vector<std::string> overrides = own_directory("pinched newmark");
  overrides.push_back("Body ring/Material/Density=1");
  Simulation simulation(SceneReader::read_string(prm, "ring.prm", overrides));
  simulation.run();
  const auto              &pairs = simulation.contact().contact_pairs();
  const ContactPair       &inner = *pairs[2];
  const SelfContactFigures figures(inner);
  const Tensor<1, 2>      &sum     = figures.sum;
  const double             carried = figures.carried;
  const double             deepest = figures.deepest;
  const double             plates  = -pairs[0]->total_force()[1];

  Simulation quasi_static(
    SceneReader::read_string(pinched_ring("bspline"),
                             "ring.prm",
                             own_directory("pinched newmark reference")));
  for (unsigned int k = 1; k <= 80; ++k)
    quasi_static.advance_to(k / 80., "increment " + std::to_string(k));
  const double reference =
    -quasi_static.contact().contact_pairs()[0]->total_force()[1];

  const EnergyAccount &account = *simulation.energies();
  std::cout << "  steps whose contact created energy "
            << account.contact_creating_steps << "; " << inner.n_active()
            << " self-contact nodes active at the end carrying " << carried
            << ", their forces on the ring summing to (" << sum
            << "); deepest slave gap " << deepest << "; plates " << plates
            << " (quasi-static " << reference << ")" << std::endl;
  check(account.contact_creating_steps == 0, "the contact created energy");
  check(inner.n_active() >= 20, "too few self-contact nodes active");
  check(sum.norm() <= 1e-10 * carried,
        "the self-contact's forces do not sum to zero");
  check(deepest >= -1e-8 * 0.7, "a slave node behind its master");
  check(std::abs(plates - reference) <= 0.05 * reference,
        "the plates' force is not the quasi-static one");
}

// Mortar self-contact under Newmark, as the node-to-segment pair above, to
// t = 10 (the plates closed by 0.8 each): no step whose contact works
// positively, the forces on the ring summing to zero, no weighted gap
// below zero, and the plates' force within 3 % of the quasi-static run's
// at the same squeeze. (Its forces over a step are discrete gradients of
// the weighted gap's own gradient, which carries the turn of the nodal
// normals and the change of the mortar weights: with mortar's normal
// force in their place the run stalled at t = 9.425.)
GLISSADE_TEST(self_contact_pinched_ring_mortar_under_newmark)
{
  // (faceted: on the B-spline master the same run takes 100 s, 91 % of it
  // integrating the faces over the closed interpolating spline, each of
  // whose points moves with every node of the wall)
  for (const std::string surface : {"faceted"})
    {
      const std::string quasi_static_prm =
        pinched_ring(surface, false, "inner", "inner", "mortar");
      const std::string        prm = under_newmark(quasi_static_prm);
      std::vector<std::string> overrides =
        own_directory("pinched mortar newmark " + surface);
      overrides.push_back("Body ring/Material/Density=1");
      Simulation simulation(
        SceneReader::read_string(prm, "ring.prm", overrides));
      simulation.run();
      const auto              &pairs = simulation.contact().contact_pairs();
      const ContactPair       &inner = *pairs[2];
      const SelfContactFigures figures(inner);
      const double             plates = -pairs[0]->total_force()[1];

      Simulation quasi_static(SceneReader::read_string(
        quasi_static_prm,
        "ring.prm",
        own_directory("pinched mortar newmark reference " + surface)));
      for (unsigned int k = 1; k <= 80; ++k)
        quasi_static.advance_to(k / 80., "increment " + std::to_string(k));
      const double reference =
        -quasi_static.contact().contact_pairs()[0]->total_force()[1];

      const EnergyAccount &account = *simulation.energies();
      std::cout << "  " << surface << ": steps whose contact created energy "
                << account.contact_creating_steps << "; " << inner.n_active()
                << " self-contact nodes active carrying " << figures.carried
                << ", their forces on the ring summing to (" << figures.sum
                << "); deepest weighted gap " << figures.deepest << "; plates "
                << plates << " (quasi-static " << reference << ")" << std::endl;
      check(account.contact_creating_steps == 0,
            surface + ": the contact created energy");
      check(inner.n_active() >= 20,
            surface + ": too few self-contact nodes active");
      check(figures.sum.norm() <= 1e-10 * figures.carried,
            surface + ": the self-contact's forces do not sum to zero");
      check(figures.deepest >= -1e-8 * 0.7,
            surface + ": a weighted gap below zero");
      check(std::abs(plates - reference) <= 0.03 * reference,
            surface + ": the plates' force is not the quasi-static one");
    }
}

// Contact solver/Method = sparse (SparseContactStep): the bodies in contact
// and the active nodes' reactions as one sparse system, the statuses by a
// primal-dual active-set iteration. It solves the same contact law as the
// condensed bi-potential method, so each check holds it to a closed form
// (Lame's rings, a uniform pressure, Coulomb's ratio in steady sliding)
// and to the condensed method's answer on the scenes where both run.

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <iomanip>

#include "case3_rings_reference.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  std::unique_ptr<Simulation>
  run(const std::string              &file,
      const std::vector<std::string> &overrides,
      const std::string              &method,
      const std::string              &label)
  {
    std::vector<std::string> all = overrides;
    all.push_back("Contact solver/Method=" + method);
    all.push_back("Output/Progress=false");
    all.push_back("Output/VTU interval=0");
    all.push_back("Output/Directory=sparse_test/" + label + "_" + method);
    auto simulation = std::make_unique<Simulation>(
      SceneReader::read_file(source_path(file), all));
    simulation->run();
    return simulation;
  }

  /** A run, and its Newton iterations in each increment. */
  std::pair<std::unique_ptr<Simulation>, std::vector<unsigned int>>
  run_counting(const std::string              &file,
               const std::vector<std::string> &overrides,
               const std::string              &method,
               const std::string              &label)
  {
    std::vector<std::string> all = overrides;
    all.push_back("Contact solver/Method=" + method);
    all.push_back("Output/Progress=false");
    all.push_back("Output/VTU interval=0");
    all.push_back("Output/Directory=sparse_test/" + label + "_" + method);
    auto simulation = std::make_unique<Simulation>(
      SceneReader::read_file(source_path(file), all));
    std::vector<unsigned int> iterations;
    unsigned int              before = 0;
    simulation->on_increment         = [&](unsigned int, double) {
      const unsigned int total = simulation->statistics().newton_iterations;
      iterations.push_back(total - before);
      before = total;
    };
    simulation->run();
    simulation->on_increment = nullptr;
    return {std::move(simulation), iterations};
  }

} // namespace

// Case 3's rings under the compression alone, inner ring clamped at
// r = 0.5: Lame's ring a = 0.5, b = 2 under p = 400 / (2 pi b), small
// strain (the load strains the rings by about 1e-3). The 40 x 4 meshes
// leave a discretisation error of 0.17 % in u_r(2); the bound is 0.3 %.
GLISSADE_TEST(contact_sparse_rings_lame)
{
  const LameRings lame(1e4);
  const double    b = 2., c = 1.25;
  const double    u_b_lame    = lame.u_outer,
               interface_lame = lame.interface_pressure;
  for (const std::string surface : {"faceted", "bspline"})
    {
      const auto   simulation = run("prm/case3_rings.prm",
                                  {"Load program/Stage end times=1",
                                     "Load program/Stage increments=10",
                                     "Contact interface/Surface=" + surface},
                                  "sparse",
                                  "lame_" + surface);
      const double u = mean_radial_displacement(simulation->body("outer"), b);
      double       sum_rn = 0.;
      for (const auto &node : simulation->contact().contact_pairs()[0]->nodes())
        sum_rn += node.reaction[1];
      const double pressure = sum_rn / (2. * M_PI * c);
      std::cout << "  " << surface << ": u_r(2) " << u << " (Lame " << u_b_lame
                << "), interface pressure " << pressure << " (Lame "
                << interface_lame << ")" << std::endl;
      check_relative(u, u_b_lame, 3e-3, surface + ": u_r(2) against Lame");
      check_relative(pressure,
                     interface_lame,
                     3e-3,
                     surface + ": interface pressure against Lame");
    }
}

// Coulomb's law in steady sliding: a pad slid on a rigid flat has
// F_x / F_y = mu (0.2) once every node slips; along a deformable B-spline
// strip the ratio is a property of the sliding state, the same with 25 and
// 100 increments.
GLISSADE_TEST(contact_sparse_coulomb_steady_sliding)
{
  const auto ratio = [](const Simulation &simulation) {
    const Tensor<1, 2> force = const_cast<Simulation &>(simulation)
                                 .contact()
                                 .contact_pairs()[0]
                                 ->total_force();
    return -force[0] / force[1];
  };
  const double flat =
    ratio(*run("tests/data/pad_on_flat.prm", {}, "sparse", "flat"));
  const double strip_25  = ratio(*run("tests/data/pad_on_strip.prm",
                                     {"Load program/Stage increments=2, 25"},
                                     "sparse",
                                     "strip_25"));
  const double strip_100 = ratio(*run("tests/data/pad_on_strip.prm",
                                      {"Load program/Stage increments=2, 100"},
                                      "sparse",
                                      "strip_100"));
  std::cout << std::setprecision(12) << "  F_x / F_y on the flat " << flat
            << ", along the strip " << strip_25 << " (25 increments), "
            << strip_100 << " (100)" << std::endl;
  check_relative(flat, 0.2, 1e-10, "F_x / F_y on the rigid flat");
  check_relative(strip_25, strip_100, 1e-3, "the strip: 25 against 100");
}

// The same answer as the condensed method, with the same statuses and,
// in every increment, Newton iterations equal or within one (round-off
// decides whether the last correction passes its tolerance): every master
// (faceted with its vertex cones, B-spline, Hermite), friction, a rigid
// roller, a deformable strip. The two methods share the linearisation but
// not the solver of the step.
GLISSADE_TEST(contact_sparse_matches_condensed)
{
  const std::vector<std::string> turn = {"Load program/Stage end times=1, 1.02",
                                         "Load program/Stage increments=5, 10"};
  struct Scene
  {
    std::string              label, file;
    std::vector<std::string> overrides;
  };
  std::vector<Scene> scenes = {{"rings_faceted", "prm/case3_rings.prm", turn},
                               {"rings_bspline", "prm/case3_rings.prm", turn},
                               {"rings_hermite", "prm/case3_rings.prm", turn},
                               {"rings_friction", "prm/case3_rings.prm", turn},
                               {"roller", "prm/pad_on_roller.prm", {}},
                               {"strip", "tests/data/pad_on_strip.prm", {}}};
  scenes[1].overrides.push_back("Contact interface/Surface=bspline");
  scenes[2].overrides.push_back("Contact interface/Surface=hermite");
  scenes[2].overrides.push_back("Body outer/Element/Space=hermite");
  scenes[3].overrides.push_back("Contact interface/Friction coefficient=0.3");
  for (const Scene &scene : scenes)
    {
      const auto [condensed, iterations_condensed] =
        run_counting(scene.file, scene.overrides, "condensed", scene.label);
      const auto [sparse, iterations_sparse] =
        run_counting(scene.file, scene.overrides, "sparse", scene.label);
      double difference = 0., largest = 0.;
      for (const std::string name : {"inner", "outer", "pad", "strip"})
        {
          const Body *a = nullptr, *b = nullptr;
          try
            {
              a = &condensed->body(name);
              b = &sparse->body(name);
            }
          catch (...)
            {
              continue;
            }
          Vector<double> d = a->displacement();
          d -= b->displacement();
          difference = std::max(difference, d.linfty_norm());
          largest    = std::max(largest, a->displacement().linfty_norm());
        }
      std::cout << "  " << scene.label << ": largest difference of the "
                << "displacements " << difference / largest
                << " of the largest; Newton iterations "
                << condensed->statistics().newton_iterations << " (condensed), "
                << sparse->statistics().newton_iterations << " (sparse)"
                << std::endl;
      check(difference <= 1e-9 * largest,
            scene.label + ": the two methods disagree");
      // The same statuses at the end, node for node: the two methods
      // solve one contact law, and round-off cannot flip a status that
      // the law decides by a finite margin.
      const auto &nodes_a = condensed->contact().contact_pairs()[0]->nodes(),
                 &nodes_b = sparse->contact().contact_pairs()[0]->nodes();
      unsigned int other_status = 0;
      for (unsigned int k = 0; k < nodes_a.size(); ++k)
        other_status += nodes_a[k].status != nodes_b[k].status;
      check(other_status == 0,
            scene.label + ": " + std::to_string(other_status) +
              " slave nodes end with another status");
      check_iterations_within_one(iterations_condensed,
                                  iterations_sparse,
                                  scene.label + " (condensed; sparse)");
    }
}

// A law given by its strain energy alone (Law = energy, make_energy_law):
// its stress and tangent by automatic differentiation against the
// hand-written neo-Hookean and Mooney-Rivlin laws, whose derivatives were
// worked out by hand; the same scene with either law; the formula's input
// errors named. (Its derivatives against finite differences and its law at
// rest are checked with every law's, material_law_test.cc; its patch
// tests with the others', patch_test.cc.)

#include <glissade/base/input_error.h>
#include <glissade/material/energy_law.h>
#include <glissade/material/law_registry.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <iostream>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /** A strain of size `size` with stretch, compression and shear. */
  SymmetricTensor<2, 3>
  strain(const double size)
  {
    SymmetricTensor<2, 3> E;
    E[0][0] = 0.7 * size;
    E[1][1] = -0.43 * size;
    E[2][2] = 0.17 * size;
    E[0][1] = 0.27 * size;
    E[0][2] = -0.13 * size;
    E[1][2] = 0.1 * size;
    return E;
  }

  /** The largest relative differences of `law`'s S and D from
   *  `reference`'s over strains of several sizes; returns the worst at
   *  strains of at least `from` in size. */
  std::array<double, 2>
  compare(const HyperelasticLaw &law,
          const HyperelasticLaw &reference,
          const std::string     &what,
          const double           from)
  {
    std::array<double, 2> worst = {{0., 0.}};
    for (const double size : {0.3, 0.05, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8})
      {
        SymmetricTensor<2, 3> S, S_ref;
        SymmetricTensor<4, 3> D, D_ref;
        law.evaluate(strain(size), S, D);
        reference.evaluate(strain(size), S_ref, D_ref);
        const double stress  = (S - S_ref).norm() / S_ref.norm();
        const double tangent = (D - D_ref).norm() / D_ref.norm();
        const double energy =
          std::abs(law.energy(strain(size)) - reference.energy(strain(size))) /
          std::abs(reference.energy(strain(size)));
        std::cout << "  " << what << ", strain " << size
                  << ": |S - S_ref| / |S_ref| " << stress
                  << ", |D - D_ref| / |D_ref| " << tangent
                  << ", |W - W_ref| / |W_ref| " << energy << std::endl;
        if (size >= from)
          {
            worst[0] = std::max(worst[0], stress);
            worst[1] = std::max(worst[1], tangent);
          }
      }
    return worst;
  }
} // namespace

// The neo-Hookean law as the default formula and as a C++ function, and the
// Mooney-Rivlin law as a formula with constants: stress and tangent equal to
// the hand-written laws' to 1e-12 at strains from 1e-3 to 0.3. Below, the
// energy's derivative mu (I - C^-1) cancels where the hand-written law
// writes C^-1 2 mu E: the stress agrees to about 1e-16 / |E| (reported: 3e-13
// at 1e-4, 1e-8 at 1e-8); the tangent keeps its digits.
GLISSADE_TEST(energy_law_equals_hand_written_laws)
{
  const double lambda = 577., mu = 385., ratio = 0.3;
  const auto   formula     = LawRegistry::create("energy", lambda, mu, {});
  const auto   neo_hookean = LawRegistry::create("neo-Hookean", lambda, mu, {});
  const auto   function =
    make_energy_law("neo-Hookean by its energy",
                    [=](const StrainMeasures &s) -> EnergyNumber {
                      return mu / 2. * (s.I1 - 3.) - mu * s.ln_J +
                             lambda / 2. * s.ln_J * s.ln_J;
                    });
  const auto worst_formula =
    compare(*formula, *neo_hookean, "neo-Hookean formula", 1e-3);
  const auto worst_function =
    compare(*function, *neo_hookean, "neo-Hookean function", 1e-3);

  // Mooney-Rivlin, W = c1 (I1 - 3) + c2 (I2 - 3) - (2 c1 + 4 c2) ln J +
  // lambda_w / 2 (ln J)^2 with c1 = (1 - r) mu / 2, c2 = r mu / 2,
  // lambda_w = lambda - 4 c2 (mooney_rivlin.cc), read as a .prm gives it,
  // r among the formula's constants.
  ParameterHandler prm;
  LawRegistry::declare_parameters(prm);
  prm.set("Strain energy",
          "(1 - r) * mu / 2 * (I1 - 3) + r * mu / 2 * (I2 - 3)"
          " - (1 + r) * mu * lnJ + (lambda - 2 * r * mu) / 2 * lnJ^2");
  prm.set("Strain energy constants", "r = 0.3");
  const auto mooney_formula = LawRegistry::create(
    "energy",
    lambda,
    mu,
    LawRegistry::parse_parameters(prm, "energy", "Material"));
  const auto mooney =
    LawRegistry::create("Mooney-Rivlin", lambda, mu, std::any(ratio));
  const auto worst_mooney =
    compare(*mooney_formula, *mooney, "Mooney-Rivlin formula", 1e-3);

  for (const auto &[worst, what] :
       {std::make_pair(worst_formula, "the neo-Hookean formula"),
        std::make_pair(worst_function, "the neo-Hookean function"),
        std::make_pair(worst_mooney, "the Mooney-Rivlin formula")})
    {
      check(worst[0] <= 1e-12, std::string(what) + ": stress differs");
      check(worst[1] <= 1e-12, std::string(what) + ": tangent differs");
    }
}

// Case 3's rings pressed together and turned by a tenth of an element, with
// the neo-Hookean law by hand and by its energy: the same displacements and
// contact reactions to 1e-10.
GLISSADE_TEST(energy_law_scene_equals_neo_hookean)
{
  std::array<std::vector<Vector<double>>, 2> displacement;
  std::array<std::vector<double>, 2>         reaction;
  for (unsigned int k = 0; k < 2; ++k)
    {
      const std::string        law       = k == 0 ? "neo-Hookean" : "energy";
      std::vector<std::string> overrides = {
        "Body inner/Material/Law=" + law,
        "Body outer/Material/Law=" + law,
        "Load program/Stage end times=1, 1.005",
        "Load program/Stage increments=5, 2",
        "Output/VTU interval=0",
        "Output/Progress=false",
        "Output/Directory=energy_law_case3_" + std::to_string(k)};
      Simulation simulation(
        SceneReader::read_file(source_path("prm/case3_rings.prm"), overrides));
      simulation.run();
      for (const std::string body : {"inner", "outer"})
        displacement[k].push_back(simulation.body(body).displacement());
      // (the rings' total contact force is zero by symmetry: each node's)
      for (const ContactNode &node :
           simulation.contact().contact_pairs()[0]->nodes())
        for (const double r : node.reaction)
          reaction[k].push_back(r);
    }
  double difference = 0., largest = 0.;
  for (unsigned int b = 0; b < 2; ++b)
    {
      Vector<double> d = displacement[1][b];
      d -= displacement[0][b];
      difference = std::max(difference, d.linfty_norm());
      largest    = std::max(largest, displacement[0][b].linfty_norm());
    }
  double force_difference = 0., largest_force = 0.;
  for (unsigned int i = 0; i < reaction[0].size(); ++i)
    {
      force_difference =
        std::max(force_difference, std::abs(reaction[1][i] - reaction[0][i]));
      largest_force = std::max(largest_force, std::abs(reaction[0][i]));
    }
  force_difference /= largest_force;
  std::cout << "  max |u_energy - u_neo-Hookean| " << difference << " (max |u| "
            << largest << "), contact reactions " << force_difference
            << " of the largest (" << largest_force << ")" << std::endl;
  check(difference <= 1e-10 * largest, "the displacements differ");
  check(largest_force > 0. && force_difference <= 1e-10,
        "the contact reactions differ");
}

// A formula that cannot be read, a name it does not know, constants that
// are not 'name = value', and an energy with a stress at rest: each stops
// the run with a message that names the entry.
GLISSADE_TEST(energy_law_input_errors)
{
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
    {{"Body block/Material/Strain energy=mu * (I1 - 3"}, "')' expected"},
    {{"Body block/Material/Strain energy=mu * (K1 - 3)"}, "unknown name 'K1'"},
    {{"Body block/Material/Strain energy=mu * foo(I1)"},
     "unknown function 'foo'"},
    {{"Body block/Material/Strain energy constants=c1 0.5"},
     "is not 'name = value'"},
    {{"Body block/Material/Strain energy constants=mu = 2"},
     "is a variable of the formula"},
    {{"Body block/Material/Strain energy=mu * (I1 - 3)"}, "stress at rest"},
    {{"Body block/Material/Strain energy=mu * log(I1 - 3)"}, "not finite"},
  };
  for (const auto &[overrides, expected] : cases)
    {
      std::vector<std::string> all = overrides;
      all.push_back("Body block/Material/Law=energy");
      all.push_back("Output/Directory=energy_law_input_errors");
      std::string message;
      try
        {
          Simulation simulation(SceneReader::read_file(
            source_path("tests/input/block_on_rough_floor.prm"), all));
        }
      catch (const std::exception &e)
        {
          message = e.what();
        }
      std::cout << "  " << overrides[0] << ": " << message << std::endl;
      check(message.find(expected) != std::string::npos &&
              message.find("Strain energy") != std::string::npos,
            "'" + overrides[0] + "' should stop with '" + expected +
              "', naming the entry");
    }
}

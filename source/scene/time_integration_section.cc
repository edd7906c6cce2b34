// Time integration: quasi-static (the default: the load program's t is a
// load parameter) or an implicit dynamic scheme on the bodies' inertia.

#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/description/scene_description.h>
#include <glissade/scene/section_reader.h>

#include <cmath>
#include <string>

namespace glissade
{
  using namespace dealii;

  void
  TimeIntegrationSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.declare_entry(
      "Scheme",
      "quasi-static",
      Patterns::Selection("quasi-static|newmark|moreau-jean"),
      "quasi-static: no inertia, the load program's t a load parameter "
      "(every scene before dynamics). newmark: Newmark's implicit scheme on "
      "the bodies' inertia (Material/Density), the load program's "
      "increments the time steps, each solved by Newton with the contact "
      "step of the quasi-static scheme on the dynamic tangent K + M / "
      "(beta dt^2); the contact acts by each step's impulse, its law on the "
      "end positions (Kane et al.'s contact-implicit Newmark), so it never "
      "does positive work. moreau-jean: Moreau and Jean's theta-method, the "
      "contact by the step's impulses too (Signorini on the end velocities "
      "with Contact mass = kept, on the end positions with the mass "
      "redistributed; Coulomb on the step's slip); theta = 1 damps what the "
      "step does not resolve (doc/theory.md, 'Dynamics').");
    prm.declare_entry("Theta",
                      "0.5",
                      Patterns::Double(0.5, 1.),
                      "Moreau-Jean's theta, in [1/2, 1]: 1/2 conserves the "
                      "energy of a smooth motion, 1 (implicit Euler) damps "
                      "it.");
    prm.declare_entry("Newmark beta",
                      "0.25",
                      Patterns::Double(0., 0.5),
                      "Newmark's beta, in (0, 0.5]; 0.25 with gamma = 0.5 "
                      "is the trapezoidal rule, second order and energy "
                      "conserving for a linear body.");
    prm.declare_entry("Newmark gamma",
                      "0.5",
                      Patterns::Double(0.5, 1.),
                      "Newmark's gamma, in [0.5, 1]: above 0.5 the scheme "
                      "damps high frequencies (first order); unconditionally "
                      "stable for beta >= (gamma + 1/2)^2 / 4.");
    prm.declare_entry("Mass",
                      "consistent",
                      Patterns::Selection("consistent|lumped"),
                      "The mass matrix: consistent (every element space), "
                      "or lumped by the HRZ rule (diagonal scaled to the "
                      "cell's mass; Lagrange spaces only).");
    prm.declare_entry("Contact mass",
                      "redistributed",
                      Patterns::Selection("redistributed|kept"),
                      "redistributed: the nodes of every contact boundary "
                      "(slave and master) carry no mass, their share moved "
                      "to the other nodes of their cells (Khenous, Laborde "
                      "and Renard 2008): the contact force then has no "
                      "inertia of its own to ring with, and the total mass "
                      "and momentum are kept. kept: the mass as assembled "
                      "(each step's contact force rings about its mean).");
    prm.declare_entry("Mass damping",
                      "0",
                      Patterns::Double(0.),
                      "Rayleigh damping proportional to the mass, C = a_M "
                      "M (1/s): a mode of frequency omega is damped at the "
                      "ratio a_M / (2 omega).");
    prm.declare_entry(
      "Stiffness damping",
      "0",
      Patterns::Double(0.),
      "Rayleigh damping proportional to the stiffness, a_K (s): a viscous "
      "stress a_K D_0 : dE/dt on the rate of the Green-Lagrange strain (D_0 "
      "the material's tangent at rest), which is C = a_K K for small "
      "motions and brakes no rigid motion at any rotation; a mode of "
      "frequency omega is damped at the ratio a_K omega / 2.");
    prm.leave_subsection();
  }



  void
  TimeIntegrationSettings::parse_parameters(SectionReader &prm)
  {
    prm.enter_subsection("Time integration");
    const std::string where = prm.file() + ": Time integration/";
    {
      const std::string name = prm.get("Scheme");
      scheme                 = name == "newmark"     ? Scheme::newmark :
                               name == "moreau-jean" ? Scheme::moreau_jean :
                                                       Scheme::quasi_static;
    }
    theta                     = prm.get_double("Theta");
    beta                      = prm.get_double("Newmark beta");
    gamma                     = prm.get_double("Newmark gamma");
    lumped_mass               = prm.get("Mass") == "lumped";
    redistribute_contact_mass = prm.get("Contact mass") == "redistributed";
    mass_damping              = prm.get_double("Mass damping");
    stiffness_damping         = prm.get_double("Stiffness damping");
    prm.leave_subsection();
    if (!(beta > 0.))
      throw InputError(where + "Newmark beta",
                       "must be > 0 (beta = 0 is the explicit central "
                       "difference scheme, which glissade does not "
                       "implement)");
    if (beta < 0.25 * std::pow(gamma + 0.5, 2) - 1e-12)
      throw InputError(where + "Newmark beta",
                       "is " + std::to_string(beta) +
                         ": below (gamma + 1/2)^2 / 4 = " +
                         std::to_string(0.25 * std::pow(gamma + 0.5, 2)) +
                         " the scheme is only conditionally stable; raise "
                         "beta or lower Newmark gamma");
  }
} // namespace glissade

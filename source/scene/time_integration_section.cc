// Time integration: quasi-static (the default: the load program's t is a
// load parameter) or an implicit dynamic scheme on the bodies' inertia. The
// entries every scheme shares are here; each scheme declares and reads its
// own (source/time/).

#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/description/scene_description.h>
#include <glissade/scene/section_reader.h>
#include <glissade/time/time_scheme_registry.h>

#include <string>

namespace glissade
{
  using namespace dealii;

  void
  TimeIntegrationSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.declare_entry("Scheme",
                      "quasi-static",
                      Patterns::Selection(
                        TimeSchemeRegistry::names_as_pattern()),
                      TimeSchemeRegistry::documentation());
    // (each scheme's own: Newmark beta and gamma, Moreau-Jean theta,
    // Spectral radius at infinity)
    TimeSchemeRegistry::declare_parameters(prm);
    prm.declare_entry("Mass",
                      "consistent",
                      Patterns::Selection("consistent|lumped"),
                      "The mass matrix: consistent (every element space), "
                      "or lumped by the HRZ rule (diagonal scaled to the "
                      "cell's mass; spaces of values: Lagrange, serendipity, "
                      "NURBS, not Hermite).");
    prm.declare_entry("Contact mass",
                      "redistributed",
                      Patterns::Selection("redistributed|kept"),
                      "redistributed: the nodes (NURBS: control points) of "
                      "every contact boundary (slave and master) carry no "
                      "mass, their share moved to the other nodes of their "
                      "cells (a Hermite body keeps its own) (Khenous, Laborde "
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
    scheme                  = prm.get("Scheme");
    {
      const TimeSchemeRegistry::Entry &entry =
        TimeSchemeRegistry::entry(scheme);
      inertia = entry.has_inertia;
      if (entry.parse_parameters)
        scheme_settings = entry.parse_parameters(prm.handler(), where);
    }
    lumped_mass               = prm.get("Mass") == "lumped";
    redistribute_contact_mass = prm.get("Contact mass") == "redistributed";
    mass_damping              = prm.get_double("Mass damping");
    stiffness_damping         = prm.get_double("Stiffness damping");
    prm.leave_subsection();
  }
} // namespace glissade

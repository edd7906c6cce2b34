// Body <name>/Material and its regions' Material <region> subsections.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/description/scene_description.h>
#include <glissade/material/hypothesis.h>
#include <glissade/material/law_registry.h>
#include <glissade/scene/section_reader.h>

#include <algorithm>
#include <string>
#include <vector>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** The entries a material region may set; unset ones are the body's. */
    void
    declare_region_material(ParameterHandler &prm)
    {
      prm.declare_entry("Law",
                        "",
                        Patterns::Anything(),
                        "As Material/Law; empty: the body's.");
      prm.declare_entry("Young modulus",
                        "",
                        Patterns::Anything(),
                        "As Material/Young modulus; empty: the body's.");
      prm.declare_entry("Poisson ratio",
                        "",
                        Patterns::Anything(),
                        "As Material/Poisson ratio; empty: the body's.");
      prm.declare_entry("Density",
                        "",
                        Patterns::Anything(),
                        "As Material/Density; empty: the body's.");
      LawRegistry::declare_parameters(prm);
    }
  } // namespace



  void
  MaterialDescription::declare_parameters(
    ParameterHandler               &prm,
    const std::vector<std::string> &regions)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Law",
                        "neo-Hookean",
                        Patterns::Selection(
                          text::joined(LawRegistry::names(), "|")),
                        "Hyperelastic law (total Lagrangian): " +
                          LawRegistry::documentation() + ".");
      LawRegistry::declare_parameters(prm);
      prm.declare_entry("Young modulus",
                        "1",
                        Patterns::Double(),
                        "E in Pa, > 0.");
      prm.declare_entry("Poisson ratio",
                        "0.3",
                        Patterns::Double(),
                        "nu, in (-1, 0.5).");
      std::string hypotheses;
      for (const auto &[name, kind] : Hypothesis::names())
        hypotheses += (hypotheses.empty() ? "" : "|") + std::string(name);
      prm.declare_entry("Hypothesis",
                        "plane strain",
                        Patterns::Selection(hypotheses),
                        "What makes the 2D body a 3D one: plane strain, plane "
                        "stress, or axisymmetric (a body of revolution: x is "
                        "the radius r >= 0, y the axis; forces, reactions "
                        "and contact forces are for the full turn, 2 pi r "
                        "times a force per unit length of the circle; "
                        "Thickness is not used).");
      prm.declare_entry(
        "Kinematics",
        "large strain",
        Patterns::Selection("large strain|small strain"),
        "large strain: total Lagrangian, the Green-Lagrange strain and the "
        "Law at any rotation. small strain: linear elasticity, epsilon = "
        "sym(grad u) and sigma = D_0 : epsilon with D_0 the Law's tangent "
        "at rest (its Lame constants), equilibrium and pressures on the "
        "undeformed body: a Newton step solves it exactly (contact aside), "
        "and a dynamic run keeps one factorisation; valid while strains and "
        "rotations stay small (contact is still detected on the deformed "
        "body).");
      prm.declare_entry("Density",
                        "0",
                        Patterns::Double(0.),
                        "Mass per unit volume (kg/m^3 with SI units), >= "
                        "0: the inertia of a dynamic scheme (Time "
                        "integration) and the weight of Boundary "
                        "conditions/Gravity. 0: massless (a quasi-static "
                        "scene).");
      prm.declare_entry("Thickness",
                        "1",
                        Patterns::Double(),
                        "Out-of-plane thickness (m), > 0: forces are per "
                        "this thickness.");
      prm.declare_entry(
        "Regions",
        "",
        Patterns::Anything(),
        "Gmsh meshes: comma-separated names of Physical Surfaces that "
        "have a material of their own, each set in a subsection "
        "'Material <name>' beside this one (Law, Young modulus, Poisson "
        "ratio; an entry left unset is this subsection's). Cells of other "
        "Physical Surfaces take this subsection's material. Hypothesis, "
        "Kinematics and Thickness belong to the body.");
    }
    prm.leave_subsection();
    for (const std::string &region : regions)
      {
        prm.enter_subsection("Material " + region);
        declare_region_material(prm);
        prm.leave_subsection();
      }
  }



  void
  MaterialDescription::parse_parameters(SectionReader     &prm,
                                        const std::string &where)
  {
    prm.enter_subsection("Material");
    law           = prm.get("Law");
    young_modulus = prm.get_double("Young modulus");
    poisson_ratio = prm.get_double("Poisson ratio");
    density       = prm.get_double("Density");
    for (const auto &[name, kind] : Hypothesis::names())
      if (prm.get("Hypothesis") == name)
        hypothesis = kind;
    kinematics = prm.get("Kinematics") == "small strain" ?
                   Kinematics::small_strain :
                   Kinematics::large_strain;
    thickness  = prm.get_double("Thickness");
    law_settings =
      LawRegistry::parse_parameters(prm.handler(), law, where + "/Material");
    const std::vector<std::string> region_names =
      Utilities::split_string_list(prm.get("Regions"), ',');
    prm.leave_subsection();
    const auto check_moduli =
      [&where](const double E, const double nu, const std::string &subsection) {
        if (!(E > 0.))
          throw InputError(where + "/" + subsection + "/Young modulus",
                           "must be > 0");
        if (!(nu > -1. && nu < 0.5))
          throw InputError(where + "/" + subsection + "/Poisson ratio",
                           "must lie in (-1, 0.5)");
      };
    check_moduli(young_modulus, poisson_ratio, "Material");
    if (!(thickness > 0.))
      throw InputError(where + "/Material/Thickness", "must be > 0");

    // Each region: its own entries, the body's where it sets none.
    for (const std::string &name : region_names)
      {
        const std::string         subsection = "Material " + name;
        MaterialRegionDescription region;
        region.name = name;
        prm.enter_subsection(subsection);
        region.law = text::trim(prm.get("Law"));
        region.young_modulus =
          prm.number_or_inherited("Young modulus",
                                  young_modulus,
                                  where + "/" + subsection);
        region.poisson_ratio =
          prm.number_or_inherited("Poisson ratio",
                                  poisson_ratio,
                                  where + "/" + subsection);
        region.density =
          prm.number_or_inherited("Density", density, where + "/" + subsection);
        if (region.law.empty())
          region.law = law;
        const auto laws = LawRegistry::names();
        if (std::find(laws.begin(), laws.end(), region.law) == laws.end())
          throw InputError(where + "/" + subsection + "/Law",
                           "'" + region.law + "' is not a law (" +
                             text::joined(laws, ", ") + ")");
        region.law_settings =
          LawRegistry::parse_parameters(prm.handler(),
                                        region.law,
                                        where + "/" + subsection);
        prm.leave_subsection();
        if (!(region.density >= 0.))
          throw InputError(where + "/" + subsection + "/Density",
                           "must be >= 0");
        check_moduli(region.young_modulus, region.poisson_ratio, subsection);
        regions.push_back(region);
      }
  }
} // namespace glissade

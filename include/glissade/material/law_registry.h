#pragma once

#include <deal.II/base/parameter_handler.h>

#include <glissade/material/hyperelastic_law.h>

#include <any>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * The hyperelastic laws a .prm may name (`Material/Law`). Adding a law is
   * one file that defines its class and factory, and one line in
   * law_registry.cc (doc/adding_a_material.md).
   *
   * Every law takes the Lame constants of `Young modulus` and `Poisson
   * ratio` (its behaviour at small strain, which Kinematics = small strain
   * uses). A law with constants of its own declares and reads them itself,
   * as the master surfaces do (SurfaceRegistry): `declare_parameters`
   * declares them in the Material subsection (and in each region's), for
   * every body, and `parse_parameters` reads them for a material that chose
   * the law, into the settings its factory receives. The generic
   * MaterialDescription never sees them.
   */
  class LawRegistry
  {
  public:
    struct Entry
    {
      std::string name;
      std::string description;
      /**
       * The law from the Lame constants lambda, mu and its settings (what
       * its parse_parameters returned; empty if it has none).
       */
      std::function<std::unique_ptr<HyperelasticLaw>(double          lambda,
                                                     double          mu,
                                                     const std::any &settings)>
        create;
      /** Declares the law's own entries (none if empty). */
      std::function<void(dealii::ParameterHandler &)> declare_parameters = {};
      /**
       * Reads them for a material that chose the law (in the subsection
       * they were declared in); `where` names the subsection for messages
       * ("Body ring/Material"). Returns the law's settings.
       */
      std::function<std::any(const dealii::ParameterHandler &,
                             const std::string &where)>
        parse_parameters = {};
    };

    static const std::vector<Entry> &
    entries();

    /** The law `name` (throws an InputError naming Material/Law if none). */
    static std::unique_ptr<HyperelasticLaw>
    create(const std::string &name,
           double             lambda,
           double             mu,
           const std::any    &settings);

    /** Every law's own entries, in the current subsection. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** The settings of the law `name` from its own entries (empty if it
     *  has none). */
    static std::any
    parse_parameters(const dealii::ParameterHandler &prm,
                     const std::string              &name,
                     const std::string              &where);

    /** The laws' names. */
    static std::vector<std::string>
    names();

    /** "neo-Hookean: ...; Saint Venant-Kirchhoff: ..." for the help text. */
    static std::string
    documentation();
  };
} // namespace glissade

#pragma once

#include <deal.II/base/parameter_handler.h>

#include <glissade/time/time_scheme.h>

#include <any>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * The time schemes a .prm may name (Time integration/Scheme), as the
   * laws' LawRegistry: adding a scheme is one file that defines its class,
   * its entries and its factory, and one line in time_scheme_registry.cc
   * (doc/adding_a_time_scheme.md). A scheme declares and reads its own
   * entries in the Time integration section (Newmark's beta and gamma,
   * Moreau-Jean's theta, the generalised-alpha method's spectral radius);
   * the entries every dynamic scheme shares (the mass, its
   * redistribution, the damping) are the section's
   * (TimeIntegrationSettings).
   */
  class TimeSchemeRegistry
  {
  public:
    struct Entry
    {
      std::string name;
      std::string description;
      /** False for a scheme without inertia (quasi-static). */
      bool has_inertia = true;
      /** The scheme from its settings (what parse_parameters returned). */
      std::function<std::unique_ptr<TimeScheme>(const std::any &settings)>
        create;
      /** Declares the scheme's own entries (none if empty). */
      std::function<void(dealii::ParameterHandler &)> declare_parameters = {};
      /**
       * Reads and checks them when the scheme is chosen (in the Time
       * integration subsection); `where` is "file.prm: Time integration/"
       * for messages. Returns the scheme's settings.
       */
      std::function<std::any(const dealii::ParameterHandler &,
                             const std::string &where)>
        parse_parameters = {};
    };

    static const std::vector<Entry> &
    entries();

    /** The entry `name` (an InputError naming Time integration/Scheme if
     *  none). */
    static const Entry &
    entry(const std::string &name);

    /** Every scheme's own entries, in the current subsection. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** "quasi-static|newmark|..." for the pattern of Scheme. */
    static std::string
    names_as_pattern();

    /** The schemes with inertia, "newmark, moreau-jean, ...". */
    static std::string
    names_with_inertia();

    /** "quasi-static: ...; newmark: ..." for the help text. */
    static std::string
    documentation();
  };
} // namespace glissade

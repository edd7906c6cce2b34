#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/time/time_scheme_registry.h>

namespace glissade
{
  using namespace dealii;

  // Each scheme's factory and entries, defined in the scheme's own file.
  std::unique_ptr<TimeScheme>
  make_quasi_static_scheme(const std::any &);
  std::unique_ptr<TimeScheme>
  make_newmark_scheme(const std::any &);
  void
  declare_newmark_parameters(ParameterHandler &);
  std::any
  parse_newmark_parameters(const ParameterHandler &, const std::string &);
  std::unique_ptr<TimeScheme>
  make_moreau_jean_scheme(const std::any &);
  void
  declare_moreau_jean_parameters(ParameterHandler &);
  std::any
  parse_moreau_jean_parameters(const ParameterHandler &, const std::string &);
  std::unique_ptr<TimeScheme>
  make_generalized_alpha_scheme(const std::any &);
  void
  declare_generalized_alpha_parameters(ParameterHandler &);
  std::any
  parse_generalized_alpha_parameters(const ParameterHandler &,
                                     const std::string &);
  std::any
  parse_hht_alpha_parameters(const ParameterHandler &, const std::string &);



  const std::vector<TimeSchemeRegistry::Entry> &
  TimeSchemeRegistry::entries()
  {
    // One line per scheme.
    static const std::vector<Entry> list = {
      {"quasi-static",
       "no inertia, the load program's t a load parameter (every scene "
       "before dynamics)",
       false,
       make_quasi_static_scheme},
      {"newmark",
       "Newmark's implicit scheme on the bodies' inertia (Material/Density), "
       "the load program's increments the time steps, each solved by Newton "
       "with the contact step of the quasi-static scheme on the dynamic "
       "tangent K + M / (beta dt^2); the contact acts by each step's "
       "impulse, its law on the end positions (Kane et al.'s "
       "contact-implicit Newmark), so it never does positive work",
       true,
       make_newmark_scheme,
       declare_newmark_parameters,
       parse_newmark_parameters},
      {"moreau-jean",
       "Moreau and Jean's theta-method, the contact by the step's impulses "
       "too (Signorini on the end velocities with Contact mass = kept, on "
       "the end positions with the mass redistributed; Coulomb on the "
       "step's slip); theta = 1 damps what the step does not resolve "
       "(doc/theory.md, 'Dynamics')",
       true,
       make_moreau_jean_scheme,
       declare_moreau_jean_parameters,
       parse_moreau_jean_parameters},
      {"generalized-alpha",
       "Chung and Hulbert's generalised-alpha method: second order, a mode "
       "far above what the step resolves multiplied by Spectral radius at "
       "infinity per step, the resolved ones nearly kept; the contact as "
       "Newmark's",
       true,
       make_generalized_alpha_scheme,
       declare_generalized_alpha_parameters,
       parse_generalized_alpha_parameters},
      {"hht-alpha",
       "Hilber, Hughes and Taylor's alpha-method, the generalised-alpha "
       "method with alpha_m = 0 (Spectral radius at infinity in [1/2, 1])",
       true,
       make_generalized_alpha_scheme,
       {},
       parse_hht_alpha_parameters},
    };
    return list;
  }



  const TimeSchemeRegistry::Entry &
  TimeSchemeRegistry::entry(const std::string &name)
  {
    for (const Entry &entry : entries())
      if (entry.name == name)
        return entry;
    std::vector<std::string> names;
    for (const Entry &entry : entries())
      names.push_back(entry.name);
    throw InputError("Time integration/Scheme",
                     "unknown scheme '" + name +
                       "' (known: " + text::joined(names, ", ") + ")");
  }



  void
  TimeSchemeRegistry::declare_parameters(ParameterHandler &prm)
  {
    for (const Entry &entry : entries())
      if (entry.declare_parameters)
        entry.declare_parameters(prm);
  }



  std::string
  TimeSchemeRegistry::names_as_pattern()
  {
    std::vector<std::string> names;
    for (const Entry &entry : entries())
      names.push_back(entry.name);
    return text::joined(names, "|");
  }



  std::string
  TimeSchemeRegistry::names_with_inertia()
  {
    std::vector<std::string> names;
    for (const Entry &entry : entries())
      if (entry.has_inertia)
        names.push_back(entry.name);
    return text::joined(names, ", ");
  }



  std::string
  TimeSchemeRegistry::documentation()
  {
    std::vector<std::string> lines;
    for (const Entry &entry : entries())
      lines.push_back(entry.name + ": " + entry.description);
    return text::joined(lines, ". ") + ".";
  }
} // namespace glissade

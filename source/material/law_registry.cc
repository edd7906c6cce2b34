#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/material/law_registry.h>

namespace glissade
{
  using namespace dealii;

  // Each law's factory, defined in the law's own file.
  std::unique_ptr<HyperelasticLaw>
  make_neo_hookean(double lambda, double mu, const std::any &);
  std::unique_ptr<HyperelasticLaw>
  make_saint_venant_kirchhoff(double lambda, double mu, const std::any &);
  std::unique_ptr<HyperelasticLaw>
  make_mooney_rivlin(double lambda, double mu, const std::any &);
  void
  declare_mooney_rivlin_parameters(ParameterHandler &);
  std::any
  parse_mooney_rivlin_parameters(const ParameterHandler &, const std::string &);
  std::unique_ptr<HyperelasticLaw>
  make_energy_formula_law(double lambda, double mu, const std::any &);
  void
  declare_energy_law_parameters(ParameterHandler &);
  std::any
  parse_energy_law_parameters(const ParameterHandler &, const std::string &);



  const std::vector<LawRegistry::Entry> &
  LawRegistry::entries()
  {
    // One line per law.
    static const std::vector<Entry> list = {
      {"neo-Hookean",
       "compressible, W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2",
       make_neo_hookean},
      {"Saint Venant-Kirchhoff",
       "S = lambda tr(E) I + 2 mu E (unstable in strong compression)",
       make_saint_venant_kirchhoff},
      {"Mooney-Rivlin",
       "compressible, neo-Hookean plus a second invariant term (Mooney-Rivlin "
       "ratio)",
       make_mooney_rivlin,
       declare_mooney_rivlin_parameters,
       parse_mooney_rivlin_parameters},
      {"energy",
       "W(C) given as a formula (Strain energy), its stress and tangent by "
       "automatic differentiation",
       make_energy_formula_law,
       declare_energy_law_parameters,
       parse_energy_law_parameters},
    };
    return list;
  }



  std::unique_ptr<HyperelasticLaw>
  LawRegistry::create(const std::string &name,
                      const double       lambda,
                      const double       mu,
                      const std::any    &settings)
  {
    for (const Entry &entry : entries())
      if (entry.name == name)
        return entry.create(lambda, mu, settings);
    throw InputError("Material/Law",
                     "unknown law '" + name +
                       "' (known: " + text::joined(names(), ", ") + ")");
  }



  void
  LawRegistry::declare_parameters(ParameterHandler &prm)
  {
    for (const Entry &entry : entries())
      if (entry.declare_parameters)
        entry.declare_parameters(prm);
  }



  std::any
  LawRegistry::parse_parameters(const ParameterHandler &prm,
                                const std::string      &name,
                                const std::string      &where)
  {
    for (const Entry &entry : entries())
      if (entry.name == name && entry.parse_parameters)
        return entry.parse_parameters(prm, where);
    return {};
  }



  std::vector<std::string>
  LawRegistry::names()
  {
    std::vector<std::string> result;
    for (const Entry &entry : entries())
      result.push_back(entry.name);
    return result;
  }



  std::string
  LawRegistry::documentation()
  {
    std::vector<std::string> lines;
    for (const Entry &entry : entries())
      lines.push_back(entry.name + ": " + entry.description);
    return text::joined(lines, "; ");
  }
} // namespace glissade

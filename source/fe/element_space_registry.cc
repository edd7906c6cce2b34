#include <glissade/base/input_error.h>
#include <glissade/fe/element_space_registry.h>
#include <glissade/fe/hermite_space.h>
#include <glissade/fe/lagrange_space.h>
#include <glissade/fe/nurbs_space.h>
#include <glissade/fe/serendipity_space.h>

namespace glissade
{
  using namespace dealii;

  const std::vector<ElementSpaceRegistry::Entry> &
  ElementSpaceRegistry::entries()
  {
    // One line per element space.
    static const std::vector<Entry> list = {
      {"q1",
       "bilinear 4-node quadrilateral (the paper's Q4)",
       [](unsigned int) { return std::make_unique<LagrangeSpace>(1); }},
      {"q2",
       "biquadratic 9-node Lagrange quadrilateral",
       [](unsigned int) { return std::make_unique<LagrangeSpace>(2); }},
      {"q3",
       "bicubic 16-node Lagrange quadrilateral",
       [](unsigned int) { return std::make_unique<LagrangeSpace>(3); }},
      {"q8",
       "quadratic 8-node serendipity quadrilateral (the paper's Q8)",
       [](unsigned int) { return std::make_unique<SerendipitySpace>(2); }},
      {"q12",
       "cubic 12-node serendipity quadrilateral (the paper's Q12)",
       [](unsigned int) { return std::make_unique<SerendipitySpace>(3); }},
      {"hermite",
       "the paper's C1-edge Hermite quadrilateral: 12-term cubic, value and "
       "both derivatives per node and component (6 dofs per node)",
       [](unsigned int) { return std::make_unique<HermiteSpace>(); }},
      {"nurbs",
       "isogeometric: the NURBS space of the body's exact geometry "
       "(rectangle, square, ring, half ring), of degree Element/Degree and "
       "continuity C^(degree-1) between elements, its dofs the control "
       "points' displacements",
       [](unsigned int degree) {
         return std::make_unique<NurbsSpace>(degree);
       }},
    };
    return list;
  }



  std::unique_ptr<ElementSpace>
  ElementSpaceRegistry::create(const std::string &name,
                               const unsigned int degree)
  {
    for (const auto &entry : entries())
      if (entry.name == name)
        return entry.create(degree);
    throw InputError("Element/Space",
                     "unknown element space '" + name +
                       "' (known: " + names_as_pattern() + ")");
  }



  std::string
  ElementSpaceRegistry::names_as_pattern()
  {
    std::string names;
    for (const auto &entry : entries())
      names += (names.empty() ? "" : "|") + entry.name;
    return names;
  }



  std::string
  ElementSpaceRegistry::names_that(
    const std::function<bool(const ElementSpace::Capabilities &)> &wanted)
  {
    std::vector<std::string> names;
    for (const auto &entry : entries())
      if (wanted(entry.create(2)->capabilities()))
        names.push_back(entry.name);
    std::string text;
    for (unsigned int k = 0; k < names.size(); ++k)
      text += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
    return text;
  }



  std::string
  ElementSpaceRegistry::documentation()
  {
    std::string text;
    for (const auto &entry : entries())
      text +=
        (text.empty() ? "" : "; ") + entry.name + ": " + entry.description;
    return text + ".";
  }
} // namespace glissade

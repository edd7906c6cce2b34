#include <deal.II/fe/fe_q.h>

#include <glissade/fe/lagrange_space.h>

namespace glissade
{
  LagrangeSpace::LagrangeSpace(const unsigned int degree)
    : degree(degree)
    , fe(FE_Q<2>(degree), 2)
    , geometry(degree)
    , cell_rule(degree + 1)
    , face_rule(degree + 1)
  {}



  std::string
  LagrangeSpace::name() const
  {
    return "q" + std::to_string(degree);
  }
} // namespace glissade

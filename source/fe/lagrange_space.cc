#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>

#include <glissade/fe/fe_values_evaluator.h>
#include <glissade/fe/lagrange_space.h>

namespace glissade
{
  using namespace dealii;

  LagrangeSpace::LagrangeSpace(const unsigned int degree)
    : degree(degree)
    , fe(FE_Q<2>(degree), 2)
    , geometry(degree)
  {}



  std::string
  LagrangeSpace::name() const
  {
    return "q" + std::to_string(degree);
  }



  std::unique_ptr<CellEvaluator>
  LagrangeSpace::create_evaluator(const unsigned int points_per_direction) const
  {
    const unsigned int n =
      points_per_direction > 0 ? points_per_direction : degree + 1;
    return std::make_unique<FEValuesEvaluator>(geometry,
                                               fe,
                                               QGauss<2>(n),
                                               QGauss<1>(n));
  }
} // namespace glissade

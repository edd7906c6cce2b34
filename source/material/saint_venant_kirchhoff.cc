#include <glissade/material/saint_venant_kirchhoff.h>

#include <any>
#include <memory>

namespace glissade
{
  using namespace dealii;

  std::unique_ptr<HyperelasticLaw>
  make_saint_venant_kirchhoff(const double lambda,
                              const double mu,
                              const std::any &)
  {
    return std::make_unique<SaintVenantKirchhoff>(lambda, mu);
  }



  SaintVenantKirchhoff::SaintVenantKirchhoff(const double lambda,
                                             const double mu)
    : lambda(lambda)
    , mu(mu)
    , elasticity(lambda * outer_product(unit_symmetric_tensor<3>(),
                                        unit_symmetric_tensor<3>()) +
                 2. * mu * identity_tensor<3>())
  {}

  void
  SaintVenantKirchhoff::evaluate(const SymmetricTensor<2, 3> &E,
                                 SymmetricTensor<2, 3>       &S,
                                 SymmetricTensor<4, 3>       &D) const
  {
    S = lambda * trace(E) * unit_symmetric_tensor<3>() + 2. * mu * E;
    D = elasticity;
  }



  double
  SaintVenantKirchhoff::energy(const SymmetricTensor<2, 3> &E) const
  {
    return 0.5 * lambda * trace(E) * trace(E) + mu * (E * E);
  }
} // namespace glissade

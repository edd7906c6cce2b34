#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/material/law_registry.h>
#include <glissade/material/material.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace glissade
{
  using namespace dealii;

  Material::Material(std::unique_ptr<HyperelasticLaw> law,
                     const PlaneHypothesis            hypothesis,
                     const Kinematics                 kinematics)
    : law(std::move(law))
    , third(Hypothesis(hypothesis, 1.).third_direction())
    , kinematics(kinematics)
  {
    SymmetricTensor<2, 3> S;
    this->law->evaluate(SymmetricTensor<2, 3>(), S, tangent_at_rest);
  }



  Material
  Material::create(const std::string    &law_name,
                   const double          young_modulus,
                   const double          poisson_ratio,
                   const PlaneHypothesis hypothesis,
                   const Kinematics      kinematics,
                   const std::any       &law_settings)
  {
    const double E      = young_modulus;
    const double nu     = poisson_ratio;
    const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    const double mu     = E / (2. * (1. + nu));
    return Material(LawRegistry::create(law_name, lambda, mu, law_settings),
                    hypothesis,
                    kinematics);
  }



  SymmetricTensor<2, 3>
  Material::strain(const Tensor<2, 2> &H, const double e33) const
  {
    const bool            quadratic = kinematics == Kinematics::large_strain;
    SymmetricTensor<2, 3> E;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = i; j < 2; ++j)
        E[i][j] =
          0.5 * (H[i][j] + H[j][i] +
                 (quadratic ? H[0][i] * H[0][j] + H[1][i] * H[1][j] : 0.));
    E[2][2] = e33;
    return E;
  }



  double
  Material::hoop_strain(const double hoop_strain_ratio) const
  {
    // E_33 = ((1 + h)^2 - 1) / 2 with h = u_r / r, without cancellation
    // for a small h; h itself at small strain.
    return kinematics == Kinematics::large_strain ?
             hoop_strain_ratio + 0.5 * hoop_strain_ratio * hoop_strain_ratio :
             hoop_strain_ratio;
  }



  void
  Material::stress(const SymmetricTensor<2, 3> &E,
                   SymmetricTensor<2, 3>       &S,
                   SymmetricTensor<4, 3>       &D) const
  {
    if (kinematics == Kinematics::large_strain)
      law->evaluate(E, S, D);
    else
      {
        D = tangent_at_rest;
        S = D * E;
      }
  }



  double
  Material::solve_out_of_plane(const Tensor<2, 2>    &H,
                               SymmetricTensor<2, 3> &S,
                               SymmetricTensor<4, 3> &D) const
  {
    // Newton on S_33(E_33) = 0 with dS_33/dE_33 = D_3333. Starting from
    // E_33 = 0 it converges in a few steps for any physically meaningful
    // deformation; the count is bounded so a bad state cannot hang, and
    // C_33 = 1 + 2 E_33 is kept positive.
    double e33 = 0.;
    for (unsigned int it = 0; it < 50; ++it)
      {
        stress(strain(H, e33), S, D);
        double next = e33 - S[2][2] / D[2][2][2][2];
        if (!(1. + 2. * next > 0.))
          next = 0.5 * (e33 - 0.5); // halfway to C_33 = 0
        const bool done =
          std::abs(next - e33) <= 1e-15 * (1. + 2. * std::abs(e33));
        e33 = next;
        if (done)
          break;
      }
    stress(strain(H, e33), S, D);
    return e33;
  }



  MaterialPointResponse
  Material::evaluate(const Tensor<2, 2> &H,
                     const double        hoop_strain_ratio) const
  {
    SymmetricTensor<2, 3> S;
    SymmetricTensor<4, 3> D;
    MaterialPointResponse response;

    switch (third)
      {
        case ThirdDirection::held:
          stress(strain(H, 0.), S, D);
          break;
        case ThirdDirection::free_of_stress:
          {
            const double e33 = solve_out_of_plane(H, S, D);
            response.out_of_plane_stretch =
              kinematics == Kinematics::large_strain ?
                std::sqrt(1. + 2. * e33) :
                1. + e33;
          }
          break;
        case ThirdDirection::hoop:
          stress(strain(H, hoop_strain(hoop_strain_ratio)), S, D);
          response.out_of_plane_stretch = 1. + hoop_strain_ratio;
          response.hoop_stress          = S[2][2];
          response.hoop_stiffness       = D[2][2][2][2];
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = i; j < 2; ++j)
              response.hoop_coupling[i][j] = D[i][j][2][2];
          break;
      }

    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = i; j < 2; ++j)
        {
          response.stress[i][j] = S[i][j];
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int l = k; l < 2; ++l)
              {
                double value = D[i][j][k][l];
                if (third == ThirdDirection::free_of_stress)
                  value -= D[i][j][2][2] * D[2][2][k][l] / D[2][2][2][2];
                response.tangent[i][j][k][l] = value;
              }
        }
    return response;
  }



  double
  Material::energy(const Tensor<2, 2> &H, const double hoop_strain_ratio) const
  {
    SymmetricTensor<2, 3> S;
    SymmetricTensor<4, 3> D;
    double                e33 = 0.;
    if (third == ThirdDirection::free_of_stress)
      e33 = solve_out_of_plane(H, S, D);
    else if (third == ThirdDirection::hoop)
      e33 = hoop_strain(hoop_strain_ratio);
    const SymmetricTensor<2, 3> E = strain(H, e33);
    return kinematics == Kinematics::large_strain ?
             law->energy(E) :
             0.5 * (E * (tangent_at_rest * E));
  }



  SymmetricTensor<2, 3>
  Material::cauchy_stress(const Tensor<2, 2> &H,
                          const double        hoop_strain_ratio) const
  {
    SymmetricTensor<2, 3> S;
    SymmetricTensor<4, 3> D;
    double                e33 = 0.;
    if (third == ThirdDirection::free_of_stress)
      e33 = solve_out_of_plane(H, S, D);
    else
      {
        if (third == ThirdDirection::hoop)
          e33 = hoop_strain(hoop_strain_ratio);
        stress(strain(H, e33), S, D);
      }
    if (kinematics == Kinematics::small_strain)
      return S;

    Tensor<2, 3> F;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        F[i][j] = (i == j ? 1. : 0.) + H[i][j];
    F[2][2]        = std::sqrt(1. + 2. * e33);
    const double J = determinant(F);
    return symmetrize(F * Tensor<2, 3>(S) * transpose(F)) / J;
  }
} // namespace glissade

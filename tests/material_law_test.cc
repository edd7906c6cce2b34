// Every hyperelastic law of the registry (LawRegistry) against finite
// differences: its stress is the derivative of its energy, S = dW/dE, and
// its tangent the derivative of its stress, D = dS/dE, at a large strain;
// at rest both reduce to Hooke's law with the Lame constants given. A new
// law (doc/adding_a_material.md) is checked here without a line of its own.

#include <glissade/material/law_registry.h>

#include <cmath>
#include <iostream>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

GLISSADE_TEST(material_laws_against_finite_differences)
{
  const double lambda = 577., mu = 385.;
  // A strain with shear, stretch and compression: C = I + 2E positive.
  SymmetricTensor<2, 3> E;
  E[0][0]        = 0.21;
  E[1][1]        = -0.13;
  E[2][2]        = 0.05;
  E[0][1]        = 0.08;
  E[0][2]        = -0.04;
  E[1][2]        = 0.03;
  const double h = 1e-6;
  for (const LawRegistry::Entry &entry : LawRegistry::entries())
    {
      // (a law with settings is taken with a value of its own entries that
      // is not the default: Mooney-Rivlin's ratio 0.3)
      const std::any settings =
        entry.name == "Mooney-Rivlin" ? std::any(0.3) : std::any();
      const auto law = entry.create(lambda, mu, settings);
      check(law->name() == entry.name,
            entry.name + ": the law names itself '" + law->name() + "'");
      SymmetricTensor<2, 3> S, S_plus, S_minus;
      SymmetricTensor<4, 3> D, D_unused;
      law->evaluate(E, S, D);
      double stress_error = 0., tangent_error = 0.;
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = k; l < 3; ++l)
          {
            // A symmetric perturbation of E_kl (both E_kl and E_lk).
            SymmetricTensor<2, 3> dE;
            dE[k][l] = h;
            law->evaluate(E + dE, S_plus, D_unused);
            law->evaluate(E - dE, S_minus, D_unused);
            const double dW =
              (law->energy(E + dE) - law->energy(E - dE)) / (2. * h);
            // dW = S : dE / h = S_kl (k = l) or 2 S_kl (k != l)
            stress_error =
              std::max(stress_error,
                       std::abs(dW - (k == l ? 1. : 2.) * S[k][l]));
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = i; j < 3; ++j)
                tangent_error =
                  std::max(tangent_error,
                           std::abs((S_plus[i][j] - S_minus[i][j]) / (2. * h) -
                                    (k == l ? 1. : 2.) * D[i][j][k][l]));
          }
      // At rest: S = 0 and D = lambda I x I + 2 mu II.
      SymmetricTensor<2, 3> S0;
      SymmetricTensor<4, 3> D0;
      law->evaluate(SymmetricTensor<2, 3>(), S0, D0);
      const SymmetricTensor<4, 3> hooke =
        lambda * outer_product(unit_symmetric_tensor<3>(),
                               unit_symmetric_tensor<3>()) +
        2. * mu * identity_tensor<3>();
      const double hooke_error = (D0 - hooke).norm() / hooke.norm();
      std::cout << "  " << entry.name << ": |dW/dE - S| " << stress_error
                << " (|S| " << S.norm() << "), |dS/dE - D| " << tangent_error
                << " (|D| " << D.norm() << "), at rest |S| " << S0.norm()
                << ", |D - Hooke| / |Hooke| " << hooke_error << std::endl;
      check(stress_error <= 1e-7 * S.norm(),
            entry.name + ": the stress is not the energy's derivative");
      check(tangent_error <= 1e-7 * D.norm(),
            entry.name + ": the tangent is not the stress's derivative");
      check(S0.norm() <= 1e-12 * mu, entry.name + ": stressed at rest");
      check(hooke_error <= 1e-12,
            entry.name + ": not Hooke's law at small strain");
    }
}

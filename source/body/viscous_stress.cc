// The Kelvin-Voigt viscous stress of stiffness-proportional damping at one
// quadrature point (include/glissade/body/viscous_stress.h).

#include <glissade/body/viscous_stress.h>
#include <glissade/fe/cell_evaluator.h>

namespace glissade
{
  using namespace dealii;

  void
  add_viscous_stress_terms(const double                     a_K,
                           const double                     velocity_factor,
                           const ViscousStressPoint        &point,
                           const CellEvaluator             &evaluator,
                           const unsigned int               q,
                           const std::vector<unsigned int> &component,
                           const std::vector<Tensor<1, 2>> &grad,
                           const std::vector<SymmetricTensor<2, 2>> &dE,
                           const std::vector<double>                &dE33,
                           const std::vector<double> &cell_velocity,
                           FullMatrix<double>        &cell_matrix,
                           Vector<double>            &cell_rhs,
                           Vector<double>            &cell_viscous_force)
  {
    const unsigned int n = grad.size();
    const auto        &F = point.F;
    // The velocity gradient and, axisymmetric, the radial velocity over r.
    Tensor<2, 2> grad_v;
    double       v_r_over_r = 0.;
    for (unsigned int j = 0; j < n; ++j)
      {
        grad_v[component[j]] += cell_velocity[j] * grad[j];
        if (point.strains_the_hoop && component[j] == 0)
          v_r_over_r +=
            cell_velocity[j] * evaluator.shape_value(j, q) / point.radius;
      }
    // dE/dt = sym(F^T Grad v), dE_33/dt = F_33 v_r / r
    SymmetricTensor<2, 2> rate;
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = a; b < 2; ++b)
        for (unsigned int c = 0; c < 2; ++c)
          rate[a][b] += 0.5 * (F[c][a] * grad_v[c][b] + F[c][b] * grad_v[c][a]);
    const double hoop_rate =
      point.strains_the_hoop ? point.hoop_stretch * v_r_over_r : 0.;

    const MaterialPointResponse &D0    = point.at_rest;
    SymmetricTensor<2, 2>        S_v   = a_K * (D0.tangent * rate);
    double                       S_v33 = 0.;
    if (point.strains_the_hoop)
      {
        S_v += a_K * D0.hoop_coupling * hoop_rate;
        S_v33 = a_K * (D0.hoop_coupling * rate + D0.hoop_stiffness * hoop_rate);
      }

    const double stiffness = a_K * velocity_factor;
    for (unsigned int i = 0; i < n; ++i)
      {
        double force = S_v * dE[i];
        if (point.strains_the_hoop)
          force += S_v33 * dE33[i];
        cell_rhs(i) -= force * point.dV;
        cell_viscous_force(i) += force * point.dV;

        const SymmetricTensor<2, 2> D_dE_i   = D0.tangent * dE[i];
        const Tensor<1, 2>          S_grad_i = Tensor<2, 2>(S_v) * grad[i];
        for (unsigned int j = 0; j <= i; ++j)
          {
            double k = stiffness * (dE[j] * D_dE_i);
            if (component[i] == component[j])
              k += S_grad_i * grad[j];
            if (point.strains_the_hoop)
              {
                k += stiffness * (dE33[j] * (D0.hoop_coupling * dE[i]) +
                                  dE33[i] * (D0.hoop_coupling * dE[j]) +
                                  D0.hoop_stiffness * dE33[i] * dE33[j]);
                if (component[i] == 0 && component[j] == 0)
                  k += S_v33 * evaluator.shape_value(i, q) *
                       evaluator.shape_value(j, q) /
                       (point.radius * point.radius);
              }
            cell_matrix(i, j) += k * point.dV;
          }
      }
  }
} // namespace glissade

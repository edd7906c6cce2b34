// The forces of a turning frame (include/glissade/body/turning_frame.h):
// centrifugal, Coriolis and Euler, on the body's own mass.

#include <deal.II/fe/fe.h>

#include <glissade/body/body.h>
#include <glissade/body/turning_frame.h>

#include <cmath>

namespace glissade
{
  using namespace dealii;

  TurningFrame::TurningFrame(const Body                    &body,
                             const TurningFrameDescription &description,
                             Vector<double>                 reference_position,
                             const std::string             &where)
    : angular_velocity_function({description.angular_velocity},
                                where + "/Turning frame/Angular velocity")
    , coriolis(description.coriolis)
    , reference_position(std::move(reference_position))
  {
    // The partner of a dof: the same node's dof of the other component,
    // of the same kind (value, or the same derivative of a Hermite space).
    const FiniteElement<2> &fe = body.dof_handler().get_fe();
    const unsigned int per_dim = body.space().components_per_displacement();
    partner.assign(body.n_dofs(), numbers::invalid_dof_index);
    sign.assign(body.n_dofs(), 0.);
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            const auto [system, index] = fe.system_to_component_index(i);
            const unsigned int c = system / per_dim, kind = system % per_dim;
            const unsigned int other =
              fe.component_to_system_index((1 - c) * per_dim + kind, index);
            partner[local[i]] = local[other];
            sign[local[i]]    = c == 0 ? -1. : 1.;
          }
      }
  }



  void
  TurningFrame::set_time(const double t)
  {
    const Point<2> origin;
    angular_velocity_function.set_time(t);
    omega = angular_velocity_function.value(origin, 0);
    // dOmega/dt by a central difference of the expression
    const double h = 1e-6 * (1. + std::abs(t));
    angular_velocity_function.set_time(t + h);
    const double after = angular_velocity_function.value(origin, 0);
    angular_velocity_function.set_time(t - h);
    const double before = angular_velocity_function.value(origin, 0);
    omega_rate          = (after - before) / (2. * h);
    angular_velocity_function.set_time(t);
  }



  void
  TurningFrame::add_cell_terms(const FullMatrix<double>                   &mass,
                               const std::vector<types::global_dof_index> &dofs,
                               const Vector<double>                       &u,
                               const std::vector<double> &v_local,
                               const double               c_v,
                               FullMatrix<double>        *cell_matrix,
                               Vector<double>            &cell_rhs) const
  {
    const unsigned int n = dofs.size();
    // The cell's r and v by dof, and their turns J r, J v (the partners of
    // a cell's dofs are in the cell: the same node's).
    std::vector<double> r(n), Jr(n), Jv(n);
    std::vector<int>    local_partner(n, -1);
    for (unsigned int j = 0; j < n; ++j)
      {
        r[j] = reference_position(dofs[j]) + u(dofs[j]);
        for (unsigned int k = 0; k < n; ++k)
          if (dofs[k] == partner[dofs[j]])
            local_partner[j] = k;
      }
    for (unsigned int j = 0; j < n; ++j)
      {
        const unsigned int k = local_partner[j];
        Jr[j] = sign[dofs[j]] * (reference_position(dofs[k]) + u(dofs[k]));
        Jv[j] = sign[dofs[j]] * v_local[k];
      }
    const double coriolis_factor = coriolis ? 2. * omega : 0.;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const double m = mass(i, j);
          if (m == 0.)
            continue;
          cell_rhs(i) += m * (omega * omega * r[j] - coriolis_factor * Jv[j] -
                              omega_rate * Jr[j]);
          if (cell_matrix == nullptr)
            continue;
          // d/du_j of Omega^2 r_j; d/du_partner(j) of J v_j and J r_j
          (*cell_matrix)(i, j) -= m * omega * omega;
          (*cell_matrix)(i, local_partner[j]) +=
            m * sign[dofs[j]] * (coriolis_factor * c_v + omega_rate);
        }
  }



  Vector<double>
  TurningFrame::turn(const Vector<double> &w) const
  {
    Vector<double> Jw(w.size());
    for (types::global_dof_index i = 0; i < w.size(); ++i)
      if (partner[i] != numbers::invalid_dof_index)
        Jw(i) = sign[i] * w(partner[i]);
    return Jw;
  }



  Vector<double>
  TurningFrame::forces(
    const std::function<Vector<double>(const Vector<double> &)> &apply_mass,
    const Vector<double>                                        &u,
    const Vector<double>                                        &v) const
  {
    Vector<double> r = reference_position;
    r += u;
    Vector<double> f = r;
    f *= omega * omega;
    if (coriolis)
      f.add(-2. * omega, turn(v));
    f.add(-omega_rate, turn(r));
    return apply_mass(f);
  }
} // namespace glissade

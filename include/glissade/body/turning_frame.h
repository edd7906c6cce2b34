#pragma once

#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <glissade/base/user_function.h>
#include <glissade/description/scene_description.h>

#include <functional>
#include <vector>

namespace glissade
{
  class Body;

  /**
   * The forces of the frame a body is seen from when that frame turns at
   * Omega(t) about e_3 through a centre (Body <name>/Turning frame): per
   * unit mass, with r = x - centre the current position and v the
   * velocity relative to the frame,
   *
   *   f = Omega^2 r - 2 Omega e_3 x v - dOmega/dt e_3 x r,
   *
   * centrifugal, Coriolis and Euler. BodyInertia adds M f to each cell's
   * residual, with the body's own mass matrix (redistributed or not), and
   * its derivative to the tangent: -Omega^2 M (spin softening; the
   * centrifugal stress the body's large-strain law makes is its
   * stiffening), 2 Omega c_v M J and dOmega/dt M J for the Coriolis and
   * Euler forces, J the turn by a right angle (e_3 x) of the dof vectors.
   * The Coriolis forces do no work: J's product with M is skew.
   */
  class TurningFrame
  {
  public:
    /**
     * `reference_position`: X - centre at the body's dofs (a Hermite
     * derivative dof: its derivative); `where` names the body for messages.
     */
    TurningFrame(const Body                    &body,
                 const TurningFrameDescription &description,
                 dealii::Vector<double>         reference_position,
                 const std::string             &where);

    /** Omega and dOmega/dt at t. */
    void
    set_time(const double t);

    double
    angular_velocity() const
    {
      return omega;
    }

    /**
     * One cell's frame forces M_c f at the displacement u and the cell's
     * velocity v_local (the scheme's end-state velocity, whose derivative
     * in u is c_v), added to cell_rhs; their derivatives in u subtracted
     * from cell_matrix (which holds d(F_int - F_ext) / du), if given.
     */
    void
    add_cell_terms(const dealii::FullMatrix<double>                   &mass,
                   const std::vector<dealii::types::global_dof_index> &dofs,
                   const dealii::Vector<double>                       &u,
                   const std::vector<double>                          &v_local,
                   const double                                        c_v,
                   dealii::FullMatrix<double> *cell_matrix,
                   dealii::Vector<double>     &cell_rhs) const;

    /**
     * The frame forces M f on every dof at u and v, with `apply_mass`
     * the body's M x.
     */
    dealii::Vector<double>
    forces(const std::function<dealii::Vector<double>(
             const dealii::Vector<double> &)> &apply_mass,
           const dealii::Vector<double>       &u,
           const dealii::Vector<double>       &v) const;

  private:
    /** J w: (e_3 x w) at the dof level, (J w)_i = sign_i w_partner(i). */
    dealii::Vector<double>
    turn(const dealii::Vector<double> &w) const;

    UserFunction           angular_velocity_function;
    const bool             coriolis;
    dealii::Vector<double> reference_position;
    /** For each dof, the dof of the other component at the same node (and
     *  of the same kind, value or derivative), and J's sign on it. */
    std::vector<dealii::types::global_dof_index> partner;
    std::vector<double>                          sign;
    double                                       omega = 0., omega_rate = 0.;
  };
} // namespace glissade

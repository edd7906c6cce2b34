#pragma once

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>

#include <glissade/body/rigid_motion.h>
#include <glissade/fe/element_space.h>

#include <string>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * A body that relies on contact to hold what its supports leave free:
   * the rigid motions no support holds, and the springs that make its
   * tangent invertible all the same (doc/contact.md, "Bodies held by
   * contact").
   *
   * The tangent of such a body is singular; one spring k e_i e_i^T at a
   * contact dof per free motion makes it factorisable. The contact problem
   * takes the springs out again exactly, as rank-one terms of its Newton
   * matrix (theory.md, section 4.6), so no spring is left in the answer.
   * Empty for a body its supports hold, and for a dynamic one, whose mass
   * holds every motion.
   */
  class RigidMotionSprings
  {
  public:
    /**
     * `free_motions`: orthonormal combinations of rigid_motion_basis();
     * `source` (the .prm file), `body_name` and `body_size` say which
     * body relies on contact if none of its contact nodes can hold a
     * motion.
     */
    RigidMotionSprings(const std::vector<RigidMotion> &free_motions,
                       const std::string              &source,
                       const std::string              &body_name,
                       const double                    body_size);

    /** The rigid motions that the body's supports leave free. */
    const std::vector<RigidMotion> &
    free_motions() const
    {
      return motions_left_free;
    }

    /** Under a dynamic scheme the mass holds every motion: none is free. */
    void
    hold_by_inertia()
    {
      motions_left_free.clear();
    }

    /**
     * Chooses the springs' dofs among the contact dofs, one per free
     * motion: the best conditioned set (a pivoted Gram-Schmidt on the
     * motions' values there). An input error if a free motion moves none
     * of them.
     */
    void
    choose_dofs(
      const std::vector<dealii::types::global_dof_index> &contact_dofs,
      const dealii::AffineConstraints<double>            &constraints,
      const dealii::DoFHandler<2>                        &dofs,
      const ElementSpace                                 &space);

    /**
     * The springs as (dof, k), k set by the last add_to(): what the
     * contact problem takes out of its Newton matrix again.
     */
    const std::vector<std::pair<dealii::types::global_dof_index, double>> &
    springs() const
    {
      return dofs_and_stiffness;
    }

    /**
     * Adds the springs, each of stiffness `k`, to the diagonal of `tangent`
     * (the caller makes k as stiff as an average dof of the whole tangent,
     * so that they neither dominate nor vanish in the factorisation);
     * returns the diagonal entries as they were, for take_from(). On
     * several processes, where each holds a share of the tangent, one
     * process adds them and the others call with `add = false`, which sets
     * k alone.
     */
    std::vector<double>
    add_to(dealii::SparseMatrix<double> &tangent,
           const double                  k,
           const bool                    add);

    /** Restores the diagonal entries that add_to() changed. */
    void
    take_from(dealii::SparseMatrix<double> &tangent,
              const std::vector<double>    &assembled) const;

  private:
    std::vector<RigidMotion> motions_left_free;
    std::vector<std::pair<dealii::types::global_dof_index, double>>
                      dofs_and_stiffness;
    const std::string source;
    const std::string body_name;
    const double      body_size;
  };
} // namespace glissade

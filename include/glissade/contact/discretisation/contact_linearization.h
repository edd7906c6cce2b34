#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <glissade/contact/surfaces/master_surface.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace glissade
{
  /**
   * A coefficient on one dof of a contact pair's bodies (body 0: the slave,
   * 1: the master).
   */
  struct DofCoefficient
  {
    unsigned int                    body;
    dealii::types::global_dof_index dof;
    double                          value;
  };

  /** A row or a column over the dofs: a sparse vector of coefficients. */
  using DofVector = std::vector<DofCoefficient>;

  /**
   * A slave point's share of one node or control point of the slave body:
   * the point moves by `weight` times the displacement in `dofs` (x, y).
   */
  struct SlaveShare
  {
    std::array<dealii::types::global_dof_index, 2> dofs;
    double                                         weight;
  };
  using SlaveShares = std::vector<SlaveShare>;

  /**
   * One contact node's gap and slip and their derivatives with respect to
   * the dofs, the forces of its reaction on the dofs, and its share of the
   * contact tangent (theory.md, section 4.2). Written once for every
   * surface: a surface describes its point by SurfacePoint.
   *
   * With t, n the frame at the node's point c(s) on the master, the gap is
   * g = (x - c(s)) . n and the slip since the increment began is
   * u_t = t . d, d = (x - x_0) - (the displacement of the master's material
   * point c(s) since then). The reaction r = (r_t, r_n) acts as the force
   * lambda = r_t t + r_n n on the slave node and -phi_j lambda on the
   * master dofs that receive it. The contact tangent at fixed r has rank
   * two: the point slides along the master (ds) and the frame turns
   * (d theta).
   */
  struct ContactLinearization
  {
    double gap  = 0.;
    double slip = 0.;

    /**
     * The vertex's cone (SurfacePoint::vertex_cone; zero off a vertex):
     * there the slip is the tangential offset from the vertex, and the
     * reaction may tilt by atan(vertex_cone) from the normal besides
     * friction.
     */
    double vertex_cone = 0.;

    /** d u_t / dU and dg / dU. */
    DofVector slip_row, gap_row;

    /** The dof forces of a unit tangential and a unit normal reaction. */
    DofVector tangential_force, normal_force;

    /**
     * The contact tangent at the node's reaction, dF/dU = sum load (x)
     * row: node-to-segment has two terms (the point slides along the
     * master, ds/dU, and the frame turns, d theta/dU); mortar has one per
     * master node its weights reach, and the turn of the nodal normal.
     */
    struct Term
    {
      DofVector load, row;
    };
    std::vector<Term> tangent_terms;

    /** Frees the rows, forces and tangent terms, keeping gap and slip (an
     *  inactive node's: nothing reads them until it is projected again). */
    void
    release_rows()
    {
      DofVector().swap(slip_row);
      DofVector().swap(gap_row);
      DofVector().swap(tangential_force);
      DofVector().swap(normal_force);
      std::vector<Term>().swap(tangent_terms);
    }
  };

  /**
   * The bound on |r_t| / r_n that the local solver holds a node to: the
   * pair's Coulomb mu, and at a vertex with a cone (vertex_cone > 0) the
   * facets' normals' half angle added to friction's, tan(atan(vertex_cone)
   * + atan(mu)): the node sticks at the vertex while its reaction lies
   * within the two facets' friction cones, and leaves it along a facet at
   * that facet's Coulomb bound, so the reaction is the same on both sides
   * of the hand-over.
   */
  inline double
  cone_slope(const double mu, const double vertex_cone)
  {
    return vertex_cone > 0. ? std::tan(std::atan(vertex_cone) + std::atan(mu)) :
                              mu;
  }

  /**
   * The linearisation of a slave point at x made of `slave_shares`, moved by
   * `slave_motion` since the increment began, against its point on the
   * master, whose dofs moved by `master_increment(dof)` since then, with
   * the reaction `reaction` = (r_t, r_n) (that of the last iteration, at
   * which the tangent is taken).
   */
  ContactLinearization
  linearize_contact(const dealii::Point<2>     &x,
                    const SlaveShares          &slave_shares,
                    const dealii::Tensor<1, 2> &slave_motion,
                    const SurfacePoint         &point,
                    const std::function<double(dealii::types::global_dof_index)>
                                                &master_increment,
                    const std::array<double, 2> &reaction);
} // namespace glissade

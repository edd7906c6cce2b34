#pragma once

#include <deal.II/lac/vector.h>

#include <glissade/contact/compliance_matrix.h>
#include <glissade/contact/contact_linearization.h>

#include <memory>
#include <vector>

namespace glissade
{
  class Body;

  /**
   * A vector over the dofs of a contact pair's bodies (DofCoefficient::body
   * 0 or 1), with the simulation's indices of those two bodies (the second
   * is numbers::invalid_unsigned_int for a rigid obstacle).
   */
  struct PairVector
  {
    const DofVector            *coefficients;
    std::array<unsigned int, 2> bodies;
  };

  /**
   * A rank-one change of the bodies' tangent, K <- K - load (x) row, that
   * lives on contact dofs: a term of the contact tangent, the removal of a
   * floating body's regularisation, or an augmentation of a closed
   * contact constraint.
   */
  struct RankOneTerm
  {
    PairVector load, row;
  };

  /**
   * The Newton step of the bodies in contact, condensed on the active
   * contact nodes (paper eq. 8-10; theory.md, section 4.3).
   *
   * Each body has factorised its own matrix K_b; the true Newton matrix is
   * K - sum_j u_j (x) v_j, with rank-one terms on the contact dofs (the
   * contact tangent couples the bodies that touch, two terms per node). So
   * the step needs nothing but the contact block C of each K_b^-1
   * (Woodbury): with U the loads and V the rows of the terms, and
   * S = I - V C U,
   *
   *   (K - U V)^-1 = K^-1 + K^-1 U S^-1 V K^-1.
   *
   * With R the slip and gap rows and F the forces of unit reactions, the
   * compliance is W = R C F + (R C U) S^-1 (V C F), the free relative
   * displacement u_free = u_0 + R d + (R C U) S^-1 V d with d = du_lib +
   * K^-1 a (du_lib = K^-1 rhs, a an extra load), and the step du = d +
   * K^-1 (F r + U z), z = S^-1 (V d + V C F r): one more solve per body.
   */
  class CondensedProblem
  {
  public:
    using Vector2 = ComplianceMatrix::Vector2;

    /**
     * Forms W from the bodies' compliance (their current factorisations);
     * `predictor` holds each body's du_lib = K_b^-1 rhs_b. `forces` and
     * `rows` are the forces of unit reactions (tangential, normal) and the
     * slip and gap rows, two per node, and `initial` the slip and gap
     * now; `extra_load` (may be empty) is added to the right-hand side.
     */
    CondensedProblem(const std::vector<Vector2>                &initial,
                     const std::vector<PairVector>             &forces,
                     const std::vector<PairVector>             &rows,
                     const std::vector<RankOneTerm>            &terms,
                     const std::vector<PairVector>             &extra_load,
                     const std::vector<std::unique_ptr<Body>>  &bodies,
                     const std::vector<dealii::Vector<double>> &predictor);

    /** False if the Newton matrix is singular on the contact dofs (S is). */
    bool
    regular() const
    {
      return is_regular;
    }

    /** W, the compliance of the Newton matrix. */
    const ComplianceMatrix &
    compliance() const
    {
      return W;
    }

    /** (slip, gap) of each node after the predictor, with no reaction. */
    const std::vector<Vector2> &
    free_displacement() const
    {
      return u_free;
    }

    /**
     * The normal compliance of node k through the bodies' own matrices,
     * without the rank-one terms.
     */
    double
    base_normal_compliance(const unsigned int k) const
    {
      return base_compliance[k];
    }

    /** u = u_free + W r. */
    std::vector<Vector2>
    displacement(const std::vector<Vector2> &r) const;

    /**
     * `increments` holds du_lib on entry and du on exit; `contact_forces`
     * receives each body's F r (the forces of the reactions on its dofs).
     */
    void
    correct(const std::vector<Vector2>          &r,
            std::vector<dealii::Vector<double>> &increments,
            std::vector<dealii::Vector<double>> &contact_forces) const;

  private:
    /**
     * rows C loads, the products with each body's compliance, into
     * `products` (rows x loads, column major).
     */
    void
    add_compliance_products(const std::vector<PairVector> &all_rows,
                            const std::vector<PairVector> &all_loads,
                            std::vector<double>           &products) const;

    const std::vector<PairVector>            &forces;
    const std::vector<RankOneTerm>           &terms;
    const std::vector<PairVector>            &extra_load;
    const std::vector<std::unique_ptr<Body>> &bodies;
    const unsigned int                        n;
    const unsigned int                        n_terms;

    /** LU of S and its pivots; X = S^-1 V C F; y = S^-1 V d. */
    std::vector<double> S;
    std::vector<int>    pivots;
    std::vector<double> X;
    std::vector<double> y;
    bool                is_regular = true;

    ComplianceMatrix     W;
    std::vector<Vector2> u_free;
    std::vector<double>  base_compliance;
  };
} // namespace glissade

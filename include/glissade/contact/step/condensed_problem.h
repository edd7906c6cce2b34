#pragma once

#include <deal.II/lac/vector.h>

#include <glissade/contact/discretisation/contact_linearization.h>
#include <glissade/lac/compliance_matrix.h>

#include <array>
#include <cstddef>
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
   * A rank-one change of the bodies' matrices, K <- K - load (x) row, that
   * lives on contact dofs: a term of the contact tangent, or the removal
   * of a floating body's regularisation.
   */
  struct RankOneTerm
  {
    PairVector load, row;
  };

  /** The active contact nodes of a Newton iteration, as the condensed problem
   * sees them. */
  struct ActiveNodes
  {
    using Vector2 = ComplianceMatrix::Vector2;

    /** (slip, gap) of each node now. */
    std::vector<Vector2> initial;
    /** The forces of unit reactions (tangential, normal): two per node. */
    std::vector<PairVector> forces;
    /** The slip and gap rows: two per node. */
    std::vector<PairVector> rows;
    /** The terms of the contact tangent and any other rank-one change. */
    std::vector<RankOneTerm> terms;
    /** Coulomb's mu of each node. */
    std::vector<double> friction;
    /** The cap on each node's normal reaction (an abradable coating's;
     *  infinity: none). */
    std::vector<double> normal_cap;

    unsigned int
    size() const
    {
      return initial.size();
    }
  };

  /**
   * The closed directions of the contact constraints added to the Newton
   * matrix, K + sum E_k row_k (x) row_k, with the right-hand side
   * - E_k u_k row_k (theory.md, section 4.5): per node, whether its
   * tangential (stick) and normal (closed) directions are augmented, and
   * a factor on the stiffness E_k = factor / (the node's compliance through
   * its bodies alone).
   */
  struct Augmentation
  {
    std::vector<std::array<bool, 2>> directions;
    double                           factor = 1.;

    unsigned int
    count() const
    {
      unsigned int n = 0;
      for (const auto &d : directions)
        n += d[0] + d[1];
      return n;
    }
  };

  /**
   * The compliance products rows C loads (CondensedProblem) that this
   * process holds, column major with one row per row: its share of the
   * columns of F, the forces of unit reactions (processes::share of the 2n:
   * all of them on one process), and every column of U, the rank-one
   * terms' loads (each process forms its share and they are gathered).
   * Where a process forms W's and X's columns from its own columns of F,
   * it needs no other process's; every process needs all of R C U and
   * V C U.
   */
  struct ComplianceProducts
  {
    ComplianceProducts(std::size_t n_rows,
                       std::size_t n_forces,
                       std::size_t n_terms);

    /** The columns, zeros, made (not before they are needed). */
    void
    allocate();

    /** Whether this process forms the column of load j. */
    bool
    formed_here(const std::size_t j) const
    {
      return j < n_forces ?
               first_force <= j && j < end_force :
               first_term <= j - n_forces && j - n_forces < end_term;
    }

    /** Whether this process forms every column (it does on one process). */
    bool
    forms_every_column() const
    {
      return end_force - first_force == n_forces &&
             end_term - first_term == n_terms;
    }

    /** The column of load j (F's: this process's share only). */
    double *
    column(const std::size_t j)
    {
      return j < n_forces ? &force_columns[(j - first_force) * n_rows] :
                            &term_columns[(j - n_forces) * n_rows];
    }

    const std::size_t n_rows, n_forces, n_terms;
    /** This process's columns of F, [first_force, end_force), and of U. */
    std::size_t         first_force, end_force, first_term, end_term;
    std::vector<double> force_columns, term_columns;
  };

  /**
   * The Newton step of the bodies in contact, condensed on the active
   * contact nodes (paper eq. 8-10; theory.md, sections 4.3 and 4.5).
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
   * K^-1 a (du_lib = K^-1 rhs, a the augmentation's load), and the step
   * du = d + K^-1 (F r + U z), z = S^-1 (V d + V C F r): one more solve per
   * body.
   */
  class CondensedProblem
  {
  public:
    using Vector2 = ComplianceMatrix::Vector2;

    /**
     * Forms W from the bodies' compliance (their current factorisations);
     * `predictor` holds each body's du_lib = K_b^-1 rhs_b.
     */
    CondensedProblem(const ActiveNodes                         &nodes,
                     const Augmentation                        &augmentation,
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
     * Whether the symmetric part of W restricted to the given directions
     * (per node: tangential, normal) is positive definite: the local
     * problem on them is then convex.
     */
    bool
    positive_definite_on(
      const std::vector<std::array<bool, 2>> &directions) const;

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
     * rows C loads, the products with each body's compliance: the columns
     * `products` holds.
     */
    void
    add_compliance_products(const std::vector<PairVector> &all_rows,
                            const std::vector<PairVector> &all_loads,
                            ComplianceProducts            &products) const;

    /**
     * The augmented directions as rank-one terms: their rows appended to
     * `all_rows` and, unscaled, to `all_loads`; fills `augmented_row` and
     * `augmented_gap`.
     */
    void
    add_augmented_terms(const Augmentation      &augmentation,
                        std::vector<PairVector> &all_rows,
                        std::vector<PairVector> &all_loads);

    /**
     * Scales the products of the augmented loads by -E_k (into
     * `augmented_scale`), E_k from the normal compliances in the products
     * P; returns each row applied to K^-1 a, a the augmentation's load.
     */
    std::vector<double>
    scale_augmented_loads(double factor, ComplianceProducts &P);

    /**
     * S = I - V C U (its LU, in place of V C U in P), this process's
     * columns of X = S^-1 V C F and y = S^-1 V d from the products P and
     * the rows applied to d; false if S is singular to working precision.
     */
    bool
    solve_woodbury_system(ComplianceProducts        &P,
                          const std::vector<double> &row_of_d);

    /**
     * W = R C F + (R C U) X, its columns formed by shares and gathered; the
     * products P are released on the way.
     */
    void
    form_compliance(ComplianceProducts &P);

    /** u_free = u_0 + R d + (R C U) y. */
    void
    form_free_displacement(const ComplianceProducts  &P,
                           const std::vector<double> &row_of_d);

    const ActiveNodes                        &nodes;
    const std::vector<std::unique_ptr<Body>> &bodies;
    const unsigned int                        n;

    /**
     * The rank-one terms: the nodes' (`n_given` of them), then one per
     * augmented direction (load -E_k row_k, so `augmented_row` and
     * `augmented_scale` = -E_k, and its share of the right-hand side
     * `augmented_gap` = u_k).
     */
    unsigned int              n_given = 0;
    std::vector<unsigned int> augmented_row;
    std::vector<double>       augmented_scale, augmented_gap;

    /**
     * X = S^-1 V C F, this process's columns of it (those of its share of
     * F, from `first_force`), and y = S^-1 V d.
     */
    std::vector<double> X;
    std::size_t         first_force = 0, end_force = 0;
    std::vector<double> y;
    bool                is_regular = true;

    ComplianceMatrix     W;
    std::vector<Vector2> u_free;
  };
} // namespace glissade

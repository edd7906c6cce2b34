// Independent reference solvers and problem generators for
// bipotential_tests.cc. Nothing here uses BiPotentialSolver: the references
// are direct methods (active-set enumeration, Murty's principal pivoting,
// enumeration of stick/slip/open patterns) built on a plain Gaussian
// elimination, so that they share no code path with the iteration.
//
// Declared here, defined in bipotential_reference.cc.
#pragma once

#include <glissade/lac/compliance_matrix.h>

#include <cstddef>
#include <vector>

namespace reference
{
  using Vector2 = glissade::ComplianceMatrix::Vector2;

  // A square dense matrix, row-major.
  struct DenseMatrix
  {
    unsigned int        n = 0;
    std::vector<double> a;

    explicit DenseMatrix(const unsigned int size)
      : n(size)
      , a(std::size_t(size) * size, 0.)
    {}

    double &
    operator()(const unsigned int i, const unsigned int j)
    {
      return a[std::size_t(i) * n + j];
    }

    double
    operator()(const unsigned int i, const unsigned int j) const
    {
      return a[std::size_t(i) * n + j];
    }
  };

  // The 2n x 2n matrix of W, scalar index 2 k + component.
  DenseMatrix
  to_dense(const glissade::ComplianceMatrix &W);

  // u = u_free + W r, computed from the dense copy (not with the class).
  std::vector<Vector2>
  displacement(const DenseMatrix          &W,
               const std::vector<Vector2> &u_free,
               const std::vector<Vector2> &r);

  // ---------------------------------------------------------------------
  // Frictionless references: the LCP  w = q + M z >= 0, z >= 0, w.z = 0
  // with M the normal-normal part of W and q the free gaps.

  DenseMatrix
  normal_part(const DenseMatrix &W);

  // Murty's least-index principal pivoting method: flip the first index
  // that violates its sign condition. Finite for P-matrices (SPD included).
  // Returns the number of pivots, or -1 if it did not terminate.
  int
  murty_lcp(const DenseMatrix         &M,
            const std::vector<double> &q,
            std::vector<double>       &z);

  // All solutions of the LCP by enumeration of the 2^n active sets.
  std::vector<std::vector<double>>
  enumerate_lcp(const DenseMatrix &M, const std::vector<double> &q);

  // ---------------------------------------------------------------------
  // Coulomb reference: enumerate the 4^n patterns (open, stick, slip in +t,
  // slip in -t), solve the linear system each pattern implies, and keep the
  // patterns whose inequalities hold. Returns the distinct solutions.
  std::vector<std::vector<Vector2>>
  enumerate_coulomb(const DenseMatrix          &W,
                    const std::vector<Vector2> &u_free,
                    const std::vector<double>  &mu);

  // ---------------------------------------------------------------------
  // Problem generators.

  // A random symmetric positive definite W: B B^T / m + shift I with B of
  // size 2n x m (entries uniform in [-1, 1]), so the coupling between nodes
  // is of the same order as the diagonal.
  glissade::ComplianceMatrix
  random_spd(const unsigned int                        n_nodes,
             const unsigned int                        seed,
             const double                              shift = 0.2,
             const glissade::ComplianceMatrix::Storage storage =
               glissade::ComplianceMatrix::Storage::dense);

  // Nodes on the surface of an elastic half-plane (plane strain, reduced
  // modulus E* = 1), at the centres of n equal cells covering [-1, 1]. A
  // nodal force r_j is spread as a uniform pressure r_j / h over its cell;
  // the surface displacement of a line load P is (2 / (pi E*)) P ln(L / |x|)
  // (Johnson, Contact Mechanics, eq. 2.19b) with L = 8 > 2 * (length / 4),
  // which keeps the logarithmic kernel positive definite. The tangential
  // blocks use the same kernel and the normal-tangential coupling is
  // neglected (it vanishes for an incompressible half-plane).
  glissade::ComplianceMatrix
  half_plane(const unsigned int n_nodes, std::vector<double> &x);
} // namespace reference

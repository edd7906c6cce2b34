// The factorisation behind the condensed contact problem: the block of
// A^-1 on the contact dofs from a Cholesky factor with those dofs ordered
// last must equal the one obtained by back-substitutions with an
// independent LU (UMFPACK); a matrix that is not positive definite must
// fall back on LU and still be solved.

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <glissade/body/contact_port.h>
#include <glissade/lac/direct_solver.h>
#include <glissade/lac/schur_cholesky.h>

#include <cmath>

#include "test_tools.h"

using namespace dealii;
using namespace glissade;
using glissade_tests::check;

namespace
{
  /** 5-point Laplacian on an n x n grid, plus shift * identity. */
  void
  make_grid_matrix(const unsigned int    n,
                   const double          shift,
                   SparsityPattern      &pattern,
                   SparseMatrix<double> &matrix)
  {
    const unsigned int     size = n * n;
    DynamicSparsityPattern dsp(size, size);
    const auto id = [n](unsigned int i, unsigned int j) { return i * n + j; };
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          dsp.add(id(i, j), id(i, j));
          if (i > 0)
            dsp.add(id(i, j), id(i - 1, j));
          if (i + 1 < n)
            dsp.add(id(i, j), id(i + 1, j));
          if (j > 0)
            dsp.add(id(i, j), id(i, j - 1));
          if (j + 1 < n)
            dsp.add(id(i, j), id(i, j + 1));
        }
    pattern.copy_from(dsp);
    matrix.reinit(pattern);
    for (unsigned int i = 0; i < size; ++i)
      for (auto it = pattern.begin(i); it != pattern.end(i); ++it)
        matrix.set(i, it->column(), it->column() == i ? 4. + shift : -1.);
  }

  double
  residual(const SparseMatrix<double> &A,
           const Vector<double>       &x,
           const Vector<double>       &b)
  {
    Vector<double> r(b.size());
    A.vmult(r, x);
    r -= b;
    return r.linfty_norm() / b.linfty_norm();
  }
} // namespace



GLISSADE_TEST(contact_compliance_block_matches_solves)
{
  const unsigned int   n = 40;
  SparsityPattern      pattern;
  SparseMatrix<double> A;
  make_grid_matrix(n, 0.01, pattern, A);

  // "Contact dofs": one edge of the grid and a few scattered unknowns.
  std::vector<long> last;
  for (unsigned int j = 0; j < n; ++j)
    last.push_back(j);
  for (const long extra : {777L, 1234L, 1599L, 801L})
    last.push_back(extra);

  DirectSolver cholesky, lu;
  cholesky.use_cholesky(true, last);
  cholesky.factorize(A);
  lu.factorize(A);
  check(cholesky.has_inverse_block() && cholesky.n_cholesky == 1,
        "an SPD matrix is factorised by Cholesky");
  // The columns of C at the unknowns `columns` against LU solves.
  SchurCholesky &factor        = cholesky.cholesky();
  const auto     check_columns = [&](const std::vector<long> &columns,
                                 const std::string       &how) {
    double worst = 0., largest = 0.;
    for (const long j : columns)
      {
        Vector<double> column(A.m());
        column(j) = 1.;
        lu.solve(column);
        for (const long i : last)
          {
            const double block = factor.inverse_entry(factor.last_position(i),
                                                      factor.last_position(j));
            worst   = std::max(worst, std::abs(block - column(i)));
            largest = std::max(largest, std::abs(column(i)));
          }
      }
    std::cout << "  " << how << ": columns of A^-1 on " << last.size()
              << " last unknowns (1600 in all): largest entry " << largest
              << ", largest difference to LU back-substitutions " << worst
              << std::endl;
    check(worst <= 1e-10 * largest, how + ": differs from LU solves");
  };
  const auto positions = [&](const std::vector<long> &unknowns) {
    std::vector<long> p;
    for (const long j : unknowns)
      p.push_back(factor.last_position(j));
    return p;
  };
  // Both ways of forming C: a few columns by triangular solves (fewer
  // than a third of them), then the whole block by dpotri.
  const std::vector<long> few = {3, 777, 1599};
  factor.compute_inverse_columns(positions(few));
  check(factor.n_inverse_columns() == 3, "three columns formed");
  check_columns(few, "3 columns by dpotrs");
  factor.compute_inverse_columns(positions(last));
  check(factor.n_inverse_columns() == long(last.size()),
        "the whole block formed");
  check_columns(last, "the whole block by dpotri");

  Vector<double> b(A.m()), x(A.m());
  for (unsigned int i = 0; i < b.size(); ++i)
    b(i) = std::sin(0.1 * i) + 0.5;
  x = b;
  cholesky.solve(x);
  const double r = residual(A, x, b);
  std::cout << "  Cholesky solve: relative residual " << r << std::endl;
  check(r < 1e-12, "Cholesky solve residual");
}



GLISSADE_TEST(contact_compliance_indefinite_falls_back_on_lu)
{
  // Laplacian eigenvalues on a 20 x 20 grid lie in (0, 8); a shift of -1
  // makes the matrix indefinite but leaves it regular.
  SparsityPattern      pattern;
  SparseMatrix<double> A;
  make_grid_matrix(20, -1., pattern, A);
  DirectSolver solver;
  solver.use_cholesky(true, {0, 1, 2, 3});
  solver.factorize(A);
  std::cout << "  Cholesky factorisations " << solver.n_cholesky << ", LU "
            << solver.n_lu << std::endl;
  check(solver.n_lu == 1 && !solver.has_inverse_block(),
        "an indefinite matrix falls back on LU");

  Vector<double> b(A.m()), x(A.m());
  for (unsigned int i = 0; i < b.size(); ++i)
    b(i) = std::cos(0.3 * i);
  x = b;
  solver.solve(x);
  const double r = residual(A, x, b);
  std::cout << "  LU solve after the fall-back: relative residual " << r
            << std::endl;
  check(r < 1e-10, "fall-back solve residual");
}



// The compliance between contact dofs when some were not declared when
// the factorisation chose its last unknowns (a node activated within the
// increment): the declared pairs come from the factor's inverse, a dof not
// declared takes one back-substitution (its column, and by symmetry its
// row). Every entry must equal an independent LU solve's, and only the
// undeclared dofs may cost a solve (before, one of them made every column
// a solve: 156 s of W against 0.76 s on 390,000 dofs).
GLISSADE_TEST(contact_compliance_block_with_undeclared_dofs)
{
  const unsigned int   n = 40;
  SparsityPattern      pattern;
  SparseMatrix<double> A;
  make_grid_matrix(n, 0.01, pattern, A);

  std::vector<types::global_dof_index> declared;
  for (unsigned int j = 0; j < n; ++j)
    declared.push_back(j);
  AffineConstraints<double> no_constraints;
  no_constraints.close();
  ContactPort             port(A.m());
  const std::vector<long> last = port.declare(declared, no_constraints);

  DirectSolver cholesky, lu;
  cholesky.use_cholesky(true, last);
  cholesky.factorize(A);
  lu.factorize(A);
  check(cholesky.has_inverse_block(),
        "an SPD matrix is factorised by Cholesky");
  unsigned int                        solves = 0;
  const ContactPort::HomogeneousSolve solve  = [&](const Vector<double> &f,
                                                  Vector<double>       &x) {
    ++solves;
    x = f;
    cholesky.solve(x);
  };

  // Rows and columns mixing declared dofs and two that were not (41, one
  // row into the grid, and 1599, the far corner), in both roles.
  const std::vector<types::global_dof_index> rows    = {0, 5, 41, 39, 1599};
  const std::vector<types::global_dof_index> columns = {1599, 2, 41, 17};
  std::vector<double>                        block;
  port.compliance_block(rows, columns, cholesky, solve, block);
  double worst = 0., largest = 0.;
  for (std::size_t c = 0; c < columns.size(); ++c)
    {
      Vector<double> column(A.m());
      column(columns[c]) = 1.;
      lu.solve(column);
      for (std::size_t r = 0; r < rows.size(); ++r)
        {
          worst =
            std::max(worst,
                     std::abs(block[r + c * rows.size()] - column(rows[r])));
          largest = std::max(largest, std::abs(column(rows[r])));
        }
    }
  std::cout << "  " << rows.size() << " x " << columns.size()
            << " block, 2 dofs undeclared: largest entry " << largest
            << ", largest difference to LU " << worst << ", " << solves
            << " back-substitutions" << std::endl;
  check(worst <= 1e-10 * largest, "the block differs from LU solves");
  check(solves == 2, "only the two undeclared dofs may cost a solve");
}

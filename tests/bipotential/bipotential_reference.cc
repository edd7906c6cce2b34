// The reference solvers and problem generators of bipotential_reference.h.

#include "bipotential_reference.h"

#include <glissade/lac/compliance_matrix.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace reference
{
  namespace
  {
    // Solve A x = b by Gaussian elimination with partial pivoting. Returns
    // false if a pivot is below 1e-13 times the largest entry (singular).
    bool
    gauss_solve(DenseMatrix A, std::vector<double> b, std::vector<double> &x)
    {
      const unsigned int n       = A.n;
      double             largest = 0.;
      for (double v : A.a)
        largest = std::max(largest, std::abs(v));
      for (unsigned int c = 0; c < n; ++c)
        {
          unsigned int pivot = c;
          for (unsigned int i = c + 1; i < n; ++i)
            if (std::abs(A(i, c)) > std::abs(A(pivot, c)))
              pivot = i;
          if (std::abs(A(pivot, c)) <= 1e-13 * largest)
            return false;
          if (pivot != c)
            {
              for (unsigned int j = 0; j < n; ++j)
                std::swap(A(c, j), A(pivot, j));
              std::swap(b[c], b[pivot]);
            }
          for (unsigned int i = c + 1; i < n; ++i)
            {
              const double factor = A(i, c) / A(c, c);
              for (unsigned int j = c; j < n; ++j)
                A(i, j) -= factor * A(c, j);
              b[i] -= factor * b[c];
            }
        }
      x.assign(n, 0.);
      for (unsigned int i = n; i-- > 0;)
        {
          double sum = b[i];
          for (unsigned int j = i + 1; j < n; ++j)
            sum -= A(i, j) * x[j];
          x[i] = sum / A(i, i);
        }
      return true;
    }
  } // namespace

  DenseMatrix
  to_dense(const glissade::ComplianceMatrix &W)
  {
    DenseMatrix result(W.size());
    for (unsigned int k = 0; k < W.n_nodes(); ++k)
      for (unsigned int l = 0; l < W.n_nodes(); ++l)
        {
          const auto block = W.block(k, l);
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int b = 0; b < 2; ++b)
              result(2 * k + a, 2 * l + b) = block[a][b];
        }
    return result;
  }

  std::vector<Vector2>
  displacement(const DenseMatrix          &W,
               const std::vector<Vector2> &u_free,
               const std::vector<Vector2> &r)
  {
    std::vector<Vector2> u = u_free;
    for (unsigned int i = 0; i < W.n; ++i)
      for (unsigned int j = 0; j < W.n; ++j)
        u[i / 2][i % 2] += W(i, j) * r[j / 2][j % 2];
    return u;
  }

  // ---------------------------------------------------------------------
  // Frictionless references: the LCP  w = q + M z >= 0, z >= 0, w.z = 0
  // with M the normal-normal part of W and q the free gaps.

  DenseMatrix
  normal_part(const DenseMatrix &W)
  {
    DenseMatrix M(W.n / 2);
    for (unsigned int i = 0; i < M.n; ++i)
      for (unsigned int j = 0; j < M.n; ++j)
        M(i, j) = W(2 * i + 1, 2 * j + 1);
    return M;
  }

  namespace
  {
    // z with z_A = -M_AA^-1 q_A on the active set A, zero elsewhere.
    bool
    solve_on_active_set(const DenseMatrix         &M,
                        const std::vector<double> &q,
                        const std::vector<bool>   &active,
                        std::vector<double>       &z)
    {
      std::vector<unsigned int> index;
      for (unsigned int i = 0; i < M.n; ++i)
        if (active[i])
          index.push_back(i);
      z.assign(M.n, 0.);
      if (index.empty())
        return true;
      DenseMatrix         M_AA(index.size());
      std::vector<double> minus_q(index.size());
      for (unsigned int i = 0; i < index.size(); ++i)
        {
          minus_q[i] = -q[index[i]];
          for (unsigned int j = 0; j < index.size(); ++j)
            M_AA(i, j) = M(index[i], index[j]);
        }
      std::vector<double> z_A;
      if (!gauss_solve(M_AA, minus_q, z_A))
        return false;
      for (unsigned int i = 0; i < index.size(); ++i)
        z[index[i]] = z_A[i];
      return true;
    }

    std::vector<double>
    lcp_w(const DenseMatrix         &M,
          const std::vector<double> &q,
          const std::vector<double> &z)
    {
      std::vector<double> w = q;
      for (unsigned int i = 0; i < M.n; ++i)
        for (unsigned int j = 0; j < M.n; ++j)
          w[i] += M(i, j) * z[j];
      return w;
    }
  } // namespace

  int
  murty_lcp(const DenseMatrix         &M,
            const std::vector<double> &q,
            std::vector<double>       &z)
  {
    double q_scale = 0.;
    for (double v : q)
      q_scale = std::max(q_scale, std::abs(v));
    const double      tolerance = 1e-12 * q_scale;
    std::vector<bool> active(M.n, false);
    for (int pivots = 0; pivots < 100000; ++pivots)
      {
        if (!solve_on_active_set(M, q, active, z))
          return -1;
        const std::vector<double> w        = lcp_w(M, q, z);
        int                       violated = -1;
        for (unsigned int i = 0; i < M.n && violated < 0; ++i)
          if ((active[i] && z[i] < -tolerance) ||
              (!active[i] && w[i] < -tolerance))
            violated = i;
        if (violated < 0)
          return pivots;
        active[violated] = !active[violated];
      }
    return -1;
  }

  std::vector<std::vector<double>>
  enumerate_lcp(const DenseMatrix &M, const std::vector<double> &q)
  {
    double q_scale = 0.;
    for (double v : q)
      q_scale = std::max(q_scale, std::abs(v));
    const double                     tolerance = 1e-12 * q_scale;
    std::vector<std::vector<double>> solutions;
    for (unsigned int mask = 0; mask < (1u << M.n); ++mask)
      {
        std::vector<bool> active(M.n);
        for (unsigned int i = 0; i < M.n; ++i)
          active[i] = (mask >> i) & 1u;
        std::vector<double> z;
        if (!solve_on_active_set(M, q, active, z))
          continue;
        const std::vector<double> w        = lcp_w(M, q, z);
        bool                      feasible = true;
        for (unsigned int i = 0; i < M.n; ++i)
          feasible = feasible && z[i] >= -tolerance && w[i] >= -tolerance;
        if (feasible)
          solutions.push_back(z);
      }
    return solutions;
  }

  // ---------------------------------------------------------------------
  // Coulomb reference.

  std::vector<std::vector<Vector2>>
  enumerate_coulomb(const DenseMatrix          &W,
                    const std::vector<Vector2> &u_free,
                    const std::vector<double>  &mu)
  {
    const unsigned int n       = W.n / 2;
    double             u_scale = 0.;
    for (const Vector2 &u : u_free)
      u_scale = std::max({u_scale, std::abs(u[0]), std::abs(u[1])});
    const double tolerance = 1e-11 * u_scale;

    std::vector<std::vector<Vector2>> solutions;
    unsigned int                      n_patterns = 1;
    for (unsigned int k = 0; k < n; ++k)
      n_patterns *= 4;
    for (unsigned int pattern = 0; pattern < n_patterns; ++pattern)
      {
        // Rows 2k, 2k+1 of the system hold node k's two equations.
        DenseMatrix         A(2 * n);
        std::vector<double> b(2 * n, 0.);
        std::vector<int>    state(n);
        for (unsigned int k = 0, p = pattern; k < n; ++k, p /= 4)
          state[k] = p % 4; // 0 open, 1 stick, 2 slip +t, 3 slip -t
        for (unsigned int k = 0; k < n; ++k)
          {
            const unsigned int rt = 2 * k, rn = 2 * k + 1;
            if (state[k] == 0) // r = 0
              {
                A(rt, rt) = 1.;
                A(rn, rn) = 1.;
                continue;
              }
            // u_n = 0 in the three closed states.
            for (unsigned int j = 0; j < 2 * n; ++j)
              A(rn, j) = W(rn, j);
            b[rn] = -u_free[k][1];
            if (state[k] == 1) // u_t = 0
              {
                for (unsigned int j = 0; j < 2 * n; ++j)
                  A(rt, j) = W(rt, j);
                b[rt] = -u_free[k][0];
              }
            else // r_t = -s mu r_n with s the direction of slip
              {
                const double s = state[k] == 2 ? 1. : -1.;
                A(rt, rt)      = 1.;
                A(rt, rn)      = s * mu[k];
              }
          }
        std::vector<double> x;
        if (!gauss_solve(A, b, x))
          continue;
        std::vector<Vector2> r(n);
        for (unsigned int k = 0; k < n; ++k)
          r[k] = {{x[2 * k], x[2 * k + 1]}};
        const std::vector<Vector2> u          = displacement(W, u_free, r);
        const double               force_tol  = tolerance / W(1, 1);
        bool                       admissible = true;
        for (unsigned int k = 0; k < n; ++k)
          {
            if (state[k] == 0)
              admissible = admissible && u[k][1] >= -tolerance;
            else if (state[k] == 1)
              admissible = admissible && r[k][1] >= -force_tol &&
                           std::abs(r[k][0]) <= mu[k] * r[k][1] + force_tol;
            else
              {
                const double s = state[k] == 2 ? 1. : -1.;
                admissible     = admissible && r[k][1] >= -force_tol &&
                             s * u[k][0] >= -tolerance;
              }
          }
        if (!admissible)
          continue;
        // Patterns on a stick/slip boundary give the same solution twice.
        bool seen = false;
        for (const auto &other : solutions)
          {
            double difference = 0.;
            for (unsigned int k = 0; k < n; ++k)
              difference = std::max({difference,
                                     std::abs(other[k][0] - r[k][0]),
                                     std::abs(other[k][1] - r[k][1])});
            seen = seen || difference <= 1e-8 * (1. + u_scale / W(1, 1));
          }
        if (!seen)
          solutions.push_back(r);
      }
    return solutions;
  }

  // ---------------------------------------------------------------------
  // Problem generators.

  glissade::ComplianceMatrix
  random_spd(const unsigned int                        n_nodes,
             const unsigned int                        seed,
             const double                              shift,
             const glissade::ComplianceMatrix::Storage storage)
  {
    std::mt19937                           generator(seed);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    const unsigned int                     size = 2 * n_nodes, m = size;
    DenseMatrix                            B(std::max(size, m));
    for (unsigned int i = 0; i < size; ++i)
      for (unsigned int j = 0; j < m; ++j)
        B(i, j) = uniform(generator);
    glissade::ComplianceMatrix W(n_nodes, storage);
    for (unsigned int k = 0; k < n_nodes; ++k)
      for (unsigned int l = 0; l < n_nodes; ++l)
        {
          glissade::ComplianceMatrix::Block block;
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int b = 0; b < 2; ++b)
              {
                double sum = 0.;
                for (unsigned int j = 0; j < m; ++j)
                  sum += B(2 * k + a, j) * B(2 * l + b, j);
                block[a][b] = sum / m + (2 * k + a == 2 * l + b ? shift : 0.);
              }
          W.set_block(k, l, block);
        }
    return W;
  }

  glissade::ComplianceMatrix
  half_plane(const unsigned int n_nodes, std::vector<double> &x)
  {
    const double h = 2. / n_nodes, L = 8.;
    x.resize(n_nodes);
    for (unsigned int i = 0; i < n_nodes; ++i)
      x[i] = -1. + (i + 0.5) * h;
    const auto F = [](const double z) {
      return z == 0. ? 0. : z * std::log(std::abs(z)) - z;
    };
    // The coefficient depends only on |i - j| on a uniform grid.
    std::vector<double> coefficient(n_nodes);
    for (unsigned int d = 0; d < n_nodes; ++d)
      {
        const double y = d * h;
        coefficient[d] =
          2. / M_PI * (std::log(L) - (F(y + 0.5 * h) - F(y - 0.5 * h)) / h);
      }
    glissade::ComplianceMatrix W(n_nodes);
    for (unsigned int k = 0; k < n_nodes; ++k)
      for (unsigned int l = 0; l < n_nodes; ++l)
        {
          const double c = coefficient[k > l ? k - l : l - k];
          W.set_block(k, l, {{{{c, 0.}}, {{0., c}}}});
        }
    return W;
  }
} // namespace reference

// Small helpers shared by the Hermite element tests: a check counter, a
// reproducible random source and a dense linear solver. Standard library only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "../harness.h"

namespace hermite_tests
{
  /** Prints each figure with its bound (glissade_tests::expect). */
  class Checker
  {
  public:
    /** Passes if value <= bound (an error or a round-off level). */
    void
    at_most(const std::string &name, const double value, const double bound)
    {
      char text[256];
      std::snprintf(text,
                    sizeof(text),
                    "%-66s %10.3e  (<= %.1e)",
                    name.c_str(),
                    value,
                    bound);
      glissade_tests::expect(value <= bound, text); // NaN fails, as wanted
    }

    /** Passes if lower <= value <= upper (a rate, a rank). */
    void
    between(const std::string &name,
            const double       value,
            const double       lower,
            const double       upper)
    {
      char text[256];
      std::snprintf(text,
                    sizeof(text),
                    "%-66s %10.4g  (in [%g, %g])",
                    name.c_str(),
                    value,
                    lower,
                    upper);
      glissade_tests::expect(value >= lower && value <= upper, text);
    }
  };

  /** Uniform random numbers from a fixed seed, so every run is the same. */
  class Random
  {
  public:
    double
    uniform(const double low = -1.0, const double high = 1.0)
    {
      return std::uniform_real_distribution<double>(low, high)(generator);
    }

  private:
    std::mt19937_64 generator{20120101};
  };

  /**
   * Solves A x = b for a small dense square A (row-major vectors) by
   * Gaussian elimination with partial pivoting.
   */
  inline std::vector<double>
  solve_dense(std::vector<std::vector<double>> A, std::vector<double> b)
  {
    const std::size_t n = b.size();
    for (std::size_t k = 0; k < n; ++k)
      {
        std::size_t pivot = k;
        for (std::size_t i = k + 1; i < n; ++i)
          if (std::abs(A[i][k]) > std::abs(A[pivot][k]))
            pivot = i;
        if (A[pivot][k] == 0.0)
          throw std::runtime_error("solve_dense: singular matrix");
        std::swap(A[k], A[pivot]);
        std::swap(b[k], b[pivot]);
        for (std::size_t i = k + 1; i < n; ++i)
          {
            const double factor = A[i][k] / A[k][k];
            for (std::size_t j = k; j < n; ++j)
              A[i][j] -= factor * A[k][j];
            b[i] -= factor * b[k];
          }
      }
    std::vector<double> x(n);
    for (std::size_t k = n; k-- > 0;)
      {
        double sum = b[k];
        for (std::size_t j = k + 1; j < n; ++j)
          sum -= A[k][j] * x[j];
        x[k] = sum / A[k][k];
      }
    return x;
  }

  /**
   * Numerical rank of a symmetric matrix: Gaussian elimination with full
   * (diagonal) pivoting, counting pivots above tolerance * largest pivot.
   */
  inline unsigned int
  numerical_rank(std::vector<std::vector<double>> A, const double tolerance)
  {
    const std::size_t n           = A.size();
    double            first_pivot = 0;
    for (std::size_t k = 0; k < n; ++k)
      {
        std::size_t pi = k, pj = k;
        for (std::size_t i = k; i < n; ++i)
          for (std::size_t j = k; j < n; ++j)
            if (std::abs(A[i][j]) > std::abs(A[pi][pj]))
              pi = i, pj = j;
        const double pivot = std::abs(A[pi][pj]);
        if (k == 0)
          first_pivot = pivot;
        if (pivot <= tolerance * first_pivot)
          return k;
        std::swap(A[k], A[pi]);
        for (auto &row : A)
          std::swap(row[k], row[pj]);
        for (std::size_t i = k + 1; i < n; ++i)
          {
            const double factor = A[i][k] / A[k][k];
            for (std::size_t j = k; j < n; ++j)
              A[i][j] -= factor * A[k][j];
          }
      }
    return n;
  }

  /** Convergence rate between two successive halvings of h. */
  inline double
  rate(const double coarse_error, const double fine_error)
  {
    return std::log2(coarse_error / fine_error);
  }
} // namespace hermite_tests

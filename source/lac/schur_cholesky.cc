#include <deal.II/base/timer.h>

#include <glissade/lac/schur_cholesky.h>

#include <suitesparse/camd.h>
#include <suitesparse/cholmod.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace glissade
{
  using namespace dealii;

  static_assert(std::is_same_v<SuiteSparse_long, long>,
                "SchurCholesky hands long indices to CHOLMOD");

  struct SchurCholesky::Cholmod
  {
    cholmod_common  common;
    cholmod_factor *factor = nullptr;

    Cholmod()
    {
      cholmod_l_start(&common);
      // Failures are reported through the status, never printed: a matrix
      // that is not positive definite is an expected outcome here.
      common.print              = 0;
      common.error_handler      = nullptr;
      common.supernodal         = CHOLMOD_SUPERNODAL;
      common.nmethods           = 1;
      common.method[0].ordering = CHOLMOD_GIVEN;
      // Postordering the elimination tree could move contact dofs away from
      // the end of the ordering; CAMD's order is postordered already.
      common.postorder = false;
    }

    ~Cholmod()
    {
      free_factor();
      cholmod_l_finish(&common);
    }

    void
    free_factor()
    {
      if (factor != nullptr)
        cholmod_l_free_factor(&factor, &common);
    }

    /** A view of the caller's arrays (upper triangle read: stype = 1). */
    static cholmod_sparse
    view(const long                 n,
         const std::vector<long>   &column_start,
         const std::vector<long>   &row_index,
         const std::vector<double> &values)
    {
      cholmod_sparse A{};
      A.nrow   = n;
      A.ncol   = n;
      A.nzmax  = values.size();
      A.p      = const_cast<long *>(column_start.data());
      A.i      = const_cast<long *>(row_index.data());
      A.x      = const_cast<double *>(values.data());
      A.stype  = 1;
      A.itype  = CHOLMOD_LONG;
      A.xtype  = CHOLMOD_REAL;
      A.dtype  = CHOLMOD_DOUBLE;
      A.sorted = true;
      A.packed = true;
      return A;
    }
  };



  SchurCholesky::SchurCholesky()
    : cholmod(std::make_unique<Cholmod>())
  {}



  SchurCholesky::~SchurCholesky() = default;



  void
  SchurCholesky::set_last_unknowns(const std::vector<long> &unknowns)
  {
    std::vector<long> sorted = unknowns;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    if (sorted != last_unknowns)
      {
        last_unknowns = sorted;
        analysed      = false;
      }
  }



  bool
  SchurCholesky::factorized() const
  {
    return cholmod->factor != nullptr &&
           cholmod->factor->minor == cholmod->factor->n;
  }



  bool
  SchurCholesky::factorize(const long                 n,
                           const std::vector<long>   &column_start,
                           const std::vector<long>   &row_index,
                           const std::vector<double> &values,
                           const bool                 new_pattern)
  {
    cholmod_sparse A = Cholmod::view(n, column_start, row_index, values);
    Timer          timer;
    if (new_pattern || !analysed || cholmod->factor == nullptr)
      {
        // Constrained AMD: set 0 (the body) first, set 1 (contact) last.
        std::vector<long> constraint_set(n, 0), permutation(n);
        for (const long i : last_unknowns)
          constraint_set[i] = 1;
        double control[CAMD_CONTROL], info[CAMD_INFO];
        camd_l_defaults(control);
        const long status = camd_l_order(n,
                                         column_start.data(),
                                         row_index.data(),
                                         permutation.data(),
                                         control,
                                         info,
                                         constraint_set.data());
        if (status != CAMD_OK && status != CAMD_OK_BUT_JUMBLED)
          throw std::runtime_error("CAMD ordering failed with status " +
                                   std::to_string(status));
        cholmod->free_factor();
        cholmod->factor = cholmod_l_analyze_p(
          &A, permutation.data(), nullptr, 0, &cholmod->common);
        if (cholmod->factor == nullptr)
          throw std::runtime_error("CHOLMOD analysis failed with status " +
                                   std::to_string(cholmod->common.status));

        n_last = last_unknowns.size();
        position.assign(n, -1);
        const long *perm = static_cast<const long *>(cholmod->factor->Perm);
        for (long k = n - n_last; k < n; ++k)
          {
            if (constraint_set[perm[k]] != 1)
              throw std::logic_error(
                "SchurCholesky: the contact unknowns are not last in the "
                "ordering");
            position[perm[k]] = k - (n - n_last);
          }
        analysed = true;
        analysis_seconds += timer.wall_time();
        timer.restart();
      }
    cholmod_l_factorize(&A, cholmod->factor, &cholmod->common);
    factorization_seconds += timer.wall_time();
    forget_inverse_columns();
    return cholmod->common.status == CHOLMOD_OK && factorized();
  }



  void
  SchurCholesky::solve(Vector<double> &x) const
  {
    cholmod_dense b{};
    b.nrow  = x.size();
    b.ncol  = 1;
    b.nzmax = x.size();
    b.d     = x.size();
    b.x     = x.begin();
    b.xtype = CHOLMOD_REAL;
    b.dtype = CHOLMOD_DOUBLE;
    cholmod_dense *solution =
      cholmod_l_solve(CHOLMOD_A, cholmod->factor, &b, &cholmod->common);
    if (solution == nullptr)
      throw std::runtime_error("CHOLMOD solve failed with status " +
                               std::to_string(cholmod->common.status));
    const double *s = static_cast<const double *>(solution->x);
    std::copy(s, s + x.size(), x.begin());
    cholmod_l_free_dense(&solution, &cholmod->common);
  }



  void
  SchurCholesky::take_request(const std::vector<long> &wanted)
  {
    asked_positions = wanted;
  }



  void
  SchurCholesky::form_requested_columns()
  {
    std::vector<double> factor;
    trailing_factor(factor);
    columns_of_inverse(factor, n_last, asked_positions, formed_columns);
  }



  void
  SchurCholesky::hand_over_columns(std::vector<long>   &wanted,
                                   std::vector<double> &columns)
  {
    wanted.swap(asked_positions);
    columns.swap(formed_columns);
    asked_positions.clear();
    std::vector<double>().swap(formed_columns);
  }



  void
  SchurCholesky::trailing_factor(std::vector<double> &trailing) const
  {
    const cholmod_factor &L     = *cholmod->factor;
    const long            n     = L.n;
    const long            first = n - n_last;
    // Copy the trailing block L_cc out of the supernodes that hold it:
    // supernode s has columns super[s] .. super[s+1]-1, rows Ls[pi[s]..],
    // values column major from px[s] with leading dimension = its rows.
    trailing.assign(std::size_t(n_last) * n_last, 0.);
    const long   *super = static_cast<const long *>(L.super);
    const long   *pi    = static_cast<const long *>(L.pi);
    const long   *px    = static_cast<const long *>(L.px);
    const long   *rows  = static_cast<const long *>(L.s);
    const double *x     = static_cast<const double *>(L.x);
    for (std::size_t s = 0; s < L.nsuper; ++s)
      {
        const long k1 = super[s], k2 = super[s + 1];
        if (k2 <= first)
          continue;
        const long n_rows = pi[s + 1] - pi[s];
        for (long k = std::max(k1, first); k < k2; ++k)
          {
            const long column = k - k1;
            for (long i = column; i < n_rows; ++i)
              trailing[(rows[pi[s] + i] - first) + (k - first) * n_last] =
                x[px[s] + i + column * n_rows];
          }
      }
  }
} // namespace glissade

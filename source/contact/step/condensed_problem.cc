#include <glissade/base/processes.h>
#include <glissade/body/body.h>
#include <glissade/contact/step/condensed_problem.h>
#include <glissade/lac/lapack.h>

#include <algorithm>
#include <functional>
#include <map>
#include <tuple>
#include <utility>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** v . u for a vector over the dofs of a pair's bodies. */
    double
    dot(const PairVector &v, const std::vector<Vector<double>> &u)
    {
      double sum = 0.;
      for (const auto &e : *v.coefficients)
        sum += e.value * u[v.bodies[e.body]](e.dof);
      return sum;
    }

    /** u += factor v. */
    void
    add(const PairVector            &v,
        const double                 factor,
        std::vector<Vector<double>> &u)
    {
      for (const auto &e : *v.coefficients)
        u[v.bodies[e.body]](e.dof) += factor * e.value;
    }

    /** An entry of a row or load on one body: local dof index, value. */
    struct LocalEntry
    {
      unsigned int index;
      double       value;
    };

    /**
     * Rows or loads on one body: each that has an entry there, as (its
     * index among all rows or loads, its entries by local dof index).
     */
    using LocalVectors =
      std::vector<std::pair<std::size_t, std::vector<LocalEntry>>>;

    /**
     * What the compliance products of one body need: its dofs that the
     * rows reach and those the loads reach (sorted), the rows and the
     * loads in those local numbers.
     */
    struct BodyProducts
    {
      std::vector<types::global_dof_index> row_dofs, column_dofs;
      LocalVectors                         rows, loads;
    };

    /**
     * The part of `vectors` on body b: its dofs there, sorted, into
     * `dofs`, and the vectors numbered by their position in `dofs`; only
     * the vectors `kept` says.
     */
    void
    restrict_to_body(
      const std::vector<PairVector>          &vectors,
      const unsigned int                      b,
      std::vector<types::global_dof_index>   &dofs,
      LocalVectors                           &local,
      const std::function<bool(std::size_t)> &kept = [](std::size_t) {
        return true;
      })
    {
      std::map<types::global_dof_index, unsigned int> index;
      for (std::size_t i = 0; i < vectors.size(); ++i)
        if (kept(i))
          for (const auto &e : *vectors[i].coefficients)
            if (vectors[i].bodies[e.body] == b)
              index.emplace(e.dof, 0);
      for (auto &[dof, i] : index)
        {
          i = dofs.size();
          dofs.push_back(dof);
        }
      for (std::size_t i = 0; i < vectors.size(); ++i)
        if (kept(i))
          {
            std::vector<LocalEntry> entries;
            for (const auto &e : *vectors[i].coefficients)
              if (vectors[i].bodies[e.body] == b)
                entries.push_back({index[e.dof], e.value});
            if (!entries.empty())
              local.emplace_back(i, std::move(entries));
          }
    }

    // Rows C loads, one of two ways. Dense: the rows and loads as dense
    // matrices, two BLAS products. Sparse: loops over the entries
    // (add_sparse_products). On a B-spline master every row and load
    // reaches some 50 nodes (the interpolation's band): at 160 active nodes
    // the dense way does 3 times the flops and takes 3.5 times less time
    // (W 0.215 s -> 0.061 s on the peers benchmark's rings at 160 x 16), at
    // 800 nodes 16 times the flops and 1.3 times less (3.51 s against
    // 4.44 s per run). On a faceted master a row has 4 entries and the
    // dense way would do a thousand times the work. A BLAS flop costs about
    // a thirtieth of one in the loops: dense when it needs fewer than 30
    // times the flops.
    bool
    dense_is_cheaper(const BodyProducts &body)
    {
      const std::size_t m         = body.row_dofs.size(),
                        m_columns = body.column_dofs.size();
      const std::size_t n_here = body.rows.size(), l_here = body.loads.size();
      double            sparse_flops = 0.;
      for (const auto &[j, load] : body.loads)
        sparse_flops += double(load.size()) * m;
      for (const auto &[i, row] : body.rows)
        sparse_flops += double(row.size()) * l_here;
      const double dense_flops =
        double(m) * m_columns * l_here + double(n_here) * m * l_here;
      return dense_flops < 30. * sparse_flops;
    }

    /**
     * products += rows C loads on one body, by two BLAS products per block
     * of loads: T = C L, then R T by blocks of rows. (In blocks of 512
     * loads and 1,024 rows, so that L, T, R and R T are not whole-size
     * arrays: the peers' rings at 1,600 active nodes peaked at 3.99 GB
     * with them, 3.34 GB without, in the same time.)
     */
    void
    add_dense_products(const BodyProducts        &body,
                       const std::vector<double> &C,
                       ComplianceProducts        &products)
    {
      const std::size_t m         = body.row_dofs.size(),
                        m_columns = body.column_dofs.size();
      const std::size_t n_here = body.rows.size(), l_here = body.loads.size();
      constexpr std::size_t load_block = 512, row_block = 1024;
      const std::size_t     width = std::min(load_block, l_here),
                        height    = std::min(row_block, n_here);
      std::vector<double> L(m_columns * width), T(m * width), R(height * m, 0.),
        RT(height * width);
      const double one = 1., zero = 0.;
      for (std::size_t k0 = 0; k0 < l_here; k0 += load_block)
        {
          const std::size_t loads_here = std::min(load_block, l_here - k0);
          std::fill(L.begin(), L.end(), 0.);
          for (std::size_t k = 0; k < loads_here; ++k)
            for (const auto &e : body.loads[k0 + k].second)
              L[e.index + k * m_columns] += e.value;
          const int im = m, ic = m_columns, il = loads_here;
          dgemm_("N",
                 "N",
                 &im,
                 &il,
                 &ic,
                 &one,
                 C.data(),
                 &im,
                 L.data(),
                 &ic,
                 &zero,
                 T.data(),
                 &im);
          for (std::size_t r0 = 0; r0 < n_here; r0 += row_block)
            {
              const std::size_t rows_here = std::min(row_block, n_here - r0);
              for (std::size_t r = 0; r < rows_here; ++r)
                for (const auto &e : body.rows[r0 + r].second)
                  R[r + std::size_t(e.index) * rows_here] += e.value;
              const int ir = rows_here;
              dgemm_("N",
                     "N",
                     &ir,
                     &il,
                     &im,
                     &one,
                     R.data(),
                     &ir,
                     T.data(),
                     &im,
                     &zero,
                     RT.data(),
                     &ir);
              for (std::size_t k = 0; k < loads_here; ++k)
                {
                  double *column = products.column(body.loads[k0 + k].first);
                  for (std::size_t r = 0; r < rows_here; ++r)
                    column[body.rows[r0 + r].first] += RT[r + k * rows_here];
                }
              // (R back to zeros, entry by entry: the rows are sparse)
              for (std::size_t r = 0; r < rows_here; ++r)
                for (const auto &e : body.rows[r0 + r].second)
                  R[r + std::size_t(e.index) * rows_here] = 0.;
            }
        }
    }



    /**
     * products += rows C loads on one body, by loops over the entries. T =
     * C L column by column (each load's entries: axpys down the columns of
     * C), turned over so that a row of T is contiguous, then each row of the
     * products = sum_e r_e T(e, :) (axpys along the rows of T). Every inner
     * loop runs over contiguous memory; gathering T(e) for each row and load
     * instead took 1.6 times as long (the rings at 800 x 80, B-spline
     * master). The loads go in blocks, so that T costs 2 m x 256 doubles,
     * not m x loads.
     */
    void
    add_sparse_products(const BodyProducts        &body,
                        const std::vector<double> &C,
                        ComplianceProducts        &products)
    {
      const std::size_t m = body.row_dofs.size(), l_here = body.loads.size();
      constexpr std::size_t block = 256;
      std::vector<double>   T(m * block), T_rows(m * block), row_product(block);
      std::vector<double *> columns(block);
      for (std::size_t k0 = 0; k0 < l_here; k0 += block)
        {
          const std::size_t width = std::min(block, l_here - k0);
          std::fill(T.begin(), T.end(), 0.);
          for (std::size_t k = 0; k < width; ++k)
            columns[k] = products.column(body.loads[k0 + k].first);
          for (std::size_t k = 0; k < width; ++k)
            {
              double *t = &T[k * m];
              for (const auto &e : body.loads[k0 + k].second)
                {
                  const double *column = &C[std::size_t(e.index) * m];
                  for (std::size_t r = 0; r < m; ++r)
                    t[r] += e.value * column[r];
                }
            }
          constexpr std::size_t tile = 64;
          for (std::size_t r0 = 0; r0 < m; r0 += tile)
            for (std::size_t k1 = 0; k1 < width; k1 += tile)
              for (std::size_t r = r0; r < std::min(m, r0 + tile); ++r)
                for (std::size_t k = k1; k < std::min(width, k1 + tile); ++k)
                  T_rows[r * width + k] = T[k * m + r];
          for (const auto &[i, row] : body.rows)
            {
              std::fill(row_product.begin(), row_product.begin() + width, 0.);
              for (const auto &e : row)
                {
                  const double *t = &T_rows[std::size_t(e.index) * width];
                  for (std::size_t k = 0; k < width; ++k)
                    row_product[k] += e.value * t[k];
                }
              for (std::size_t k = 0; k < width; ++k)
                columns[k][i] += row_product[k];
            }
        }
    }
  } // namespace



  ComplianceProducts::ComplianceProducts(const std::size_t n_rows,
                                         const std::size_t n_forces,
                                         const std::size_t n_terms)
    : n_rows(n_rows)
    , n_forces(n_forces)
    , n_terms(n_terms)
  {
    std::tie(first_force, end_force) = processes::share(n_forces);
    std::tie(first_term, end_term)   = processes::share(n_terms);
  }



  void
  ComplianceProducts::allocate()
  {
    force_columns.assign(n_rows * (end_force - first_force), 0.);
    term_columns.assign(n_rows * n_terms, 0.);
  }



  CondensedProblem::CondensedProblem(
    const ActiveNodes                        &nodes,
    const Augmentation                       &augmentation,
    const std::vector<std::unique_ptr<Body>> &bodies,
    const std::vector<Vector<double>>        &predictor)
    : nodes(nodes)
    , bodies(bodies)
    , n(nodes.size())
    , n_given(nodes.terms.size())
  {
    // Rows: R (2n), then V (one per term); loads: F (2n), then U, the
    // augmented directions last (add_augmented_terms()).
    std::vector<PairVector> all_rows(nodes.rows);
    std::vector<PairVector> all_loads(nodes.forces);
    for (const auto &term : nodes.terms)
      {
        all_rows.push_back(term.row);
        all_loads.push_back(term.load);
      }
    add_augmented_terms(augmentation, all_rows, all_loads);
    const std::size_t  n_rows = all_rows.size();
    ComplianceProducts P(n_rows, 2 * n, all_loads.size() - 2 * n);
    add_compliance_products(all_rows, all_loads, P);
    const std::vector<double> rows_of_a =
      scale_augmented_loads(augmentation.factor, P);

    // Every row applied to d = du_lib + K^-1 a.
    std::vector<double> row_of_d(n_rows);
    for (std::size_t i = 0; i < n_rows; ++i)
      row_of_d[i] = dot(all_rows[i], predictor) + rows_of_a[i];

    is_regular = solve_woodbury_system(P, row_of_d);
    if (!is_regular)
      return;
    form_free_displacement(P, row_of_d);
    form_compliance(P);
  }



  void
  CondensedProblem::add_augmented_terms(const Augmentation      &augmentation,
                                        std::vector<PairVector> &all_rows,
                                        std::vector<PairVector> &all_loads)
  {
    // An augmented direction is a term whose row is the direction's row
    // and whose load is the same row times -E_k (scaled in
    // scale_augmented_loads(), once E_k is known from the products).
    for (unsigned int k = 0; k < augmentation.directions.size(); ++k)
      for (unsigned int c = 0; c < 2; ++c)
        if (augmentation.directions[k][c])
          {
            augmented_row.push_back(2 * k + c);
            augmented_gap.push_back(nodes.initial[k][c]);
            all_rows.push_back(nodes.rows[2 * k + c]);
            all_loads.push_back(nodes.rows[2 * k + c]);
          }
  }



  std::vector<double>
  CondensedProblem::scale_augmented_loads(const double        factor,
                                          ComplianceProducts &P)
  {
    const std::size_t size = 2 * n;

    // E_k = factor / (node k's normal compliance through its bodies alone),
    // a scale at which S stays well conditioned: R C F's diagonal, each
    // entry from the process that holds its column.
    std::vector<double> diagonal(size, 0.);
    for (std::size_t j = P.first_force; j < P.end_force; ++j)
      diagonal[j] = P.column(j)[j];
    processes::gather_columns(diagonal.data(), 1, size);
    std::vector<double> stiffness(n, 0.);
    double              largest = 0.;
    for (unsigned int k = 0; k < n; ++k)
      {
        const double w = diagonal[2 * k + 1];
        stiffness[k]   = w > 0. ? factor / w : 0.;
        largest        = std::max(largest, stiffness[k]);
      }
    std::vector<double> rows_of_a(P.n_rows, 0.);
    for (unsigned int j = 0; j < augmented_row.size(); ++j)
      {
        const unsigned int k = augmented_row[j] / 2;
        augmented_scale.push_back(
          -(stiffness[k] > 0. ? stiffness[k] : largest));
        double *column = P.column(size + n_given + j);
        for (std::size_t i = 0; i < P.n_rows; ++i)
          {
            column[i] *= augmented_scale[j];
            rows_of_a[i] += column[i] * augmented_gap[j];
          }
      }
    return rows_of_a;
  }



  bool
  CondensedProblem::solve_woodbury_system(ComplianceProducts        &P,
                                          const std::vector<double> &row_of_d)
  {
    const int size = 2 * n, t = n_given + augmented_row.size(), ld = P.n_rows;
    first_force       = P.first_force;
    end_force         = P.end_force;
    const int columns = end_force - first_force;

    // S = I - V C U, in place of V C U (the rows of V in U's columns); X =
    // S^-1 V C F on this process's columns of F; y = S^-1 V d.
    y.assign(row_of_d.begin() + size, row_of_d.end());
    X.assign(std::size_t(t) * columns, 0.);
    if (t == 0)
      return true;
    double *S = &P.term_columns[size];
    for (int j = 0; j < t; ++j)
      for (int i = 0; i < t; ++i)
        S[i + std::size_t(j) * ld] =
          (i == j ? 1. : 0.) - S[i + std::size_t(j) * ld];

    std::vector<int>    pivots(t);
    int                 info = 0;
    std::vector<double> work(4 * t);
    std::vector<int>    iwork(t);
    const double        norm = dlange_("1", &t, &t, S, &ld, work.data());
    dgetrf_(&t, &t, S, &ld, pivots.data(), &info);
    // Singular in floating point too: a body that relies on contact with
    // its springs taken out and the contact not holding it leaves S
    // singular up to round-off, not exactly. Its conditioning (rcond) does
    // not see it where the singular direction is all of S: a single
    // spring's S = 1 - k e^T C e, zero but for round-off, is a 1 x 1
    // matrix of rcond 1. Its smallest singular value, about rcond ||S||,
    // against the identity's 1 does (a ring held in y by two plates alone:
    // its translation was left to round-off, ctest
    // held_by_contact_ring_between_two_plates).
    double rcond = 0.;
    if (info == 0)
      dgecon_("1", &t, S, &ld, &norm, &rcond, work.data(), iwork.data(), &info);
    if (!(info == 0 && rcond > 1e-13 && rcond * norm > 1e-10))
      return false;
    // (S's LU is replicated; X's columns stay with the process that formed
    // them)
    for (int c = 0; c < columns; ++c)
      std::copy_n(&P.force_columns[std::size_t(c) * ld + size],
                  t,
                  &X[std::size_t(c) * t]);
    const int one = 1;
    if (columns > 0)
      dgetrs_("N", &t, &columns, S, &ld, pivots.data(), X.data(), &t, &info);
    dgetrs_("N", &t, &one, S, &ld, pivots.data(), y.data(), &t, &info);
    return true;
  }



  void
  CondensedProblem::form_compliance(ComplianceProducts &P)
  {
    // W = R C F + (R C U) X; BLAS: the product is the dense part of the
    // contact tangent's cost. Each process forms the columns of its share
    // of F, in place of its columns of R C F; U's columns are released
    // before W's dense array is made, F's before W is gathered.
    const int size = 2 * n, t = n_given + augmented_row.size(), ld = P.n_rows,
              columns = end_force - first_force;
    if (t > 0 && columns > 0)
      {
        const double one = 1.;
        dgemm_("N",
               "N",
               &size,
               &columns,
               &t,
               &one,
               P.term_columns.data(),
               &ld,
               X.data(),
               &t,
               &one,
               P.force_columns.data(),
               &ld);
      }
    std::vector<double>().swap(P.term_columns);
    std::vector<double> W_dense(std::size_t(size) * size);
    for (int c = 0; c < columns; ++c)
      std::copy_n(&P.force_columns[std::size_t(c) * ld],
                  size,
                  &W_dense[(first_force + c) * size]);
    std::vector<double>().swap(P.force_columns);
    processes::gather_columns(W_dense.data(), size, size);
    // (W_dense is in the layout of W's dense storage: taken over, not
    // copied)
    W.reinit(n, std::move(W_dense));
  }



  void
  CondensedProblem::form_free_displacement(const ComplianceProducts  &P,
                                           const std::vector<double> &row_of_d)
  {
    // u_free = u_0 + R d + (R C U) y.
    const int size = 2 * n, t = n_given + augmented_row.size();
    u_free = nodes.initial;
    for (int i = 0; i < size; ++i)
      {
        double value = row_of_d[i];
        for (int k = 0; k < t; ++k)
          value += P.term_columns[i + std::size_t(k) * P.n_rows] * y[k];
        u_free[i / 2][i % 2] += value;
      }
  }



  bool
  CondensedProblem::positive_definite_on(
    const std::vector<std::array<bool, 2>> &directions) const
  {
    std::vector<std::pair<unsigned int, unsigned int>> index;
    for (unsigned int k = 0; k < directions.size(); ++k)
      for (unsigned int c = 0; c < 2; ++c)
        if (directions[k][c])
          index.emplace_back(k, c);
    const int m = index.size();
    if (m == 0)
      return true;
    std::vector<double> A(std::size_t(m) * m);
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        {
          const auto [k, a] = index[i];
          const auto [l, c] = index[j];
          A[i + std::size_t(j) * m] =
            0.5 * (W.block(k, l)[a][c] + W.block(l, k)[c][a]);
        }
    int info = 0;
    dpotrf_("L", &m, A.data(), &m, &info);
    return info == 0;
  }



  void
  CondensedProblem::add_compliance_products(
    const std::vector<PairVector> &all_rows,
    const std::vector<PairVector> &all_loads,
    ComplianceProducts            &products) const
  {
    // Each entry is formed by one process, with the arithmetic one process
    // alone does; the columns of U are then sent to all, those of F stay
    // where they were formed. A process asks its bodies only for the
    // columns of C its loads reach (on several processes, its share).
    const auto formed_here = [&](const std::size_t j) {
      return products.formed_here(j);
    };
    std::vector<BodyProducts> per_body(bodies.size());
    std::vector<bool>         dense(bodies.size(), false);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        BodyProducts &body = per_body[b];
        restrict_to_body(all_rows, b, body.row_dofs, body.rows);
        restrict_to_body(all_loads, b, body.column_dofs, body.loads);
        if (body.row_dofs.empty() || body.column_dofs.empty())
          {
            body = BodyProducts();
            continue;
          }
        // (the way is chosen from all the loads: every process chooses
        // alike)
        dense[b] = dense_is_cheaper(body);
        if (!products.forms_every_column())
          {
            body.column_dofs.clear();
            body.loads.clear();
            restrict_to_body(
              all_loads, b, body.column_dofs, body.loads, formed_here);
          }
      }

    // C's columns formed for every body first, and only then read and the
    // products made: forming them passes through the whole inverse block,
    // which then never sits beside the products (82 MB at 3,200 contact
    // dofs). On several processes each body's factorisation has its host
    // form every process's columns: all bodies' asked for first, so that
    // the hosts of different bodies form theirs at once, then received.
    // (Collective on several processes: called by each, even one whose
    // loads do not reach the body.)
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!per_body[b].row_dofs.empty())
        bodies[b]->system().ask_for_compliance(per_body[b].row_dofs,
                                               per_body[b].column_dofs);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!per_body[b].row_dofs.empty())
        bodies[b]->system().form_asked_compliance();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!per_body[b].row_dofs.empty())
        bodies[b]->system().prepare_compliance(per_body[b].row_dofs,
                                               per_body[b].column_dofs);
    products.allocate();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const BodyProducts &body = per_body[b];
        if (body.row_dofs.empty())
          continue;
        std::vector<double> C;
        bodies[b]->system().compliance_block(body.row_dofs,
                                             body.column_dofs,
                                             C);
        if (body.loads.empty())
          continue;
        if (dense[b])
          add_dense_products(body, C, products);
        else
          add_sparse_products(body, C, products);
      }
    processes::gather_columns(products.term_columns.data(),
                              products.n_rows,
                              products.n_terms);
  }



  void
  CondensedProblem::correct(const std::vector<Vector2>  &r,
                            std::vector<Vector<double>> &increments,
                            std::vector<Vector<double>> &contact_forces) const
  {
    // z = y + X r, each process's columns of X on its share of r, summed
    // over the processes.
    const int           t = n_given + augmented_row.size();
    std::vector<double> z(t, 0.);
    if (processes::adds_terms_held_once())
      z = y;
    for (std::size_t j = first_force; j < end_force; ++j)
      if (const double r_j = r[j / 2][j % 2]; r_j != 0.)
        for (int i = 0; i < t; ++i)
          z[i] += X[i + (j - first_force) * t] * r_j;
    processes::sum(z);

    // The loads F r + U z (+ the augmentation's right-hand side) on each
    // body, and one solve per body.
    std::vector<Vector<double>> loads(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        contact_forces[b].reinit(bodies[b]->n_dofs());
        loads[b].reinit(bodies[b]->n_dofs());
      }
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int c = 0; c < 2; ++c)
        add(nodes.forces[2 * k + c], r[k][c], contact_forces);
    for (unsigned int i = 0; i < n_given; ++i)
      add(nodes.terms[i].load, z[i], loads);
    for (unsigned int j = 0; j < augmented_row.size(); ++j)
      add(nodes.rows[augmented_row[j]],
          augmented_scale[j] * (z[n_given + j] + augmented_gap[j]),
          loads);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        loads[b] += contact_forces[b];
        if (loads[b].linfty_norm() > 0.)
          {
            Vector<double> correction;
            bodies[b]->system().solve_homogeneous(loads[b], correction);
            increments[b] += correction;
          }
      }
  }
} // namespace glissade

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/full_matrix.h>

#include <glissade/fe/fe_values_evaluator.h>
#include <glissade/fe/serendipity_space.h>

#include <cmath>
#include <stdexcept>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** Coefficient of x^power in the 1D Lagrange polynomial l_j on j/p. */
    double
    monomial_coefficient(const unsigned int degree,
                         const unsigned int j,
                         const unsigned int power)
    {
      // Expand prod_{m != j} (x - x_m) / (x_j - x_m) as a polynomial.
      std::vector<double> poly        = {1.};
      double              denominator = 1.;
      for (unsigned int m = 0; m <= degree; ++m)
        if (m != j)
          {
            const double        xm = double(m) / degree;
            std::vector<double> next(poly.size() + 1, 0.);
            for (unsigned int k = 0; k < poly.size(); ++k)
              {
                next[k + 1] += poly[k];
                next[k] -= xm * poly[k];
              }
            poly = next;
            denominator *= double(j) / degree - xm;
          }
      return power < poly.size() ? poly[power] / denominator : 0.;
    }
  } // namespace



  SerendipitySpace::SerendipitySpace(const unsigned int degree)
    : degree(degree)
    // Equidistant nodes (deal.II's FE_Q defaults to Gauss-Lobatto points
    // from degree 3 on): the classical Q12 has its edge nodes at thirds.
    , fe(FE_Q<2>(QIterated<1>(QTrapezoid<1>(), degree)), 2)
  {
    if (degree != 2 && degree != 3)
      throw std::invalid_argument("serendipity elements of degree 2 or 3");

    // Which 1D node each base dof sits on, from FE_Q's support points.
    const FiniteElement<2>   &base    = fe.base_element(0);
    const auto               &support = base.get_unit_support_points();
    const unsigned int        n       = base.n_dofs_per_cell();
    std::vector<unsigned int> ix(n), iy(n);
    std::vector<unsigned int> interior, boundary;
    for (unsigned int i = 0; i < n; ++i)
      {
        ix[i] = static_cast<unsigned int>(std::round(support[i][0] * degree));
        iy[i] = static_cast<unsigned int>(std::round(support[i][1] * degree));
        const bool inside =
          ix[i] > 0 && ix[i] < degree && iy[i] > 0 && iy[i] < degree;
        (inside ? interior : boundary).push_back(i);
      }

    // The excluded monomials x^a y^b: both powers >= 2 (and <= p).
    std::vector<std::pair<unsigned int, unsigned int>> excluded;
    for (unsigned int a = 2; a <= degree; ++a)
      for (unsigned int b = 2; b <= degree; ++b)
        excluded.emplace_back(a, b);
    AssertThrow(excluded.size() == interior.size(), ExcInternalError());

    // Coefficient of x^a y^b in the Q_p interpolant is
    // sum_i L_ix^(a) L_iy^(b) u_i; setting it to zero for every excluded
    // monomial gives M u_interior = -B u_boundary.
    const unsigned int m = interior.size();
    FullMatrix<double> M(m, m), B(m, boundary.size());
    for (unsigned int r = 0; r < m; ++r)
      {
        const auto [a, b] = excluded[r];
        const auto c      = [&](const unsigned int i) {
          return monomial_coefficient(degree, ix[i], a) *
                 monomial_coefficient(degree, iy[i], b);
        };
        for (unsigned int k = 0; k < m; ++k)
          M(r, k) = c(interior[k]);
        for (unsigned int k = 0; k < boundary.size(); ++k)
          B(r, k) = c(boundary[k]);
      }
    FullMatrix<double> M_inverse(m, m);
    M_inverse.invert(M);
    relations.resize(n);
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int j = 0; j < boundary.size(); ++j)
        {
          double coefficient = 0.;
          for (unsigned int r = 0; r < m; ++r)
            coefficient -= M_inverse(k, r) * B(r, j);
          if (std::abs(coefficient) > 1e-14)
            relations[interior[k]].emplace_back(boundary[j], coefficient);
        }
  }



  std::string
  SerendipitySpace::name() const
  {
    return degree == 2 ? "q8" : "q12";
  }



  void
  SerendipitySpace::setup(const DoFHandler<2>       &dof_handler,
                          AffineConstraints<double> &element_constraints)
  {
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int c = 0; c < 2; ++c)
          for (unsigned int i = 0; i < relations.size(); ++i)
            if (!relations[i].empty())
              {
                const auto dof = local[fe.component_to_system_index(c, i)];
                element_constraints.add_line(dof);
                for (const auto &[j, coefficient] : relations[i])
                  element_constraints.add_entry(
                    dof,
                    local[fe.component_to_system_index(c, j)],
                    coefficient);
              }
      }
    element_constraints.close();

    // Node positions from the manifold (MappingQ(p) places its support
    // points there), interiors then moved by the serendipity relations.
    std::vector<Point<2>> support(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(MappingQ<2>(degree),
                                         dof_handler,
                                         support);
    euler_vector.reinit(dof_handler.n_dofs());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c   = fe.system_to_component_index(i).first;
            euler_vector[local[i]] = support[local[i]][c];
          }
      }
    element_constraints.distribute(euler_vector);
    geometry =
      std::make_unique<MappingFEField<2, 2, Vector<double>>>(dof_handler,
                                                             euler_vector);
  }



  void
  SerendipitySpace::attach(const DoFHandler<2> &distributed)
  {
    geometry =
      std::make_unique<MappingFEField<2, 2, Vector<double>>>(distributed,
                                                             euler_vector);
  }



  const Mapping<2> &
  SerendipitySpace::mapping() const
  {
    AssertThrow(geometry, ExcMessage("SerendipitySpace::setup() not called"));
    return *geometry;
  }



  std::unique_ptr<CellEvaluator>
  SerendipitySpace::create_evaluator(
    const unsigned int points_per_direction) const
  {
    const unsigned int n =
      points_per_direction > 0 ? points_per_direction : degree + 1;
    return std::make_unique<FEValuesEvaluator>(mapping(),
                                               fe,
                                               QGauss<2>(n),
                                               QGauss<1>(n));
  }
} // namespace glissade

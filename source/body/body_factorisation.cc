#include <glissade/base/input_error.h>
#include <glissade/body/body.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

// A body's factorisation and its contact port: the factorisation of its
// tangent (with the springs of a body held by contact), its solves, the
// contact dofs it eliminates last, and the block of its inverse on them
// that the condensed contact step reads (Body::compliance_block).

namespace glissade
{
  using namespace dealii;

  void
  Body::factorize()
  {
    // The springs of a body held by contact: as stiff as an average dof,
    // so that they neither dominate nor vanish in the factorisation.
    std::vector<double> assembled(springs.size());
    if (!springs.empty())
      {
        double sum = 0.;
        for (types::global_dof_index i = 0; i < n_dofs(); ++i)
          sum += std::abs(tangent.diag_element(i));
        const double k = sum / n_dofs();
        for (unsigned int s = 0; s < springs.size(); ++s)
          {
            double &diagonal  = tangent.diag_element(springs[s].first);
            assembled[s]      = diagonal;
            springs[s].second = k;
            diagonal += k;
          }
      }
    const bool refactored = factorization.factorize(tangent);
    for (unsigned int s = 0; s < springs.size(); ++s)
      tangent.diag_element(springs[s].first) = assembled[s];
    // The compliance of a previous factorisation is stale.
    if (refactored)
      {
        contact_rows_resolved.clear();
        compliance_columns.clear();
      }
  }



  void
  Body::solve(const Vector<double> &rhs, Vector<double> &increment) const
  {
    increment = rhs;
    factorization.solve(increment);
    constraints.distribute(increment);
  }



  bool
  Body::tangent_is_symmetric() const
  {
    // Follower pressure makes the tangent unsymmetric: LU, not Cholesky.
    for (const auto &load : boundary_conditions->surface_loads())
      if (load.is_pressure)
        return false;
    return true;
  }



  void
  Body::set_contact_dofs(
    const std::vector<types::global_dof_index> &contact_dofs)
  {
    contact_position.assign(n_dofs(), -1);
    contact_rows.clear();
    std::vector<long> unknowns;
    for (const auto dof : contact_dofs)
      {
        if (contact_position[dof] >= 0)
          continue;
        contact_position[dof] = contact_rows.size();
        std::vector<std::pair<long, double>> row;
        if (const auto *line = constraints.get_constraint_entries(dof))
          for (const auto &[j, w] : *line)
            row.emplace_back(j, w);
        else if (!constraints.is_constrained(dof))
          row.emplace_back(dof, 1.);
        // (a fixed dof has an empty row: it never moves)
        for (const auto &[j, w] : row)
          unknowns.push_back(j);
        contact_rows.push_back(row);
      }
    factorization.use_cholesky(tangent_is_symmetric(), unknowns);
    contact_rows_resolved.clear();
    if (!free_motions.empty())
      choose_spring_dofs(contact_dofs);
  }



  void
  Body::choose_spring_dofs(
    const std::vector<types::global_dof_index> &contact_dofs)
  {
    // The candidates: unconstrained nodal values among the contact dofs,
    // each with the values that the free motions take there.
    std::map<types::global_dof_index, std::vector<double>> candidates;
    for (const auto dof : contact_dofs)
      if (!constraints.is_constrained(dof))
        candidates.emplace(dof, std::vector<double>());
    for (const auto &cell : dofs.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const auto vertex_dofs =
            BoundaryConditions::cell_vertex_dofs(cell, v, *element_space);
          for (unsigned int c = 0; c < 2; ++c)
            {
              const auto found = candidates.find(vertex_dofs[c]);
              if (found != candidates.end() && found->second.empty())
                for (const auto &motion : free_motions)
                  found->second.push_back(motion.at(cell->vertex(v))[c]);
            }
        }

    // Pivoted Gram-Schmidt: each time the candidate that moves most under
    // the free motions not yet held.
    springs.clear();
    std::vector<std::vector<double>> held;
    for (unsigned int step = 0; step < free_motions.size(); ++step)
      {
        double                  best   = 0.;
        types::global_dof_index chosen = 0;
        std::vector<double>     direction;
        for (const auto &[dof, values] : candidates)
          {
            if (values.empty())
              continue;
            std::vector<double> rest = values;
            for (const auto &q : held)
              {
                double projection = 0.;
                for (unsigned int j = 0; j < q.size(); ++j)
                  projection += q[j] * values[j];
                for (unsigned int j = 0; j < q.size(); ++j)
                  rest[j] -= projection * q[j];
              }
            double norm = 0.;
            for (const double r : rest)
              norm += r * r;
            norm = std::sqrt(norm);
            if (norm > best)
              {
                best      = norm;
                chosen    = dof;
                direction = rest;
              }
          }
        // The motions are scaled to move the body by about 1.
        if (best < 1e-3)
          throw InputError(source + ": Body " + name() + "/Boundary conditions",
                           "body '" + name() + "' relies on contact to hold " +
                             free_motions[step].describe(reference_size) +
                             ", but none of its contact nodes moves with it");
        for (double &d : direction)
          d /= best;
        held.push_back(direction);
        springs.emplace_back(chosen, 0.);
      }
  }



  bool
  Body::dof_is_prescribed(const types::global_dof_index dof) const
  {
    if (!constraints.is_constrained(dof))
      return false;
    const auto *line = constraints.get_constraint_entries(dof);
    return line == nullptr || line->empty();
  }



  void
  Body::compliance_block(const std::vector<types::global_dof_index> &rows,
                         const std::vector<types::global_dof_index> &columns,
                         std::vector<double>                        &block)
  {
    const std::size_t n_rows = rows.size();
    block.assign(n_rows * columns.size(), 0.);

    // From the Cholesky factor: every dof must be a declared contact dof.
    bool from_factor =
      !contact_rows.empty() && factorization.has_inverse_block();
    for (const auto dof : rows)
      from_factor = from_factor && contact_position[dof] >= 0;
    for (const auto dof : columns)
      from_factor = from_factor && contact_position[dof] >= 0;
    if (from_factor)
      {
        SchurCholesky &cholesky = factorization.cholesky();
        if (contact_rows_resolved.empty())
          {
            contact_rows_resolved = contact_rows;
            for (auto &row : contact_rows_resolved)
              for (auto &[j, w] : row)
                j = cholesky.last_position(j);
          }
        std::vector<long> wanted;
        for (const auto dof : columns)
          for (const auto &[j, w] :
               contact_rows_resolved[contact_position[dof]])
            wanted.push_back(j);
        cholesky.compute_inverse_columns(wanted);
        for (std::size_t c = 0; c < columns.size(); ++c)
          {
            const auto &column =
              contact_rows_resolved[contact_position[columns[c]]];
            for (std::size_t r = 0; r < n_rows; ++r)
              {
                double value = 0.;
                for (const auto &[i, wi] :
                     contact_rows_resolved[contact_position[rows[r]]])
                  for (const auto &[j, wj] : column)
                    value += wi * wj * cholesky.inverse_entry(i, j);
                block[r + c * n_rows] = value;
              }
          }
        return;
      }

    // One back-substitution per column, kept for this factorisation.
    for (std::size_t c = 0; c < columns.size(); ++c)
      {
        auto found = compliance_columns.find(columns[c]);
        if (found == compliance_columns.end())
          {
            Vector<double> unit(n_dofs());
            unit(columns[c]) = 1.;
            found =
              compliance_columns.emplace(columns[c], Vector<double>()).first;
            solve_homogeneous(unit, found->second);
          }
        for (std::size_t r = 0; r < n_rows; ++r)
          block[r + c * n_rows] = found->second(rows[r]);
      }
  }



  void
  Body::solve_homogeneous(const Vector<double> &force, Vector<double> &x) const
  {
    x = force;
    constraints.condense(x);
    for (const auto &line : constraints.get_lines())
      x(line.index) = 0.;
    factorization.solve(x);
    for (const auto &line : constraints.get_lines())
      {
        double value = 0.;
        for (const auto &[j, w] : line.entries)
          value += w * x(j);
        x(line.index) = value;
      }
  }
} // namespace glissade

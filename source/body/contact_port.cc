// Where contact reads a body's linear system: its contact dofs and the
// compliance between them (include/glissade/body/contact_port.h).

#include <glissade/base/processes.h>
#include <glissade/body/contact_port.h>

namespace glissade
{
  using namespace dealii;

  ContactPort::ContactPort(const types::global_dof_index n_dofs)
    : n_dofs(n_dofs)
  {}



  std::vector<long>
  ContactPort::declare(const std::vector<types::global_dof_index> &contact_dofs,
                       const AffineConstraints<double>            &constraints)
  {
    contact_position.assign(n_dofs, -1);
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
    contact_rows_resolved.clear();
    return unknowns;
  }



  bool
  ContactPort::reads_factor(const std::vector<types::global_dof_index> &rows,
                            const std::vector<types::global_dof_index> &columns,
                            const DirectSolver &factorization) const
  {
    // From the Cholesky factor: every dof must be a declared contact dof.
    bool from_factor =
      !contact_rows.empty() && factorization.has_inverse_block();
    for (const auto dof : rows)
      from_factor = from_factor && contact_position[dof] >= 0;
    for (const auto dof : columns)
      from_factor = from_factor && contact_position[dof] >= 0;
    // (on several processes each may ask for other columns, and both ways
    // are collective there: the way is the same on all of them)
    return processes::maximum(from_factor ? 0 : 1) == 0;
  }



  void
  ContactPort::prepare_compliance(
    const std::vector<types::global_dof_index> &rows,
    const std::vector<types::global_dof_index> &columns,
    DirectSolver                               &factorization,
    const HomogeneousSolve                     &solve)
  {
    if (reads_factor(rows, columns, factorization))
      {
        factorization.inverse_block().compute_inverse_columns(
          factor_positions(columns, factorization.inverse_block()));
        return;
      }
    // One back-substitution per column, kept for this factorisation. (A
    // solve is collective on several processes: each makes those of the
    // columns that any of them lacks, in the same order.)
    std::vector<unsigned long> lacking;
    for (const auto dof : columns)
      if (compliance_columns.find(dof) == compliance_columns.end())
        lacking.push_back(dof);
    for (const auto dof : processes::union_of(lacking))
      {
        Vector<double> unit(n_dofs);
        unit(dof) = 1.;
        solve(unit, compliance_columns[dof]);
      }
  }



  void
  ContactPort::compliance_block(
    const std::vector<types::global_dof_index> &rows,
    const std::vector<types::global_dof_index> &columns,
    DirectSolver                               &factorization,
    const HomogeneousSolve                     &solve,
    std::vector<double>                        &block)
  {
    prepare_compliance(rows, columns, factorization, solve);
    const std::size_t n_rows = rows.size();
    block.assign(n_rows * columns.size(), 0.);
    if (reads_factor(rows, columns, factorization))
      {
        block_from_factor(rows, columns, factorization.inverse_block(), block);
        return;
      }
    for (std::size_t c = 0; c < columns.size(); ++c)
      {
        const Vector<double> &column = compliance_columns.at(columns[c]);
        for (std::size_t r = 0; r < n_rows; ++r)
          block[r + c * n_rows] = column(rows[r]);
      }
  }



  std::vector<long>
  ContactPort::factor_positions(
    const std::vector<types::global_dof_index> &columns,
    const TrailingBlockInverse                 &cholesky)
  {
    if (contact_rows_resolved.empty())
      {
        contact_rows_resolved = contact_rows;
        for (auto &row : contact_rows_resolved)
          for (auto &[j, w] : row)
            j = cholesky.last_position(j);
      }
    std::vector<long> wanted;
    for (const auto dof : columns)
      for (const auto &[j, w] : contact_rows_resolved[contact_position[dof]])
        wanted.push_back(j);
    return wanted;
  }



  void
  ContactPort::block_from_factor(
    const std::vector<types::global_dof_index> &rows,
    const std::vector<types::global_dof_index> &columns,
    const TrailingBlockInverse                 &cholesky,
    std::vector<double>                        &block)
  {
    // (the columns were formed by prepare_compliance())
    const std::size_t n_rows = rows.size();
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
  }
} // namespace glissade

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
  ContactPort::reads_factor(const DirectSolver &factorization) const
  {
    // (on several processes both ways are collective: the way is the same
    // on all of them)
    const bool from_factor =
      !contact_rows.empty() && factorization.has_inverse_block();
    return processes::maximum(from_factor ? 0 : 1) == 0;
  }



  void
  ContactPort::ask_for_compliance(
    const std::vector<types::global_dof_index> &rows,
    const std::vector<types::global_dof_index> &columns,
    DirectSolver                               &factorization)
  {
    // The declared contact dofs' entries from the factor; a dof that was
    // not declared (a node activated or slid onto another segment since
    // the factorisation chose its last unknowns) by one back-substitution,
    // its column, which by symmetry is also its row. Only those dofs pay
    // a solve: at 390,000 dofs, 4 undeclared dofs among 546 made every
    // column a solve (156 s for W; 0.76 s so).
    lacking_columns.clear();
    const auto ask = [&](const types::global_dof_index dof) {
      if (compliance_columns.find(dof) == compliance_columns.end())
        lacking_columns.push_back(dof);
    };
    asked_of_factor = reads_factor(factorization);
    if (asked_of_factor)
      {
        std::vector<types::global_dof_index> declared_columns;
        for (const auto dof : columns)
          if (declared(dof))
            declared_columns.push_back(dof);
          else
            ask(dof);
        for (const auto dof : rows)
          if (!declared(dof))
            ask(dof);
        factorization.inverse_block().ask_for_inverse_columns(
          factor_positions(declared_columns, factorization.inverse_block()));
      }
    else
      for (const auto dof : columns)
        ask(dof);
    compliance_asked = true;
  }



  void
  ContactPort::form_asked_compliance(DirectSolver &factorization)
  {
    if (compliance_asked && asked_of_factor)
      factorization.inverse_block().form_asked_inverse_columns();
  }



  void
  ContactPort::prepare_compliance(
    const std::vector<types::global_dof_index> &rows,
    const std::vector<types::global_dof_index> &columns,
    DirectSolver                               &factorization,
    const HomogeneousSolve                     &solve)
  {
    if (!compliance_asked)
      {
        ask_for_compliance(rows, columns, factorization);
        form_asked_compliance(factorization);
      }
    compliance_asked = false;
    if (asked_of_factor)
      factorization.inverse_block().receive_inverse_columns();
    // (A solve is collective on several processes: each makes those of the
    // columns that any of them lacks, in the same order.)
    for (const auto dof : processes::union_of(lacking_columns))
      {
        Vector<double> unit(n_dofs);
        unit(dof) = 1.;
        solve(unit, compliance_columns[dof]);
      }
    lacking_columns.clear();
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
    const bool from_factor = reads_factor(factorization);
    for (std::size_t c = 0; c < columns.size(); ++c)
      for (std::size_t r = 0; r < n_rows; ++r)
        if (from_factor && declared(rows[r]) && declared(columns[c]))
          block[r + c * n_rows] =
            entry_from_factor(rows[r],
                              columns[c],
                              factorization.inverse_block());
        else if (!from_factor || !declared(columns[c]))
          block[r + c * n_rows] = compliance_columns.at(columns[c])(rows[r]);
        else
          block[r + c * n_rows] = compliance_columns.at(rows[r])(columns[c]);
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



  double
  ContactPort::entry_from_factor(const types::global_dof_index row,
                                 const types::global_dof_index column,
                                 const TrailingBlockInverse   &cholesky) const
  {
    // (the column was formed by prepare_compliance())
    double value = 0.;
    for (const auto &[i, wi] : contact_rows_resolved[contact_position[row]])
      for (const auto &[j, wj] :
           contact_rows_resolved[contact_position[column]])
        value += wi * wj * cholesky.inverse_entry(i, j);
    return value;
  }
} // namespace glissade

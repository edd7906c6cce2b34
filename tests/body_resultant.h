#pragma once

// The resultant of a force vector on a body's dofs, which several contact
// tests compare: the sum over its value dofs of each component (a Hermite
// body's derivative dofs carry moments, not force).

#include <glissade/body/body.h>

#include <vector>

namespace glissade_tests
{
  inline dealii::Tensor<1, 2>
  resultant(const glissade::Body &body, const dealii::Vector<double> &f)
  {
    const auto          &fe      = body.space().finite_element();
    const unsigned int   per_dim = body.space().components_per_displacement();
    dealii::Tensor<1, 2> total;
    std::vector<bool>    counted(body.n_dofs(), false);
    std::vector<dealii::types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            if (c % per_dim == 0 && !counted[local[i]])
              {
                counted[local[i]] = true;
                total[c / per_dim] += f(local[i]);
              }
          }
      }
    return total;
  }
} // namespace glissade_tests

// The springs of a body held by contact
// (include/glissade/body/rigid_motion_springs.h).

#include <glissade/base/input_error.h>
#include <glissade/body/boundary_conditions.h>
#include <glissade/body/rigid_motion_springs.h>

#include <cmath>
#include <map>

namespace glissade
{
  using namespace dealii;

  RigidMotionSprings::RigidMotionSprings(
    const std::vector<RigidMotion> &free_motions,
    const std::string              &source,
    const std::string              &body_name,
    const double                    body_size)
    : motions_left_free(free_motions)
    , source(source)
    , body_name(body_name)
    , body_size(body_size)
  {}



  void
  RigidMotionSprings::choose_dofs(
    const std::vector<types::global_dof_index> &contact_dofs,
    const AffineConstraints<double>            &constraints,
    const DoFHandler<2>                        &dofs,
    const ElementSpace                         &space)
  {
    // The candidates: unconstrained nodal values among the contact dofs,
    // each with the values that the free motions take there.
    std::map<types::global_dof_index, std::vector<double>> candidates;
    for (const auto dof : contact_dofs)
      if (!constraints.is_constrained(dof))
        candidates.emplace(dof, std::vector<double>());
    const auto take = [&](const types::global_dof_index dof,
                          const unsigned int            component,
                          const Point<2>               &X) {
      const auto found = candidates.find(dof);
      if (found != candidates.end() && found->second.empty())
        for (const auto &motion : motions_left_free)
          found->second.push_back(motion.at(X)[component]);
    };
    if (space.capabilities().dofs_are_nodal_values)
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto vertex_dofs =
              BoundaryConditions::cell_vertex_dofs(cell, v, space);
            for (unsigned int c = 0; c < 2; ++c)
              take(vertex_dofs[c], c, cell->vertex(v));
          }
    else
      // (dofs that are not nodal values, NURBS control points: a rigid
      // motion moves each as it moves the point the space gives it, the
      // control point of an isoparametric space)
      for (const auto &point : space.interpolation_points())
        take(point.dof, point.component, point.point);

    // Pivoted Gram-Schmidt: each time the candidate that moves most under
    // the free motions not yet held.
    dofs_and_stiffness.clear();
    std::vector<std::vector<double>> held;
    for (unsigned int step = 0; step < motions_left_free.size(); ++step)
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
          throw InputError(source + ": Body " + body_name +
                             "/Boundary conditions",
                           "body '" + body_name +
                             "' relies on contact to hold " +
                             motions_left_free[step].describe(body_size) +
                             ", but none of its contact nodes moves with it");
        for (double &d : direction)
          d /= best;
        held.push_back(direction);
        dofs_and_stiffness.emplace_back(chosen, 0.);
      }
  }



  std::vector<double>
  RigidMotionSprings::add_to(SparseMatrix<double> &tangent,
                             const double          k,
                             const bool            add)
  {
    std::vector<double> assembled(dofs_and_stiffness.size());
    for (unsigned int s = 0; s < dofs_and_stiffness.size(); ++s)
      {
        double &diagonal = tangent.diag_element(dofs_and_stiffness[s].first);
        assembled[s]     = diagonal;
        dofs_and_stiffness[s].second = k;
        if (add)
          diagonal += k;
      }
    return assembled;
  }



  void
  RigidMotionSprings::take_from(SparseMatrix<double>      &tangent,
                                const std::vector<double> &assembled) const
  {
    for (unsigned int s = 0; s < dofs_and_stiffness.size(); ++s)
      tangent.diag_element(dofs_and_stiffness[s].first) = assembled[s];
  }
} // namespace glissade

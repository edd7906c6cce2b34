// Measures of a body's state (include/glissade/body/body_measures.h).

#include <glissade/base/input_error.h>
#include <glissade/base/processes.h>
#include <glissade/body/body.h>
#include <glissade/body/body_measures.h>
#include <glissade/mesh/nearest_vertex.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  Tensor<1, 2>
  vertex_displacement(const Body &body, const Point<2> &point)
  {
    const auto            dof_pair = vertex_value_dofs(body, point);
    const Vector<double> &u        = body.nodal_displacement();
    return Tensor<1, 2>({u(dof_pair[0]), u(dof_pair[1])});
  }



  std::array<types::global_dof_index, 2>
  vertex_value_dofs(const Body &body, const Point<2> &point)
  {
    // A distributed mesh may not hold the vertex here: the whole mesh's
    // vertices are kept for it.
    if (body.mesh_is_distributed())
      {
        const auto &nodes          = body.whole_mesh_nodes();
        const auto [nearest, best] = nearest_vertex(nodes.vertices, point);
        if (best > 1e-8 * body.size())
          {
            std::ostringstream message;
            message << "point(" << point[0] << ", " << point[1]
                    << ") is not a vertex of the mesh of body '" << body.name()
                    << "' (the nearest vertex is at " << nodes.vertices[nearest]
                    << ")";
            throw InputError("", message.str());
          }
        return nodes.vertex_dofs[nearest];
      }
    std::ostringstream location;
    location.precision(17);
    location << "point(" << point[0] << ", " << point[1] << ")";
    const Location where = BoundaryConditions::resolve(location.str(),
                                                       body.boundary_names(),
                                                       body.triangulation(),
                                                       body.name(),
                                                       "",
                                                       false,
                                                       body.size());
    return BoundaryConditions::vertex_dofs(body.dof_handler(),
                                           body.space(),
                                           where.vertex);
  }



  std::vector<Tensor<1, 2>>
  vertex_displacements(const Body &body)
  {
    const Vector<double>     &u = body.nodal_displacement();
    std::vector<Tensor<1, 2>> result(body.triangulation().n_vertices());
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const auto value_dofs =
            BoundaryConditions::cell_vertex_dofs(cell, v, body.space());
          for (unsigned int d = 0; d < 2; ++d)
            result[cell->vertex_index(v)][d] = u(value_dofs[d]);
        }
    return result;
  }



  double
  max_displacement(const Body &body)
  {
    // Nodal values: pair the x and y value dofs that share a node.
    const FiniteElement<2> &fe = body.space().finite_element();
    const unsigned int per_dim = body.space().components_per_displacement();
    std::vector<std::pair<unsigned int, unsigned int>> pairs;
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto ci = fe.system_to_component_index(i);
        if (ci.first != 0)
          continue;
        for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
          if (fe.system_to_component_index(j) ==
              std::make_pair(per_dim, ci.second))
            pairs.emplace_back(i, j);
      }
    const Vector<double>                &u = body.nodal_displacement();
    std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());
    double                               largest = 0.;
    // (a distributed mesh may not hold the node where it is largest)
    if (body.mesh_is_distributed())
      {
        for (const auto &[x, y] : body.whole_mesh_nodes().node_dofs)
          largest = std::max(largest, std::hypot(u(x), u(y)));
        return largest;
      }
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(local_dofs);
        for (const auto &p : pairs)
          largest = std::max(largest,
                             std::hypot(u(local_dofs[p.first]),
                                        u(local_dofs[p.second])));
      }
    return largest;
  }



  Tensor<1, 2>
  support_reaction(const Body &body, const std::string &boundary)
  {
    const Location where = BoundaryConditions::resolve(
      boundary, body.boundary_names(), body.triangulation(), body.name(), "");
    const Vector<double> &residual = body.unbalanced_forces();
    const Vector<double> &contact  = body.get_contact_forces();
    Tensor<1, 2>          sum;
    if (where.is_vertex && !body.space().capabilities().dofs_are_nodal_values)
      {
        // (the functions nonzero at the point: the support's multiplier
        // times each function's value, which sum to one)
        Location at = where;
        BoundaryConditions::locate_on_boundary_face(at,
                                                    body.triangulation(),
                                                    body.name(),
                                                    boundary);
        for (const auto &f : BoundaryConditions::functions_at_face_point(
               body.dof_handler(), body.space(), at))
          sum[f.component] += residual(f.dof) - contact(f.dof);
        return sum;
      }
    if (where.is_vertex)
      {
        const auto d = BoundaryConditions::vertex_dofs(body.dof_handler(),
                                                       body.space(),
                                                       where.vertex);
        return Tensor<1, 2>(
          {residual(d[0]) - contact(d[0]), residual(d[1]) - contact(d[1])});
      }
    if (!body.space().capabilities().dofs_are_nodal_values)
      {
        // (the dofs a support on the boundary constrains: its control
        // points, whose residual is the boundary's reaction since the
        // functions sum to one)
        for (unsigned int c = 0; c < 2; ++c)
          {
            std::vector<DofRelation> relations;
            body.space().boundary_relations(body.dof_handler(),
                                            where.boundary,
                                            Functions::ZeroFunction<2>(2),
                                            {{c == 0, c == 1}},
                                            false,
                                            relations);
            for (const auto &r : relations)
              sum[c] += residual(r.dof) - contact(r.dof);
          }
        return sum;
      }
    const FiniteElement<2>              &fe = body.space().finite_element();
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    std::vector<bool>                    counted(body.n_dofs(), false);
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == where.boundary)
          {
            cell->face(f)->get_dof_indices(face_dofs);
            for (unsigned int k = 0; k < face_dofs.size(); ++k)
              if (!counted[face_dofs[k]])
                {
                  counted[face_dofs[k]] = true;
                  // Only value dofs carry force; derivative dofs carry
                  // its moments.
                  const unsigned int per_dim =
                    body.space().components_per_displacement();
                  const unsigned int k_component =
                    fe.face_system_to_component_index(k).first;
                  if (k_component % per_dim == 0)
                    sum[k_component / per_dim] +=
                      residual(face_dofs[k]) - contact(face_dofs[k]);
                }
          }
    return sum;
  }



  double
  strain_energy(const Body &body)
  {
    const Hypothesis     &hypothesis = body.hypothesis();
    const Vector<double> &u          = body.displacement();
    // (made at the first cell whose stiffness is not kept: at small strain
    // none, and this runs at every step)
    std::unique_ptr<CellEvaluator>       evaluator;
    std::vector<types::global_dof_index> local(
      body.dof_handler().get_fe().n_dofs_per_cell());
    std::vector<double> values(local.size());
    double              energy = 0.;
    // (a mesh shared out: this process's cells, then the processes' sums;
    // every process asks)
    const bool shared_out = body.mesh_is_distributed();
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        if (shared_out && !body.is_own_cell(cell))
          continue;
        body.space().cell_dof_indices(cell, local);
        for (unsigned int i = 0; i < local.size(); ++i)
          values[i] = u(local[i]);
        // (small strain: 1/2 u_e . K_e u_e, the same quadrature without
        // evaluating the shape functions again)
        if (const FullMatrix<double> *K = body.kept_cell_stiffness(cell))
          {
            for (unsigned int i = 0; i < local.size(); ++i)
              for (unsigned int j = 0; j < local.size(); ++j)
                energy += 0.5 * values[i] * (*K)(i, j) * values[j];
            continue;
          }
        if (!evaluator)
          evaluator = body.space().create_evaluator();
        evaluator->reinit(cell);
        const Material &material =
          body.materials().of_cell(cell->material_id());
        for (unsigned int q = 0; q < evaluator->n_quadrature_points(); ++q)
          {
            const Point<2> X = evaluator->quadrature_point(q);
            const double   hoop =
              hypothesis.strains_the_hoop() ?
                  hypothesis.hoop_ratio(evaluator->value(values, q)[0], X) :
                  0.;
            energy += material.energy(evaluator->gradient(values, q), hoop) *
                      evaluator->JxW(q) * hypothesis.out_of_plane_measure(X);
          }
      }
    if (shared_out)
      processes::sum(&energy, 1);
    return energy;
  }
} // namespace glissade

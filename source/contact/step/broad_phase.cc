// The broad phase of automatic contact: bounding boxes in an R-tree.

#include <deal.II/numerics/rtree.h>

#include <glissade/body/body.h>
#include <glissade/contact/step/broad_phase.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <utility>

namespace glissade
{
  using namespace dealii;

  BroadPhase::BroadPhase(const std::vector<Side> &sides,
                         const double             alert_distance)
    : alert_distance(alert_distance)
  {
    for (const Side &side : sides)
      {
        Boundary                             boundary{side.body, {}, {}, {}};
        std::map<unsigned int, unsigned int> index_of_vertex;
        for (const auto &cell :
             side.body->dof_handler().active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                side.boundary_ids.count(cell->face(f)->boundary_id()) > 0)
              {
                std::array<unsigned int, 2> face;
                for (const unsigned int v : {0u, 1u})
                  {
                    const auto [at, added] =
                      index_of_vertex.emplace(cell->face(f)->vertex_index(v),
                                              boundary.dofs.size());
                    face[v] = at->second;
                    if (!added)
                      continue;
                    boundary.dofs.push_back(
                      BoundaryConditions::cell_vertex_dofs(
                        cell,
                        GeometryInfo<2>::face_to_cell_vertices(f, v),
                        side.body->space()));
                    boundary.reference.push_back(cell->face(f)->vertex(v));
                  }
                boundary.faces.push_back(face);
              }
        boundaries.push_back(std::move(boundary));
      }
  }



  BoundingBox<2>
  BroadPhase::reach_box(const unsigned int side) const
  {
    const Boundary       &boundary = boundaries[side];
    const Vector<double> &u        = boundary.body->displacement();
    std::vector<Point<2>> x(boundary.dofs.size());
    for (unsigned int k = 0; k < x.size(); ++k)
      x[k] = boundary.reference[k] +
             Tensor<1, 2>({u(boundary.dofs[k][0]), u(boundary.dofs[k][1])});
    double longest_face = 0.;
    for (const auto &[a, b] : boundary.faces)
      longest_face = std::max(longest_face, x[a].distance(x[b]));
    if (x.empty())
      return BoundingBox<2>();
    BoundingBox<2> box(x);
    box.extend(longest_face + 0.5 * alert_distance);
    return box;
  }



  std::vector<std::array<unsigned int, 2>>
  BroadPhase::couples_within_reach() const
  {
    std::vector<std::pair<BoundingBox<2>, unsigned int>> boxes;
    for (unsigned int s = 0; s < boundaries.size(); ++s)
      if (!boundaries[s].dofs.empty())
        boxes.emplace_back(reach_box(s), s);
    const auto tree = pack_rtree(boxes);

    std::vector<std::array<unsigned int, 2>>             couples;
    std::vector<std::pair<BoundingBox<2>, unsigned int>> overlapping;
    for (const auto &[box, s] : boxes)
      {
        overlapping.clear();
        tree.query(boost::geometry::index::intersects(box),
                   std::back_inserter(overlapping));
        for (const auto &other : overlapping)
          if (other.second > s)
            couples.push_back({{s, other.second}});
      }
    std::sort(couples.begin(), couples.end());
    return couples;
  }
} // namespace glissade

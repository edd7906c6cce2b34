#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/body/body.h>
#include <glissade/contact/surfaces/master_chain.h>

#include <algorithm>
#include <map>
#include <set>

namespace glissade
{
  using namespace dealii;

  std::vector<MasterChain>
  MasterChain::build_all(const Body        &body,
                         const std::string &boundary,
                         const std::string &entry)
  {
    // One boundary name or several ("inner, outer"): their faces together.
    std::set<types::boundary_id> ids;
    for (const auto &name : text::split_top_level(boundary, ','))
      ids.insert(body.boundary_id(text::trim(name), entry));

    struct BoundaryFace
    {
      unsigned int v0, v1;
      Face         face;
    };
    std::vector<BoundaryFace>                         faces;
    std::map<unsigned int, std::vector<unsigned int>> at_vertex;
    // The value dofs of each vertex of the boundary, from the face's own
    // cell (a search of the mesh per vertex made a 20,000-node master
    // quadratic to set up).
    std::map<unsigned int, std::array<types::global_dof_index, 2>> dofs_of;
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            ids.count(cell->face(f)->boundary_id()) > 0)
          {
            faces.push_back({cell->face(f)->vertex_index(0),
                             cell->face(f)->vertex_index(1),
                             {cell, f}});
            at_vertex[faces.back().v0].push_back(faces.size() - 1);
            at_vertex[faces.back().v1].push_back(faces.size() - 1);
            for (const unsigned int v : {0u, 1u})
              dofs_of[cell->face(f)->vertex_index(v)] =
                BoundaryConditions::cell_vertex_dofs(
                  cell,
                  GeometryInfo<2>::face_to_cell_vertices(f, v),
                  body.space());
          }
    if (faces.empty())
      throw InputError(entry, "the master boundary has no faces");
    for (const auto &[vertex, list] : at_vertex)
      if (list.size() > 2)
        throw InputError(entry,
                         "the master boundary branches (more than two faces "
                         "at a vertex): each of its curves must be one chain "
                         "of faces");

    const auto              &points = body.triangulation().get_vertices();
    std::vector<bool>        used(faces.size(), false);
    std::vector<MasterChain> chains;
    // One curve: the faces met walking from `start` until none is left.
    const auto walk = [&](const unsigned int start) {
      std::vector<unsigned int> vertices = {start}, order;
      while (true)
        {
          int next_face = -1;
          for (const unsigned int f : at_vertex[vertices.back()])
            if (!used[f])
              next_face = f;
          if (next_face < 0)
            break;
          used[next_face] = true;
          order.push_back(next_face);
          const BoundaryFace &face = faces[next_face];
          vertices.push_back(face.v0 == vertices.back() ? face.v1 : face.v0);
        }
      MasterChain chain;
      chain.closed = at_vertex[start].size() == 2;
      if (chain.closed)
        vertices.pop_back(); // the walk came back to its start

      // The master body must lie to the right of the direction of travel,
      // so that n = e3 x t points out of it.
      const Face        &first = faces[order[0]].face;
      const Tensor<1, 2> t     = points[vertices[1]] - points[vertices[0]];
      const Tensor<1, 2> outward =
        first.cell->face(first.face)->center() - first.cell->center();
      if (-t[1] * outward[0] + t[0] * outward[1] < 0.)
        {
          std::reverse(vertices.begin(), vertices.end());
          std::reverse(order.begin(), order.end());
          // Keep segment i joining vertices[i] and vertices[i + 1]: after
          // the reversal of a closed chain the closing face comes first.
          if (chain.closed)
            std::rotate(order.begin(), order.begin() + 1, order.end());
        }
      const unsigned int minimum = chain.closed ? 3 : 2;
      if (vertices.size() < minimum)
        throw InputError(entry,
                         "the master boundary has a curve with too few "
                         "nodes for a curve");
      chain.vertices = vertices;
      for (const unsigned int v : vertices)
        {
          chain.reference_points.push_back(points[v]);
          chain.value_dofs.push_back(dofs_of.at(v));
        }
      for (const unsigned int f : order)
        chain.faces.push_back(faces[f].face);
      chains.push_back(std::move(chain));
    };
    // Open curves from their first end in the mesh's order, then the
    // closed ones from their first face.
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (const unsigned int end : {faces[f].v0, faces[f].v1})
        if (!used[f] && at_vertex[end].size() == 1)
          walk(end);
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (!used[f])
        walk(faces[f].v0);
    return chains;
  }



  MasterChain
  MasterChain::build(const Body        &body,
                     const std::string &boundary,
                     const std::string &entry,
                     const unsigned int curve)
  {
    std::vector<MasterChain> chains = build_all(body, boundary, entry);
    AssertIndexRange(curve, chains.size());
    return std::move(chains[curve]);
  }
} // namespace glissade

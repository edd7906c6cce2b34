#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/base/user_function.h>
#include <glissade/mesh/cell_order.h>
#include <glissade/mesh/gmsh_reader.h>
#include <glissade/mesh/mesh_factory.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  MeshLabels
  MeshFactory::create(const MeshDescription &description,
                      Triangulation<2>      &triangulation,
                      const std::string     &where)
  {
    MeshLabels labels =
      type(description.type).create(description, triangulation, where);

    if (description.distortion > 0. && labels.second_order)
      throw InputError(where + "/Mesh/Distortion",
                       "applies to first-order meshes only ('" +
                         description.file +
                         "' has second-order quadrilaterals)");
    if (description.distortion > 0.)
      GridTools::distort_random(description.distortion, triangulation, true);
    take_boundary_parts(description, triangulation, labels, where);
    check_cells_are_not_folded(triangulation, where);
    if (type(description.type).from_file)
      {
        check_mesh_is_conforming(triangulation, where);
        // (after the checks, whose messages number the cells as the file
        // does; a file's order would share the mesh out poorly. A patch
        // keeps its elements' order, which a NURBS space reads.)
        if (!type(description.type).exact_patch)
          order_cells_along_hilbert_curve(triangulation);
      }
    return labels;
  }



  void
  MeshFactory::take_boundary_parts(const MeshDescription &description,
                                   Triangulation<2>      &triangulation,
                                   MeshLabels            &labels,
                                   const std::string     &where)
  {
    const std::string entry = where + "/Mesh/Boundary parts";
    for (const auto &part : description.boundary_parts)
      {
        const auto from = labels.boundaries.find(part.boundary);
        if (from == labels.boundaries.end())
          throw InputError(entry,
                           "part '" + part.name +
                             "': the mesh has no boundary '" + part.boundary +
                             "'");
        if (labels.boundaries.count(part.name) > 0)
          throw InputError(entry,
                           "part '" + part.name +
                             "': the mesh has a boundary of that name already");
        // A new id: above every id in use (254 and 255 are deal.II's and
        // the processes' own).
        types::boundary_id id = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              id =
                std::max<types::boundary_id>(id,
                                             cell->face(f)->boundary_id() + 1);
        for (const auto &[name, named] : labels.boundaries)
          id = std::max<types::boundary_id>(id, named + 1);
        if (id >= 254)
          throw InputError(entry,
                           "part '" + part.name +
                             "': the mesh has no boundary id left for it");
        UserFunction condition({part.condition}, entry);
        unsigned int taken = 0, left = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == from->second)
              {
                if (condition.value(cell->face(f)->center(), 0) != 0.)
                  {
                    cell->face(f)->set_boundary_id(id);
                    ++taken;
                  }
                else
                  ++left;
              }
        if (taken == 0)
          throw InputError(entry,
                           "part '" + part.name + "' takes no face of '" +
                             part.boundary + "' (" + part.condition +
                             " is zero at every face's centre)");
        labels.boundaries[part.name] = id;
        if (left == 0)
          labels.boundaries.erase(part.boundary);
      }
  }



  const MeshFactory::MeshType &
  MeshFactory::type(const std::string &name)
  {
    for (const MeshType &entry : types())
      if (entry.name == name)
        return entry;
    throw InputError("Mesh/Type",
                     "unknown mesh type '" + name +
                       "' (known: " + names_as_pattern() + ")");
  }



  std::string
  MeshFactory::names_as_pattern()
  {
    std::string names;
    for (const MeshType &entry : types())
      names += (names.empty() ? "" : "|") + entry.name;
    return names;
  }



  std::string
  MeshFactory::documentation()
  {
    std::string text;
    for (const MeshType &entry : types())
      text +=
        (text.empty() ? "" : "; ") + entry.name + ": " + entry.documentation;
    return text + ".";
  }



  void
  MeshFactory::check_mesh_is_conforming(const Triangulation<2> &triangulation,
                                        const std::string      &where)
  {
    // In a mesh with a hanging node (a vertex in the middle of a
    // neighbour's edge) deal.II finds no neighbour across either side, so
    // both count as boundary: the edge opens under load and the answer is
    // wrong without a word. A boundary vertex strictly inside another
    // boundary face is such a node. Boundary vertices are hashed in a grid
    // of the mean face length, so the search is linear in the boundary.
    std::vector<std::pair<Point<2>, Point<2>>> faces;
    std::map<unsigned int, Point<2>>           vertices;
    double                                     length = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            faces.emplace_back(cell->face(f)->vertex(0),
                               cell->face(f)->vertex(1));
            length += cell->face(f)->measure();
            for (const unsigned int v : {0u, 1u})
              vertices[cell->face(f)->vertex_index(v)] =
                cell->face(f)->vertex(v);
          }
    if (faces.empty())
      return;
    const double h = length / faces.size();
    std::map<std::pair<long, long>, std::vector<Point<2>>> grid;
    const auto key = [h](const double x, const double y) {
      return std::make_pair(static_cast<long>(std::floor(x / h)),
                            static_cast<long>(std::floor(y / h)));
    };
    for (const auto &[index, p] : vertices)
      grid[key(p[0], p[1])].push_back(p);
    for (const auto &[a, b] : faces)
      {
        const Tensor<1, 2> d  = b - a;
        const double       d2 = d.norm_square();
        const auto low        = key(std::min(a[0], b[0]), std::min(a[1], b[1]));
        const auto high       = key(std::max(a[0], b[0]), std::max(a[1], b[1]));
        for (long i = low.first; i <= high.first; ++i)
          for (long j = low.second; j <= high.second; ++j)
            {
              const auto found = grid.find({i, j});
              if (found == grid.end())
                continue;
              for (const Point<2> &p : found->second)
                {
                  const double s = (p - a) * d / d2;
                  const double off =
                    std::abs(d[0] * (p - a)[1] - d[1] * (p - a)[0]) /
                    std::sqrt(d2);
                  if (s > 1e-8 && s < 1. - 1e-8 && off < 1e-10 * std::sqrt(d2))
                    {
                      std::ostringstream message;
                      message << "the node at (" << p[0] << ", " << p[1]
                              << ") lies inside the edge from (" << a[0] << ", "
                              << a[1] << ") to (" << b[0] << ", " << b[1]
                              << ") without being one of its ends (a "
                                 "hanging node): the mesh must be conforming, "
                                 "or that edge would open";
                      throw InputError(where + "/Mesh", message.str());
                    }
                }
            }
      }
  }



  void
  MeshFactory::check_cells_are_not_folded(const Triangulation<2> &triangulation,
                                          const std::string      &where)
  {
    // The Jacobian of the bilinear map at the four corners of each cell
    // (deal.II's vertex order: 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1)). A
    // zero or negative corner determinant is a degenerate or folded
    // (bow-tie) cell, whose stiffness is meaningless: the run would go on
    // and answer wrongly, or fail later with "did not converge".
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const auto v = [&](const unsigned int i) { return cell->vertex(i); };
        const std::array<std::pair<Tensor<1, 2>, Tensor<1, 2>>, 4> corners{
          {{v(1) - v(0), v(2) - v(0)},
           {v(1) - v(0), v(3) - v(1)},
           {v(3) - v(2), v(2) - v(0)},
           {v(3) - v(2), v(3) - v(1)}}};
        const double scale = std::pow(cell->diameter(), 2);
        for (const auto &[along_xi, along_eta] : corners)
          {
            const double det =
              along_xi[0] * along_eta[1] - along_xi[1] * along_eta[0];
            if (!(det > 1e-12 * scale))
              {
                std::ostringstream message;
                message << "cell " << cell->active_cell_index() << " (vertices";
                for (const unsigned int i : {0u, 1u, 3u, 2u})
                  message << " (" << v(i)[0] << ", " << v(i)[1] << ")";
                message << ") is "
                        << (std::abs(det) <= 1e-12 * scale ?
                              "degenerate (zero area at a corner)" :
                              "folded (its corners turn the wrong way)")
                        << "; every cell must be a convex quadrilateral";
                throw InputError(where + "/Mesh", message.str());
              }
          }
      }
  }
} // namespace glissade

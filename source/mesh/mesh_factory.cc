#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
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
    check_cells_are_not_folded(triangulation, where);
    if (type(description.type).from_file)
      check_mesh_is_conforming(triangulation, where);
    return labels;
  }



  const std::vector<MeshFactory::MeshType> &
  MeshFactory::types()
  {
    const auto rings_radii = [](const MeshDescription &d,
                                const std::string     &where) {
      if (!(d.outer_radius > d.inner_radius && d.inner_radius > 0))
        throw InputError(where + "/Mesh/Outer radius",
                         "rings need 0 < Inner radius < Outer radius");
    };
    // One line per kind of mesh.
    static const std::vector<MeshType> list = {
      {"rectangle",
       "from Corner 1 to Corner 2, boundaries left, right, bottom, top",
       false,
       [](const MeshDescription &d, const std::string &where) {
         if (!(d.corner_2[0] > d.corner_1[0] && d.corner_2[1] > d.corner_1[1]))
           throw InputError(where + "/Mesh/Corner 2",
                            "must lie above and to the right of Corner 1");
       },
       [](const MeshDescription &d, Triangulation<2> &t, const std::string &) {
         MeshLabels labels;
         labels.boundaries = create_rectangle(d.corner_1, d.corner_2, d, t);
         return labels;
       }},
      {"square",
       "centred at Center with side Side, same boundary names",
       false,
       [](const MeshDescription &, const std::string &) {},
       [](const MeshDescription &d, Triangulation<2> &t, const std::string &) {
         const Tensor<1, 2> half({d.side / 2, d.side / 2});
         MeshLabels         labels;
         labels.boundaries =
           create_rectangle(d.center - half, d.center + half, d, t);
         return labels;
       }},
      {"half ring",
       "centred at Center between Inner radius and Outer radius, "
       "boundaries inner, outer, start and end at the Start/End angle",
       false,
       [rings_radii](const MeshDescription &d, const std::string &where) {
         rings_radii(d, where);
         if (!(d.end_angle > d.start_angle &&
               d.end_angle - d.start_angle < 360.))
           throw InputError(where + "/Mesh/End angle",
                            "must be larger than Start angle, by less than "
                            "360");
       },
       [](const MeshDescription &d, Triangulation<2> &t, const std::string &) {
         MeshLabels labels;
         labels.boundaries = create_ring(d, false, t);
         return labels;
       }},
      {"ring",
       "the same closed, boundaries inner and outer",
       false,
       [rings_radii](const MeshDescription &d, const std::string &where) {
         rings_radii(d, where);
         if (d.subdivisions[0] < 3)
           throw InputError(where + "/Mesh/Subdivisions",
                            "a ring needs at least 3 elements around");
       },
       [](const MeshDescription &d, Triangulation<2> &t, const std::string &) {
         MeshLabels labels;
         labels.boundaries = create_ring(d, true, t);
         return labels;
       }},
      {"gmsh",
       "the .msh file File, whose named physical lines become boundaries",
       true,
       [](const MeshDescription &d, const std::string &where) {
         if (d.file.empty())
           throw InputError(where + "/Mesh/File", "gmsh meshes need a File");
       },
       [](const MeshDescription &d,
          Triangulation<2>      &t,
          const std::string     &where) {
         return read_gmsh(d.file, t, where + "/Mesh/File");
       }}};
    return list;
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



  BoundaryNames
  MeshFactory::create_rectangle(const Point<2>        &lower_left,
                                const Point<2>        &upper_right,
                                const MeshDescription &description,
                                Triangulation<2>      &triangulation)
  {
    // colorize = true numbers the sides 0 (x = x0), 1 (x = x1), 2 (y = y0)
    // and 3 (y = y1).
    GridGenerator::subdivided_hyper_rectangle(
      triangulation, description.subdivisions, lower_left, upper_right, true);
    return {{"left", 0}, {"right", 1}, {"bottom", 2}, {"top", 3}};
  }



  BoundaryNames
  MeshFactory::create_ring(const MeshDescription &description,
                           const bool             closed,
                           Triangulation<2>      &triangulation)
  {
    const unsigned int n_around  = description.subdivisions[0];
    const unsigned int n_through = description.subdivisions[1];
    const double       r_in      = description.inner_radius;
    const double       r_out     = description.outer_radius;
    const double theta_0 = closed ? 0. : description.start_angle * M_PI / 180.;
    const double theta_1 =
      closed ? 2. * M_PI : description.end_angle * M_PI / 180.;
    const unsigned int n_angles = closed ? n_around : n_around + 1;

    std::vector<Point<2>> vertices;
    for (unsigned int i = 0; i < n_angles; ++i)
      {
        const double theta =
          theta_0 + (theta_1 - theta_0) * double(i) / double(n_around);
        for (unsigned int j = 0; j <= n_through; ++j)
          {
            const double r =
              r_in + (r_out - r_in) * double(j) / double(n_through);
            vertices.push_back(
              description.center +
              Tensor<1, 2>({r * std::cos(theta), r * std::sin(theta)}));
          }
      }

    const auto vertex = [&](const unsigned int i, const unsigned int j) {
      return (i % n_angles) * (n_through + 1) + j;
    };
    std::vector<CellData<2>> cells;
    for (unsigned int i = 0; i < n_around; ++i)
      for (unsigned int j = 0; j < n_through; ++j)
        {
          // First reference direction radial, second along theta: e_r x
          // e_theta = +e_z, so the cell is positively oriented.
          CellData<2> cell;
          cell.vertices = {vertex(i, j),
                           vertex(i, j + 1),
                           vertex(i + 1, j),
                           vertex(i + 1, j + 1)};
          cells.push_back(cell);
        }
    triangulation.create_triangulation(vertices, cells, SubCellData());

    const double tolerance = 1e-10 * r_out;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const double r0 = (face->vertex(0) - description.center).norm();
            const double r1 = (face->vertex(1) - description.center).norm();
            if (std::abs(r0 - r_in) < tolerance &&
                std::abs(r1 - r_in) < tolerance)
              face->set_boundary_id(0);
            else if (std::abs(r0 - r_out) < tolerance &&
                     std::abs(r1 - r_out) < tolerance)
              face->set_boundary_id(1);
            else
              {
                // A radial end of a half ring: which one, by its angle.
                const Tensor<1, 2> d = face->center() - description.center;
                const Tensor<1, 2> e0({std::cos(theta_0), std::sin(theta_0)});
                const Tensor<1, 2> e1({std::cos(theta_1), std::sin(theta_1)});
                const Tensor<1, 2> direction = d / d.norm();
                face->set_boundary_id(
                  (direction - e0).norm() < (direction - e1).norm() ? 2 : 3);
              }
          }

    triangulation.set_all_manifold_ids(0);
    triangulation.set_manifold(0, PolarManifold<2>(description.center));

    if (closed)
      return {{"inner", 0}, {"outer", 1}};
    return {{"inner", 0}, {"outer", 1}, {"start", 2}, {"end", 3}};
  }



} // namespace glissade

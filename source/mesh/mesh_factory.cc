#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
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
  BoundaryNames
  MeshFactory::create(const MeshDescription &description,
                      Triangulation<2>      &triangulation,
                      const std::string     &where)
  {
    BoundaryNames names;
    if (description.type == "rectangle")
      names = create_rectangle(description.corner_1,
                               description.corner_2,
                               description,
                               triangulation);
    else if (description.type == "square")
      {
        const Tensor<1, 2> half({description.side / 2, description.side / 2});
        names = create_rectangle(description.center - half,
                                 description.center + half,
                                 description,
                                 triangulation);
      }
    else if (description.type == "half ring")
      names = create_ring(description, false, triangulation);
    else if (description.type == "ring")
      names = create_ring(description, true, triangulation);
    else if (description.type == "gmsh")
      names = read_gmsh(description, triangulation, where);
    else
      throw InputError(where + "/Mesh/Type",
                       "unknown mesh type '" + description.type + "'");

    if (description.distortion > 0.)
      GridTools::distort_random(description.distortion, triangulation, true);
    check_cells_are_not_folded(triangulation, where);
    if (description.type == "gmsh")
      check_mesh_is_conforming(triangulation, where);
    return names;
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
            faces.emplace_back(cell->face(f)->vertex(0), cell->face(f)->vertex(1));
            length += cell->face(f)->measure();
            for (const unsigned int v : {0u, 1u})
              vertices[cell->face(f)->vertex_index(v)] = cell->face(f)->vertex(v);
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
        const Tensor<1, 2> d     = b - a;
        const double       d2    = d.norm_square();
        const auto         low   = key(std::min(a[0], b[0]), std::min(a[1], b[1]));
        const auto         high  = key(std::max(a[0], b[0]), std::max(a[1], b[1]));
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
                    std::abs(d[0] * (p - a)[1] - d[1] * (p - a)[0]) / std::sqrt(d2);
                  if (s > 1e-8 && s < 1. - 1e-8 && off < 1e-10 * std::sqrt(d2))
                    {
                      std::ostringstream message;
                      message << "the node at (" << p[0] << ", " << p[1]
                              << ") lies inside the edge from (" << a[0]
                              << ", " << a[1] << ") to (" << b[0] << ", "
                              << b[1]
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
            const double det = along_xi[0] * along_eta[1] -
                               along_xi[1] * along_eta[0];
            if (!(det > 1e-12 * scale))
              {
                std::ostringstream message;
                message << "cell " << cell->active_cell_index()
                        << " (vertices";
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
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              description.subdivisions,
                                              lower_left,
                                              upper_right,
                                              true);
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
            vertices.push_back(description.center +
                               Tensor<1, 2>({r * std::cos(theta),
                                             r * std::sin(theta)}));
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
                face->set_boundary_id((direction - e0).norm() <
                                          (direction - e1).norm() ?
                                        2 :
                                        3);
              }
          }

    triangulation.set_all_manifold_ids(0);
    triangulation.set_manifold(0, PolarManifold<2>(description.center));

    if (closed)
      return {{"inner", 0}, {"outer", 1}};
    return {{"inner", 0}, {"outer", 1}, {"start", 2}, {"end", 3}};
  }



  namespace
  {
    /**
     * Checks the section structure of a Gmsh file before deal.II reads it:
     * GridIn::read_msh loops forever on a file cut short before $Nodes and
     * trusts the declared node and element counts (a wrong digit asks for
     * gigabytes). Found by the fuzzer (tests/fuzz).
     */
    /** Returns true for MSH 2.x, false for 4.1 (the only two read). */
    bool
    check_gmsh_structure(const std::vector<std::string> &lines,
                         const std::string              &file,
                         const std::string              &entry)
    {
      const auto find = [&](const std::string &marker, const std::size_t from) {
        for (std::size_t i = from; i < lines.size(); ++i)
          if (lines[i] == marker)
            return i;
        throw InputError(entry,
                         "'" + file + "' has no " + marker +
                           " line where one is needed (a truncated or "
                           "damaged Gmsh file?)");
      };
      // Every section that opens must close: deal.II reads a section up to
      // its $End line and loops forever if there is none ($PhysicalNames
      // without $EndPhysicalNames: found by the fuzzer).
      for (std::size_t i = 0; i < lines.size(); ++i)
        if (lines[i].size() > 1 && lines[i][0] == '$' &&
            lines[i].rfind("$End", 0) != 0)
          find("$End" + lines[i].substr(1), i + 1);
      const std::size_t format = find("$MeshFormat", 0);
      const std::size_t format_end = find("$EndMeshFormat", format);
      const std::string version =
        format + 1 < format_end ?
          lines[format + 1].substr(0, lines[format + 1].find(' ')) :
          std::string();
      if (version.rfind("2.", 0) != 0 && version != "4.1")
        throw InputError(entry,
                         "'" + file + "': MSH version '" + version +
                           "' is not read: glissade reads MSH 2.2 and 4.1 "
                           "(ASCII; gmsh -format msh22 or msh41)");
      if (lines[format + 1].find(" 1 ") != std::string::npos &&
          lines[format + 1].find(" 0 ") == std::string::npos)
        throw InputError(entry,
                         "'" + file +
                           "': binary MSH files are not read: save as ASCII");
      const bool version_2 = version.rfind("2.", 0) == 0;
      std::size_t from = format_end;
      for (const std::string section : {"Nodes", "Elements"})
        {
          const std::size_t begin = find("$" + section, from);
          const std::size_t end   = find("$End" + section, begin);
          from                    = end;
          // Version 2: "N" then N lines. Version 4: "blocks N ..." then at
          // least N lines (plus one per block).
          std::istringstream header(begin + 1 < end ? lines[begin + 1] : "");
          long long          first = -1, second = -1;
          header >> first >> second;
          const long long declared = version_2 ? first : second;
          const long long present  = static_cast<long long>(end - begin) - 2;
          if (declared < 0 || (version_2 ? declared != present :
                                           declared > present))
            throw InputError(entry,
                             "'" + file + "' declares " +
                               std::to_string(declared) + " " +
                               (section == std::string("Nodes") ?
                                  "nodes" :
                                  "elements") +
                               " but its $" + section + " section has " +
                               std::to_string(std::max(present, 0ll)) +
                               " lines");
        }
      return version_2;
    }

    /** Nodes per element of the Gmsh element types deal.II may meet. */
    int
    gmsh_nodes_per_element(const long type)
    {
      switch (type)
        {
          case 1: return 2;   // line
          case 2: return 3;   // triangle
          case 3: return 4;   // quadrangle
          case 4: return 4;   // tetrahedron
          case 5: return 8;   // hexahedron
          case 8: return 3;   // second-order line
          case 9: return 6;   // second-order triangle
          case 10: return 9;  // second-order quadrangle
          case 15: return 1;  // point
          case 16: return 8;  // serendipity quadrangle
          default: return -1;
        }
    }

    /** The whitespace-separated fields of a line, as long integers. */
    bool
    read_integers(const std::string &line, std::vector<long long> &values)
    {
      values.clear();
      std::istringstream in(line);
      std::string        field;
      while (in >> field)
        {
          char     *end = nullptr;
          const long long v = std::strtoll(field.c_str(), &end, 10);
          if (*end != '\0')
            return false;
          values.push_back(v);
        }
      return true;
    }

    /**
     * Every record of $Entities, $Nodes and $Elements checked against its
     * declared counts before deal.II reads the file: its reader trusts
     * them, and a stray line, an element block of dimension 6, a count of
     * 4e9 nodes or a negative number of tags made it crash, allocate
     * gigabytes or loop (found by fuzzing). Node references must name
     * declared nodes, coordinates must be finite and z zero.
     */
    void
    check_gmsh_records(const std::vector<std::string> &lines,
                       const bool                      version_2,
                       const std::string              &file,
                       const std::string              &entry)
    {
      const auto refuse = [&](const std::size_t line, const std::string &what) {
        throw InputError(entry,
                         "'" + file + "', line " + std::to_string(line + 1) +
                           ": " + what);
      };
      const auto section = [&](const std::string &name) {
        std::size_t begin = 0;
        while (begin < lines.size() && lines[begin] != "$" + name)
          ++begin;
        std::size_t end = begin;
        while (end < lines.size() && lines[end] != "$End" + name)
          ++end;
        return std::make_pair(begin, end); // both lines.size() if absent
      };
      std::vector<long long> v;
      std::set<long long>    nodes;
      const auto             [node_begin, node_end] = section("Nodes");
      const auto             [element_begin, element_end] = section("Elements");
      const auto coordinates = [&](const std::size_t k) {
        std::istringstream in(lines[k]);
        std::vector<double> x;
        std::string         field;
        while (in >> field)
          {
            char *end = nullptr;
            x.push_back(std::strtod(field.c_str(), &end));
            if (*end != '\0' || !std::isfinite(x.back()))
              refuse(k, "a node coordinate is not a finite number");
          }
        return x;
      };
      const auto check_node_line = [&](const std::size_t k,
                                       const std::vector<double> &x) {
        if (x.size() < 3)
          refuse(k, "a node needs x, y and z");
        if (x[2] != 0.)
          refuse(k, "a node has z = " + std::to_string(x[2]) +
                      ": glissade's meshes lie in the plane z = 0");
      };

      const auto nodes_of_type = [&](const std::size_t k, const long long type) {
        const int n = gmsh_nodes_per_element(type);
        if (n < 0)
          refuse(k, "element type " + std::to_string(type) +
                      " is not a Gmsh element glissade knows");
        return n;
      };
      const auto check_node_reference = [&](const std::size_t k,
                                            const long long   tag) {
        if (!nodes.count(tag))
          refuse(k, "the element names node " + std::to_string(tag) +
                      ", which $Nodes does not declare");
      };

      if (version_2)
        {
          // "N", then N lines "tag x y z".
          for (std::size_t k = node_begin + 2; k < node_end; ++k)
            {
              const std::vector<double> x = coordinates(k);
              if (x.size() != 4)
                refuse(k, "a node line must read 'tag x y z'");
              check_node_line(k, {x[1], x[2], x[3]});
              nodes.insert(static_cast<long long>(x[0]));
            }
          // "id type n_tags tags... nodes..."
          for (std::size_t k = element_begin + 2; k < element_end; ++k)
            {
              if (!read_integers(lines[k], v) || v.size() < 3)
                refuse(k, "an element line must read 'id type n_tags tags... "
                          "nodes...'");
              const int n = nodes_of_type(k, v[1]);
              if (v[2] < 0 || static_cast<long long>(v.size()) != 3 + v[2] + n)
                refuse(k, "the element's number of tags and of nodes do not "
                          "match its line");
              for (long long i = 3 + v[2]; i < static_cast<long long>(v.size()); ++i)
                check_node_reference(k, v[i]);
            }
          return;
        }

      // Version 4.1. $Entities: "n_points n_curves n_surfaces n_volumes"
      // and one line per entity.
      const auto [entity_begin, entity_end] = section("Entities");
      if (entity_begin < lines.size())
        {
          if (!read_integers(lines[entity_begin + 1], v) || v.size() != 4)
            refuse(entity_begin + 1, "$Entities must start with four counts");
          long long total = 0;
          for (const long long c : v)
            {
              if (c < 0)
                refuse(entity_begin + 1, "a negative entity count");
              total += c;
            }
          if (total != static_cast<long long>(entity_end - entity_begin) - 2)
            refuse(entity_begin + 1,
                   "$Entities declares " + std::to_string(total) +
                     " entities but has " +
                     std::to_string(entity_end - entity_begin - 2) + " lines");
        }
      // $Nodes: "n_blocks n_nodes min max", per block "dim tag parametric
      // n", n tags, n coordinate lines.
      if (!read_integers(lines[node_begin + 1], v) || v.size() != 4 || v[0] < 0)
        refuse(node_begin + 1, "$Nodes must start with 'blocks nodes min max'");
      {
        const long long n_blocks = v[0], n_nodes = v[1];
        std::size_t     k        = node_begin + 2;
        for (long long b = 0; b < n_blocks; ++b)
          {
            if (k >= node_end || !read_integers(lines[k], v) || v.size() != 4 ||
                v[0] < 0 || v[0] > 3 || v[2] != 0 || v[3] < 0 ||
                2 * v[3] >= static_cast<long long>(node_end - k))
              refuse(k, "a node block header must read 'dimension (0-3) tag "
                        "0 count' with its count of nodes following");
            const long long n = v[3];
            for (long long i = 1; i <= n; ++i)
              {
                if (!read_integers(lines[k + i], v) || v.size() != 1)
                  refuse(k + i, "a node tag line must hold one tag");
                nodes.insert(v[0]);
              }
            for (long long i = 1; i <= n; ++i)
              check_node_line(k + n + i, coordinates(k + n + i));
            k += 1 + 2 * n;
          }
        if (k != node_end ||
            static_cast<long long>(nodes.size()) != n_nodes)
          refuse(k, "the node blocks do not add up to the $Nodes header "
                    "(a stray or missing line, or a repeated tag)");
      }
      // $Elements: "n_blocks n_elements min max", per block "dim tag type
      // n", n lines "tag nodes...".
      if (!read_integers(lines[element_begin + 1], v) || v.size() != 4 ||
          v[0] < 0)
        refuse(element_begin + 1,
               "$Elements must start with 'blocks elements min max'");
      {
        const long long n_blocks = v[0], n_elements = v[1];
        long long       counted  = 0;
        std::size_t     k        = element_begin + 2;
        for (long long b = 0; b < n_blocks; ++b)
          {
            if (k >= element_end || !read_integers(lines[k], v) ||
                v.size() != 4 || v[0] < 0 || v[0] > 3 || v[3] < 0 ||
                v[3] >= static_cast<long long>(element_end - k))
              refuse(k, "an element block header must read 'dimension (0-3) "
                        "tag type count' with its elements following");
            const int       n     = nodes_of_type(k, v[2]);
            const long long count = v[3];
            for (long long i = 1; i <= count; ++i)
              {
                if (!read_integers(lines[k + i], v) ||
                    static_cast<long long>(v.size()) != 1 + n)
                  refuse(k + i, "an element line must hold its tag and " +
                                  std::to_string(n) + " nodes");
                for (int j = 1; j <= n; ++j)
                  check_node_reference(k + i, v[j]);
              }
            counted += count;
            k += 1 + count;
          }
        if (k != element_end || counted != n_elements)
          refuse(k, "the element blocks do not add up to the $Elements "
                    "header (a stray or missing line?)");
      }
    }

    /**
     * deal.II gives each boundary face one boundary id. A Gmsh curve in two
     * physical groups (`bottom` and `boundary`, common practice) is written
     * by MSH 2.2 as one line element per group, and deal.II keeps whichever
     * comes last: Dirichlet data would then hold some nodes only. Our rule,
     * for both versions: a boundary face carries one name, and a file that
     * gives one two is refused with the face (2.2) or curve (4.1) named.
     */
    void
    check_one_name_per_face(const std::vector<std::string> &lines,
                            const bool                      version_2,
                            const std::map<int, std::string> &group_name,
                            const std::string              &file,
                            const std::string              &entry)
    {
      const auto name_of = [&](const int tag) {
        const auto it = group_name.find(tag);
        return it == group_name.end() ? "physical tag " + std::to_string(tag) :
                                        "'" + it->second + "'";
      };
      const auto refuse = [&](const std::string &what, const int a,
                              const int b) {
        throw InputError(entry,
                         "'" + file + "': " + what +
                           " belongs to two physical groups, " + name_of(a) +
                           " and " + name_of(b) +
                           "; glissade gives each boundary face one name. "
                           "Keep one group per curve (list several names in "
                           "the .prm entry instead, e.g. 'Fixed = bottom: y; "
                           "side: x')");
      };
      if (version_2)
        {
          // "id type n_tags physical elementary ... nodes"; type 1: a line.
          std::map<std::pair<long, long>, int> face_group;
          std::size_t begin = 0;
          while (begin < lines.size() && lines[begin] != "$Elements")
            ++begin;
          for (std::size_t k = begin + 2;
               k < lines.size() && lines[k] != "$EndElements";
               ++k)
            {
              std::istringstream line(lines[k]);
              long               id = 0, type = 0, n_tags = 0;
              line >> id >> type >> n_tags;
              if (type != 1 || n_tags < 1)
                continue;
              long physical = 0, tag = 0, a = 0, b = 0;
              line >> physical;
              for (long t = 1; t < n_tags; ++t)
                line >> tag;
              line >> a >> b;
              if (!line)
                continue; // deal.II's reader reports malformed lines
              const auto key = std::minmax(a, b);
              const auto [it, inserted] =
                face_group.emplace(key, static_cast<int>(physical));
              if (!inserted && it->second != physical)
                refuse("the boundary line between nodes " +
                         std::to_string(a) + " and " + std::to_string(b),
                       it->second,
                       static_cast<int>(physical));
            }
          return;
        }
      // Version 4: "$Entities", then "n_points n_curves n_surfaces
      // n_volumes", the points ("tag x y z n_physical tags..."), then the
      // curves ("tag 6 x bounds n_physical tags... n_bounding ...").
      std::size_t begin = 0;
      while (begin < lines.size() && lines[begin] != "$Entities")
        ++begin;
      if (begin + 1 >= lines.size())
        return;
      std::istringstream counts(lines[begin + 1]);
      long               n_points = 0, n_curves = 0;
      counts >> n_points >> n_curves;
      for (long c = 0; c < n_curves; ++c)
        {
          const std::size_t k = begin + 2 + n_points + c;
          if (k >= lines.size() || lines[k] == "$EndEntities")
            return;
          std::istringstream line(lines[k]);
          long               tag = 0, n_physical = 0;
          double             bound = 0.;
          line >> tag;
          for (unsigned int i = 0; i < 6; ++i)
            line >> bound;
          line >> n_physical;
          if (line && n_physical > 1)
            {
              long first = 0, second = 0;
              line >> first >> second;
              refuse("curve " + std::to_string(tag),
                     static_cast<int>(first),
                     static_cast<int>(second));
            }
        }
    }
  } // namespace



  BoundaryNames
  MeshFactory::read_gmsh(const MeshDescription &description,
                         Triangulation<2>      &triangulation,
                         const std::string     &where)
  {
    const std::string entry = where + "/Mesh/File";
    // A device (/dev/zero) would be read until memory runs out; a missing
    // file is reported below.
    std::error_code missing;
    if (std::filesystem::exists(description.file, missing) &&
        !text::is_regular_file_of_at_most(description.file, 1ull << 31))
      throw InputError(entry,
                       "'" + description.file +
                         "' is not a regular file of at most 2 GiB: not "
                         "a Gmsh mesh");
    std::ifstream     file(description.file);
    if (!file)
      throw InputError(entry,
                       "cannot open mesh file '" + description.file + "'");
    std::stringstream text;
    text << file.rdbuf();
    std::vector<std::string> lines;
    {
      std::istringstream in(text.str());
      for (std::string line; std::getline(in, line);)
        {
          while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
            line.pop_back();
          lines.push_back(line);
        }
    }
    const bool version_2 =
      check_gmsh_structure(lines, description.file, entry);
    check_gmsh_records(lines, version_2, description.file, entry);

    // deal.II turns the physical tag of each boundary line into its boundary
    // id; the names are in the $PhysicalNames section, which we read here.
    BoundaryNames names;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i] == "$PhysicalNames")
        {
          for (std::size_t k = i + 2;
               k < lines.size() && lines[k] != "$EndPhysicalNames";
               ++k)
            {
              std::istringstream line(lines[k]);
              int                dimension = -1, tag = -1;
              std::string        name;
              line >> dimension >> tag;
              std::getline(line, name);
              const auto q0 = name.find('"');
              const auto q1 = name.rfind('"');
              if (dimension == 1 && tag >= 0 &&
                  static_cast<unsigned int>(tag) <
                    numbers::internal_face_boundary_id &&
                  q0 != std::string::npos && q1 > q0)
                names[name.substr(q0 + 1, q1 - q0 - 1)] =
                  static_cast<types::boundary_id>(tag);
            }
          break;
        }
    {
      std::map<int, std::string> group_name;
      for (const auto &[name, id] : names)
        group_name[id] = name;
      check_one_name_per_face(lines, version_2, group_name, description.file, entry);
    }

    try
      {
        std::istringstream in(text.str());
        GridIn<2>          grid_in;
        grid_in.attach_triangulation(triangulation);
        grid_in.read_msh(in);
      }
    catch (const std::exception &e)
      {
        throw InputError(entry,
                         "cannot read '" + description.file +
                           "' as a Gmsh mesh of quadrilaterals");
      }
    if (!triangulation.all_reference_cells_are_hyper_cube())
      throw InputError(entry,
                       "'" + description.file +
                         "' has non-quadrilateral cells; glissade needs "
                         "quadrilaterals (Recombine in Gmsh)");
    return names;
  }
} // namespace glissade

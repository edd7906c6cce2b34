#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/mesh/gmsh_reader.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace glissade
{
  using namespace dealii;

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
      const std::size_t format     = find("$MeshFormat", 0);
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
      const bool  version_2 = version.rfind("2.", 0) == 0;
      std::size_t from      = format_end;
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
          if (declared < 0 ||
              (version_2 ? declared != present : declared > present))
            throw InputError(
              entry,
              "'" + file + "' declares " + std::to_string(declared) + " " +
                (section == std::string("Nodes") ? "nodes" : "elements") +
                " but its $" + section + " section has " +
                std::to_string(std::max(present, 0ll)) + " lines");
        }
      return version_2;
    }

    /** Nodes per element of the Gmsh element types deal.II may meet. */
    int
    gmsh_nodes_per_element(const long type)
    {
      switch (type)
        {
          case 1:
            return 2; // line
          case 2:
            return 3; // triangle
          case 3:
            return 4; // quadrangle
          case 4:
            return 4; // tetrahedron
          case 5:
            return 8; // hexahedron
          case 8:
            return 3; // second-order line
          case 9:
            return 6; // second-order triangle
          case 10:
            return 9; // second-order quadrangle
          case 15:
            return 1; // point
          case 16:
            return 8; // serendipity quadrangle
          default:
            return -1;
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
          char           *end = nullptr;
          const long long v   = std::strtoll(field.c_str(), &end, 10);
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
     * declared nodes, coordinates must be finite and z zero. The checks
     * of one line are members; check_gmsh_records() runs them over the
     * sections of the file's version.
     */
    class GmshRecordCheck
    {
    public:
      GmshRecordCheck(const std::vector<std::string> &lines,
                      const std::string              &file,
                      const std::string              &entry)
        : lines(lines)
        , file(file)
        , entry(entry)
      {}

      /**
       * MSH 2.2: $Nodes "N", then N lines "tag x y z"; $Elements the same
       * with lines "id type n_tags tags... nodes...".
       */
      void
      check_version_2();

      /**
       * MSH 4.1, $Entities if present: "n_points n_curves n_surfaces
       * n_volumes" and one line per entity.
       */
      void
      check_entities();

      /**
       * MSH 4.1, $Nodes: "n_blocks n_nodes min max", per block "dim tag
       * parametric n", n tags, n coordinate lines.
       */
      void
      check_nodes_4();

      /**
       * MSH 4.1, $Elements: "n_blocks n_elements min max", per block "dim
       * tag type n", n lines "tag nodes..." (after $Nodes: the tags they
       * name must be known).
       */
      void
      check_elements_4();

    private:
      /** Throws the InputError of the file's line `line` (from 0). */
      [[noreturn]] void
      refuse(const std::size_t line, const std::string &what) const;

      /** The lines of $name and $Endname; both lines.size() if absent. */
      std::pair<std::size_t, std::size_t>
      section(const std::string &name) const;

      /** The numbers of line k, each finite. */
      std::vector<double>
      coordinates(const std::size_t k) const;

      /** A node's x, y, z on line k: three of them, in the plane z = 0. */
      void
      check_node_line(const std::size_t k, const std::vector<double> &x) const;

      /** The nodes of an element of Gmsh's type `type` on line k. */
      int
      nodes_of_type(const std::size_t k, const long long type) const;

      /** A node that an element on line k names: one of $Nodes. */
      void
      check_node_reference(const std::size_t k, const long long tag) const;

      const std::vector<std::string> &lines;
      const std::string              &file;
      const std::string              &entry;
      /** The tags of the nodes declared so far. */
      std::set<long long> nodes;
      /** The integers of the line being read. */
      std::vector<long long> v;
    };

    void
    GmshRecordCheck::check_version_2()
    {
      const auto [node_begin, node_end]       = section("Nodes");
      const auto [element_begin, element_end] = section("Elements");
      for (std::size_t k = node_begin + 2; k < node_end; ++k)
        {
          const std::vector<double> x = coordinates(k);
          if (x.size() != 4)
            refuse(k, "a node line must read 'tag x y z'");
          check_node_line(k, {x[1], x[2], x[3]});
          nodes.insert(static_cast<long long>(x[0]));
        }
      for (std::size_t k = element_begin + 2; k < element_end; ++k)
        {
          if (!read_integers(lines[k], v) || v.size() < 3)
            refuse(k,
                   "an element line must read 'id type n_tags tags... "
                   "nodes...'");
          const int n = nodes_of_type(k, v[1]);
          if (v[2] < 0 || static_cast<long long>(v.size()) != 3 + v[2] + n)
            refuse(k,
                   "the element's number of tags and of nodes do not "
                   "match its line");
          for (long long i = 3 + v[2]; i < static_cast<long long>(v.size());
               ++i)
            check_node_reference(k, v[i]);
        }
    }

    void
    GmshRecordCheck::check_entities()
    {
      const auto [entity_begin, entity_end] = section("Entities");
      if (entity_begin == lines.size())
        return;
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

    void
    GmshRecordCheck::check_nodes_4()
    {
      const auto [node_begin, node_end] = section("Nodes");
      if (!read_integers(lines[node_begin + 1], v) || v.size() != 4 || v[0] < 0)
        refuse(node_begin + 1, "$Nodes must start with 'blocks nodes min max'");
      const long long n_blocks = v[0], n_nodes = v[1];
      std::size_t     k = node_begin + 2;
      for (long long b = 0; b < n_blocks; ++b)
        {
          if (k >= node_end || !read_integers(lines[k], v) || v.size() != 4 ||
              v[0] < 0 || v[0] > 3 || v[2] != 0 || v[3] < 0 ||
              2 * v[3] >= static_cast<long long>(node_end - k))
            refuse(k,
                   "a node block header must read 'dimension (0-3) tag "
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
      if (k != node_end || static_cast<long long>(nodes.size()) != n_nodes)
        refuse(k,
               "the node blocks do not add up to the $Nodes header "
               "(a stray or missing line, or a repeated tag)");
    }

    void
    GmshRecordCheck::check_elements_4()
    {
      const auto [element_begin, element_end] = section("Elements");
      if (!read_integers(lines[element_begin + 1], v) || v.size() != 4 ||
          v[0] < 0)
        refuse(element_begin + 1,
               "$Elements must start with 'blocks elements min max'");
      const long long n_blocks = v[0], n_elements = v[1];
      long long       counted = 0;
      std::size_t     k       = element_begin + 2;
      for (long long b = 0; b < n_blocks; ++b)
        {
          if (k >= element_end || !read_integers(lines[k], v) ||
              v.size() != 4 || v[0] < 0 || v[0] > 3 || v[3] < 0 ||
              v[3] >= static_cast<long long>(element_end - k))
            refuse(k,
                   "an element block header must read 'dimension (0-3) "
                   "tag type count' with its elements following");
          const int       n     = nodes_of_type(k, v[2]);
          const long long count = v[3];
          for (long long i = 1; i <= count; ++i)
            {
              if (!read_integers(lines[k + i], v) ||
                  static_cast<long long>(v.size()) != 1 + n)
                refuse(k + i,
                       "an element line must hold its tag and " +
                         std::to_string(n) + " nodes");
              for (int j = 1; j <= n; ++j)
                check_node_reference(k + i, v[j]);
            }
          counted += count;
          k += 1 + count;
        }
      if (k != element_end || counted != n_elements)
        refuse(k,
               "the element blocks do not add up to the $Elements "
               "header (a stray or missing line?)");
    }

    void
    GmshRecordCheck::refuse(const std::size_t  line,
                            const std::string &what) const
    {
      throw InputError(entry,
                       "'" + file + "', line " + std::to_string(line + 1) +
                         ": " + what);
    }

    std::pair<std::size_t, std::size_t>
    GmshRecordCheck::section(const std::string &name) const
    {
      std::size_t begin = 0;
      while (begin < lines.size() && lines[begin] != "$" + name)
        ++begin;
      std::size_t end = begin;
      while (end < lines.size() && lines[end] != "$End" + name)
        ++end;
      return std::make_pair(begin, end);
    }

    std::vector<double>
    GmshRecordCheck::coordinates(const std::size_t k) const
    {
      std::istringstream  in(lines[k]);
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
    }

    void
    GmshRecordCheck::check_node_line(const std::size_t          k,
                                     const std::vector<double> &x) const
    {
      if (x.size() < 3)
        refuse(k, "a node needs x, y and z");
      if (x[2] != 0.)
        refuse(k,
               "a node has z = " + std::to_string(x[2]) +
                 ": glissade's meshes lie in the plane z = 0");
    }

    int
    GmshRecordCheck::nodes_of_type(const std::size_t k,
                                   const long long   type) const
    {
      const int n = gmsh_nodes_per_element(type);
      if (n < 0)
        refuse(k,
               "element type " + std::to_string(type) +
                 " is not a Gmsh element glissade knows");
      return n;
    }

    void
    GmshRecordCheck::check_node_reference(const std::size_t k,
                                          const long long   tag) const
    {
      if (!nodes.count(tag))
        refuse(k,
               "the element names node " + std::to_string(tag) +
                 ", which $Nodes does not declare");
    }

    void
    check_gmsh_records(const std::vector<std::string> &lines,
                       const bool                      version_2,
                       const std::string              &file,
                       const std::string              &entry)
    {
      GmshRecordCheck check(lines, file, entry);
      if (version_2)
        check.check_version_2();
      else
        {
          check.check_entities();
          check.check_nodes_4();
          check.check_elements_4();
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
    check_one_name_per_face(const std::vector<std::string>   &lines,
                            const bool                        version_2,
                            const std::map<int, std::string> &group_name,
                            const std::string                &file,
                            const std::string                &entry)
    {
      const auto name_of = [&](const int tag) {
        const auto it = group_name.find(tag);
        return it == group_name.end() ? "physical tag " + std::to_string(tag) :
                                        "'" + it->second + "'";
      };
      const auto refuse =
        [&](const std::string &what, const int a, const int b) {
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
          std::size_t                          begin = 0;
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
                refuse("the boundary line between nodes " + std::to_string(a) +
                         " and " + std::to_string(b),
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

    /**
     * Second-order geometry: the edges of second-order quadrilaterals whose
     * mid-side node is off the chord's midpoint, as parabolas through
     * (a, m, b). MappingQ(p) of a quadratic or higher element space asks a
     * line's manifold for its support points; this one answers on the
     * parabola, and the cell interiors follow by deal.II's transfinite
     * blend of the four edges. (Gmsh's centre node of a 9-node quadrilateral
     * is that blend for the meshes it makes: it is not read.)
     */
    class SecondOrderEdges : public Manifold<2>
    {
    public:
      struct Edge
      {
        Point<2> a, b, mid;
      };

      explicit SecondOrderEdges(const std::vector<Edge> &edges)
      {
        for (const Edge &e : edges)
          midpoints[key(e.a, e.b)] = e.mid;
      }

      std::unique_ptr<Manifold<2>>
      clone() const override
      {
        return std::make_unique<SecondOrderEdges>(*this);
      }

      Point<2>
      get_new_point(const ArrayView<const Point<2>> &points,
                    const ArrayView<const double>   &weights) const override
      {
        if (points.size() == 2)
          {
            const auto it = midpoints.find(key(points[0], points[1]));
            if (it != midpoints.end())
              {
                // The parabola through a (s = 0), m (s = 1/2), b (s = 1);
                // symmetric in (a, s) <-> (b, 1 - s).
                const double s = weights[1];
                return Point<2>(points[0] * ((1. - s) * (1. - 2. * s)) +
                                it->second * (4. * s * (1. - s)) +
                                points[1] * (s * (2. * s - 1.)));
              }
          }
        Point<2> p;
        for (unsigned int i = 0; i < points.size(); ++i)
          p += weights[i] * points[i];
        return p;
      }

      /** True if a curved edge joins a and b (either way round). */
      bool
      is_curved(const Point<2> &a, const Point<2> &b) const
      {
        return midpoints.count(key(a, b)) > 0;
      }

    private:
      using Key = std::pair<std::array<double, 2>, std::array<double, 2>>;

      static Key
      key(const Point<2> &a, const Point<2> &b)
      {
        const std::array<double, 2> x{{a[0], a[1]}}, y{{b[0], b[1]}};
        return x < y ? Key(x, y) : Key(y, x);
      }

      std::map<Key, Point<2>> midpoints;
    };

    /** What the elements of a file are, counted before deal.II reads it. */
    struct ElementCensus
    {
      long long                           surface_elements = 0;
      long long                           triangles        = 0;
      long long                           second_order     = 0;
      std::vector<SecondOrderEdges::Edge> curved_edges;
    };

    /**
     * Counts the surface elements and rewrites second-order ones in place as
     * first-order ones deal.II reads (types 10 and 16 as 3 on their corners,
     * 8 as 1), keeping their curved edges. The records were checked by
     * check_gmsh_records.
     */
    ElementCensus
    take_element_census(std::vector<std::string> &lines, const bool version_2)
    {
      const auto section = [&](const std::string &name) {
        std::size_t begin = 0;
        while (lines[begin] != "$" + name)
          ++begin;
        std::size_t end = begin;
        while (lines[end] != "$End" + name)
          ++end;
        return std::make_pair(begin, end);
      };
      std::map<long long, Point<2>> node;
      std::vector<long long>        v;
      const auto [node_begin, node_end] = section("Nodes");
      if (version_2)
        for (std::size_t k = node_begin + 2; k < node_end; ++k)
          {
            std::istringstream in(lines[k]);
            long long          tag = 0;
            double             x = 0., y = 0.;
            in >> tag >> x >> y;
            node[tag] = Point<2>(x, y);
          }
      else
        for (std::size_t k = node_begin + 2; k < node_end;)
          {
            read_integers(lines[k], v);
            const long long n = v[3];
            for (long long i = 1; i <= n; ++i)
              {
                read_integers(lines[k + i], v);
                std::istringstream in(lines[k + n + i]);
                double             x = 0., y = 0.;
                in >> x >> y;
                node[v[0]] = Point<2>(x, y);
              }
            k += 1 + 2 * n;
          }

      ElementCensus census;
      // The nodes of one element (corners first, Gmsh's order); returns
      // how many to keep.
      const auto visit = [&](const long long               type,
                             const std::vector<long long> &nodes) -> int {
        if (type == 2 || type == 9)
          ++census.triangles;
        if (type == 2 || type == 3 || type == 9 || type == 10 || type == 16)
          ++census.surface_elements;
        if (type == 8)
          return 2;
        if (type == 10 || type == 16)
          {
            ++census.second_order;
            for (unsigned int e = 0; e < 4; ++e)
              {
                const Point<2> a = node[nodes[e]], b = node[nodes[(e + 1) % 4]],
                               m = node[nodes[4 + e]];
                if ((m - 0.5 * (a + b)).norm() > 1e-12 * (b - a).norm())
                  census.curved_edges.push_back({a, b, m});
              }
            return 4;
          }
        return static_cast<int>(nodes.size());
      };
      const auto first_order_type = [](const long long type) {
        return type == 8 ? 1ll : (type == 10 || type == 16) ? 3ll : type;
      };
      const auto join = [](const std::vector<long long> &values,
                           const std::size_t             count) {
        std::string line;
        for (std::size_t i = 0; i < count; ++i)
          line += (i ? " " : "") + std::to_string(values[i]);
        return line;
      };

      const auto [element_begin, element_end] = section("Elements");
      if (version_2)
        for (std::size_t k = element_begin + 2; k < element_end; ++k)
          {
            // "id type n_tags tags... nodes..."
            read_integers(lines[k], v);
            const std::size_t first_node = 3 + v[2];
            const int         keep =
              visit(v[1],
                    std::vector<long long>(v.begin() + first_node, v.end()));
            if (first_order_type(v[1]) != v[1])
              {
                v[1]     = first_order_type(v[1]);
                lines[k] = join(v, first_node + keep);
              }
          }
      else
        for (std::size_t k = element_begin + 2; k < element_end;)
          {
            // "dimension tag type count", then "tag nodes..." lines.
            read_integers(lines[k], v);
            const long long type = v[2], count = v[3];
            if (first_order_type(type) != type)
              {
                v[2]     = first_order_type(type);
                lines[k] = join(v, 4);
              }
            for (long long i = 1; i <= count; ++i)
              {
                read_integers(lines[k + i], v);
                const int keep =
                  visit(type, std::vector<long long>(v.begin() + 1, v.end()));
                if (first_order_type(type) != type)
                  lines[k + i] = join(v, 1 + keep);
              }
            k += 1 + count;
          }
      return census;
    }
  } // namespace



  MeshLabels
  read_gmsh(const std::string &file_name,
            Triangulation<2>  &triangulation,
            const std::string &entry)
  {
    // A device (/dev/zero) would be read until memory runs out; a missing
    // file is reported below.
    std::error_code missing;
    if (std::filesystem::exists(file_name, missing) &&
        !text::is_regular_file_of_at_most(file_name, 1ull << 31))
      throw InputError(entry,
                       "'" + file_name +
                         "' is not a regular file of at most 2 GiB: not "
                         "a Gmsh mesh");
    std::ifstream file(file_name);
    if (!file)
      throw InputError(entry, "cannot open mesh file '" + file_name + "'");
    std::vector<std::string> lines;
    for (std::string line; std::getline(file, line);)
      {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
          line.pop_back();
        lines.push_back(line);
      }
    const bool version_2 = check_gmsh_structure(lines, file_name, entry);
    check_gmsh_records(lines, version_2, file_name, entry);

    // deal.II turns the physical tag of each boundary line into its boundary
    // id and that of each cell into its material id; the names are in the
    // $PhysicalNames section, which we read here.
    MeshLabels labels;
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
              if (tag < 0 || q0 == std::string::npos || q1 <= q0)
                continue;
              name = name.substr(q0 + 1, q1 - q0 - 1);
              if (dimension == 1 && static_cast<unsigned int>(tag) <
                                      numbers::internal_face_boundary_id)
                labels.boundaries[name] = static_cast<types::boundary_id>(tag);
              if (dimension == 2 &&
                  static_cast<unsigned int>(tag) < numbers::invalid_material_id)
                labels.regions[name] = static_cast<types::material_id>(tag);
            }
          break;
        }
    {
      std::map<int, std::string> group_name;
      for (const auto &[name, id] : labels.boundaries)
        group_name[id] = name;
      check_one_name_per_face(lines, version_2, group_name, file_name, entry);
    }

    const ElementCensus census = take_element_census(lines, version_2);
    if (census.surface_elements == 0)
      throw InputError(entry,
                       "'" + file_name +
                         "' has no surface elements, only points and "
                         "curves. When a .geo file defines physical groups, "
                         "Gmsh saves only their elements: add a Physical "
                         "Surface for the body (or set Mesh.SaveAll = 1)");
    if (census.triangles > 0)
      throw InputError(entry,
                       "'" + file_name + "' has " +
                         std::to_string(census.triangles) +
                         " triangles; glissade needs quadrilaterals "
                         "(Recombine Surface in Gmsh, or "
                         "Mesh.RecombineAll = 1)");
    labels.second_order = census.second_order > 0;

    try
      {
        std::string text;
        for (const std::string &line : lines)
          text += line + '\n';
        std::istringstream in(text);
        GridIn<2>          grid_in;
        grid_in.attach_triangulation(triangulation);
        grid_in.read_msh(in);
      }
    catch (const std::exception &e)
      {
        throw InputError(entry,
                         "cannot read '" + file_name +
                           "' as a Gmsh mesh of quadrilaterals: " +
                           text::essential_message(e));
      }

    if (!census.curved_edges.empty())
      {
        const SecondOrderEdges edges(census.curved_edges);
        // Manifold id 1 on the lines with a curved mid-side node (the
        // cells keep the flat default).
        const types::manifold_id curved = 1;
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            {
              const auto face = cell->face(f);
              if (edges.is_curved(face->vertex(0), face->vertex(1)))
                face->set_manifold_id(curved);
            }
        triangulation.set_manifold(curved, edges);
      }
    return labels;
  }
} // namespace glissade

// The kinds of mesh a .prm may name (Mesh/Type), each with the entries
// of its shape, which it declares and reads itself (the generic
// MeshDescription keeps Type, Subdivisions, File and Distortion), and its
// construction.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/mesh/gmsh_reader.h>
#include <glissade/mesh/graded_intervals.h>
#include <glissade/mesh/mesh_factory.h>
#include <glissade/mesh/nurbs_patch_file.h>

#include <any>
#include <cmath>
#include <string>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** rectangle: Corner 1, Corner 2. */
    struct RectangleShape
    {
      Point<2> corner_1, corner_2;
    };

    /** square: Center, Side. */
    struct SquareShape
    {
      Point<2> center;
      double   side = 1.;
    };

    /** half ring, ring: Center, the radii, the angles (half ring). */
    struct RingShape
    {
      Point<2> center;
      double   inner_radius = 0.5, outer_radius = 1.;
      double   start_angle = 0., end_angle = 180.; // degrees
    };

    Point<2>
    point_entry(const ParameterHandler &prm,
                const std::string      &entry,
                const std::string      &where)
    {
      const auto x =
        text::coordinates(prm.get(entry), where + "/Mesh/" + entry);
      return Point<2>(x[0], x[1]);
    }

    // Entries that several kinds read are declared by each of them with
    // the same text (deal.II lets an entry be declared again).
    void
    declare_center(ParameterHandler &prm)
    {
      prm.declare_entry("Center",
                        "0, 0",
                        Patterns::Anything(),
                        "square, rings: centre 'x, y'.");
    }

    void
    declare_radii_and_angles(ParameterHandler &prm)
    {
      declare_center(prm);
      prm.declare_entry("Inner radius",
                        "0.5",
                        Patterns::Double(0.),
                        "rings: inner radius.");
      prm.declare_entry("Outer radius",
                        "1",
                        Patterns::Double(0.),
                        "rings: outer radius.");
      prm.declare_entry("Start angle",
                        "0",
                        Patterns::Double(),
                        "half ring: angle of the 'start' end, in degrees.");
      prm.declare_entry("End angle",
                        "180",
                        Patterns::Double(),
                        "half ring: angle of the 'end' end, in degrees.");
    }

    /**
     * The half ring's angles, set on another kind: a user who turns a
     * ring by its Start angle would see nothing happen.
     */
    void
    refuse_angles(const ParameterHandler &prm,
                  const std::string      &type,
                  const std::string      &where)
    {
      const double start = prm.get_double("Start angle"),
                   end   = prm.get_double("End angle");
      if (start != 0. || end != 180.)
        throw InputError(where + "/Mesh/" +
                           (start != 0. ? "Start angle" : "End angle"),
                         "applies to Type = half ring only (this mesh is a " +
                           type +
                           "); to turn a body, use Boundary conditions/"
                           "Prescribed rotation");
    }

    RingShape
    parse_ring(const ParameterHandler &prm,
               const std::string      &where,
               const bool              half)
    {
      RingShape ring;
      ring.center       = point_entry(prm, "Center", where);
      ring.inner_radius = prm.get_double("Inner radius");
      ring.outer_radius = prm.get_double("Outer radius");
      ring.start_angle  = prm.get_double("Start angle");
      ring.end_angle    = prm.get_double("End angle");
      if (!(ring.outer_radius > ring.inner_radius && ring.inner_radius > 0))
        throw InputError(where + "/Mesh/Outer radius",
                         "rings need 0 < Inner radius < Outer radius");
      if (!half)
        refuse_angles(prm, "ring", where);
      else if (!(ring.end_angle > ring.start_angle &&
                 ring.end_angle - ring.start_angle < 360.))
        throw InputError(where + "/Mesh/End angle",
                         "must be larger than Start angle, by less than "
                         "360");
      return ring;
    }

    BoundaryNames
    create_rectangle(const Point<2>        &lower_left,
                     const Point<2>        &upper_right,
                     const MeshDescription &description,
                     Triangulation<2>      &triangulation)
    {
      // colorize = true numbers the sides 0 (x = x0), 1 (x = x1), 2 (y = y0)
      // and 3 (y = y1); the steps as Mesh/Grading asks (equal by default).
      std::vector<std::vector<double>> steps(2);
      for (unsigned int d = 0; d < 2; ++d)
        {
          const std::vector<double> ends =
            graded_interval_ends(description.subdivisions[d],
                                 description.grading[d]);
          for (unsigned int i = 0; i + 1 < ends.size(); ++i)
            steps[d].push_back((ends[i + 1] - ends[i]) *
                               (upper_right[d] - lower_left[d]));
        }
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, steps, lower_left, upper_right, true);
      return {{"left", 0}, {"right", 1}, {"bottom", 2}, {"top", 3}};
    }



    BoundaryNames
    create_ring(const MeshDescription &description,
                const RingShape       &ring,
                const bool             closed,
                Triangulation<2>      &triangulation)
    {
      const unsigned int n_around  = description.subdivisions[0];
      const unsigned int n_through = description.subdivisions[1];
      const double       r_in      = ring.inner_radius;
      const double       r_out     = ring.outer_radius;
      const double       theta_0 = closed ? 0. : ring.start_angle * M_PI / 180.;
      const double theta_1 = closed ? 2. * M_PI : ring.end_angle * M_PI / 180.;
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
                ring.center +
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
              const double r0 = (face->vertex(0) - ring.center).norm();
              const double r1 = (face->vertex(1) - ring.center).norm();
              if (std::abs(r0 - r_in) < tolerance &&
                  std::abs(r1 - r_in) < tolerance)
                face->set_boundary_id(0);
              else if (std::abs(r0 - r_out) < tolerance &&
                       std::abs(r1 - r_out) < tolerance)
                face->set_boundary_id(1);
              else
                {
                  // A radial end of a half ring: which one, by its angle.
                  const Tensor<1, 2> d = face->center() - ring.center;
                  const Tensor<1, 2> e0({std::cos(theta_0), std::sin(theta_0)});
                  const Tensor<1, 2> e1({std::cos(theta_1), std::sin(theta_1)});
                  const Tensor<1, 2> direction = d / d.norm();
                  face->set_boundary_id(
                    (direction - e0).norm() < (direction - e1).norm() ? 2 : 3);
                }
            }

      triangulation.set_all_manifold_ids(0);
      triangulation.set_manifold(0, PolarManifold<2>(ring.center));

      if (closed)
        return {{"inner", 0}, {"outer", 1}};
      return {{"inner", 0}, {"outer", 1}, {"start", 2}, {"end", 3}};
    }


    /** create_ring's ring as a NURBS patch: xi radial, eta around. */
    NurbsMultipatch
    ring_patch(const MeshDescription &description,
               const bool             closed,
               const unsigned int     degree)
    {
      const auto  &ring = std::any_cast<const RingShape &>(description.shape);
      const double theta_0 = closed ? 0. : ring.start_angle * M_PI / 180.;
      const double theta_1 = closed ? 2. * M_PI : ring.end_angle * M_PI / 180.;
      return NurbsMultipatch(NurbsPatch::annulus(ring.center,
                                                 ring.inner_radius,
                                                 ring.outer_radius,
                                                 theta_0,
                                                 theta_1,
                                                 closed,
                                                 degree,
                                                 description.subdivisions[1],
                                                 description.subdivisions[0]));
    }


    /** The knots of a rectangle's patch: the ends of its graded cells. */
    NurbsMultipatch
    rectangle_patch(const Point<2>        &corner_1,
                    const Point<2>        &corner_2,
                    const MeshDescription &d,
                    const unsigned int     degree)
    {
      return NurbsMultipatch(NurbsPatch::rectangle(
        corner_1,
        corner_2,
        degree,
        graded_interval_ends(d.subdivisions[0], d.grading[0]),
        graded_interval_ends(d.subdivisions[1], d.grading[1])));
    }

    /** Mesh/Grading is for the types whose cells are a grid of intervals. */
    void
    refuse_grading(const MeshDescription &d,
                   const std::string     &type,
                   const std::string     &where)
    {
      if (d.grading[0] != 1. || d.grading[1] != 1.)
        throw InputError(where + "/Mesh/Grading",
                         "applies to Type = rectangle, square and nurbs patch "
                         "(this mesh is a " +
                           type + ")");
    }

    /** A patch file's patch, its elements split as Subdivisions and
     *  Grading ask. */
    NurbsPatchFile
    patch_of_file(const MeshDescription &description, const std::string &where)
    {
      NurbsPatchFile file =
        NurbsPatchFile::read(description.file, where + "/Mesh/File");
      file.refine({{description.subdivisions[0], description.subdivisions[1]}},
                  description.grading);
      return file;
    }
  } // namespace


  const std::vector<MeshFactory::MeshType> &
  MeshFactory::types()
  {
    // One line per kind of mesh.
    static const std::vector<MeshType> list = {
      {"rectangle",
       "from Corner 1 to Corner 2, boundaries left, right, bottom, top",
       false,
       [](ParameterHandler &prm) {
         prm.declare_entry("Corner 1",
                           "0, 0",
                           Patterns::Anything(),
                           "rectangle: lower left corner 'x, y'.");
         prm.declare_entry("Corner 2",
                           "1, 1",
                           Patterns::Anything(),
                           "rectangle: upper right corner 'x, y'.");
       },
       [](const ParameterHandler &prm, const std::string &where) -> std::any {
         RectangleShape shape{point_entry(prm, "Corner 1", where),
                              point_entry(prm, "Corner 2", where)};
         refuse_angles(prm, "rectangle", where);
         if (!(shape.corner_2[0] > shape.corner_1[0] &&
               shape.corner_2[1] > shape.corner_1[1]))
           throw InputError(where + "/Mesh/Corner 2",
                            "must lie above and to the right of Corner 1");
         return shape;
       },
       [](const MeshDescription &, const std::string &) {},
       [](const MeshDescription &d, Triangulation<2> &t, const std::string &) {
         const auto &shape = std::any_cast<const RectangleShape &>(d.shape);
         MeshLabels  labels;
         labels.boundaries =
           create_rectangle(shape.corner_1, shape.corner_2, d, t);
         return labels;
       },
       [](const MeshDescription &d,
          const unsigned int     degree,
          const std::string &) {
         const auto &shape = std::any_cast<const RectangleShape &>(d.shape);
         return rectangle_patch(shape.corner_1, shape.corner_2, d, degree);
       }},
      {"square",
       "centred at Center with side Side, same boundary names",
       false,
       [](ParameterHandler &prm) {
         declare_center(prm);
         prm.declare_entry("Side",
                           "1",
                           Patterns::Double(0.),
                           "square: side length.");
       },
       [](const ParameterHandler &prm, const std::string &where) -> std::any {
         refuse_angles(prm, "square", where);
         return SquareShape{point_entry(prm, "Center", where),
                            prm.get_double("Side")};
       },
       [](const MeshDescription &, const std::string &) {},
       [](const MeshDescription &d, Triangulation<2> &t, const std::string &) {
         const auto        &shape = std::any_cast<const SquareShape &>(d.shape);
         const Tensor<1, 2> half({shape.side / 2, shape.side / 2});
         MeshLabels         labels;
         labels.boundaries =
           create_rectangle(shape.center - half, shape.center + half, d, t);
         return labels;
       },
       [](const MeshDescription &d,
          const unsigned int     degree,
          const std::string &) {
         const auto        &shape = std::any_cast<const SquareShape &>(d.shape);
         const Tensor<1, 2> half({shape.side / 2, shape.side / 2});
         return rectangle_patch(shape.center - half,
                                shape.center + half,
                                d,
                                degree);
       }},
      {"half ring",
       "centred at Center between Inner radius and Outer radius, "
       "boundaries inner, outer, start and end at the Start/End angle",
       false,
       declare_radii_and_angles,
       [](const ParameterHandler &prm, const std::string &where) -> std::any {
         return parse_ring(prm, where, true);
       },
       [](const MeshDescription &d, const std::string &where) {
         refuse_grading(d, "half ring", where);
       },
       [](const MeshDescription &d, Triangulation<2> &t, const std::string &) {
         MeshLabels labels;
         labels.boundaries =
           create_ring(d, std::any_cast<const RingShape &>(d.shape), false, t);
         return labels;
       },
       [](const MeshDescription &d,
          const unsigned int     degree,
          const std::string &) { return ring_patch(d, false, degree); }},
      {"ring",
       "the same closed, boundaries inner and outer",
       false,
       declare_radii_and_angles,
       [](const ParameterHandler &prm, const std::string &where) -> std::any {
         return parse_ring(prm, where, false);
       },
       [](const MeshDescription &d, const std::string &where) {
         refuse_grading(d, "ring", where);
         if (d.subdivisions[0] < 3)
           throw InputError(where + "/Mesh/Subdivisions",
                            "a ring needs at least 3 elements around");
       },
       [](const MeshDescription &d, Triangulation<2> &t, const std::string &) {
         MeshLabels labels;
         labels.boundaries =
           create_ring(d, std::any_cast<const RingShape &>(d.shape), true, t);
         return labels;
       },
       [](const MeshDescription &d,
          const unsigned int     degree,
          const std::string &) { return ring_patch(d, true, degree); }},
      {"nurbs patch",
       "the NURBS patch of the file File, or its patches joined C0 "
       "(doc/user_guide.md, NURBS patch files), one cell per element, each "
       "split into Subdivisions (along xi, eta) by knot insertion; "
       "boundaries xi0, xi1, eta0, eta1 (patch<k>.xi0, ... for several) or "
       "the file's names",
       true,
       [](ParameterHandler &) {},
       [](const ParameterHandler &prm, const std::string &where) -> std::any {
         refuse_angles(prm, "nurbs patch", where);
         return {};
       },
       [](const MeshDescription &d, const std::string &where) {
         if (d.file.empty())
           throw InputError(where + "/Mesh/File",
                            "nurbs patch meshes need a File");
       },
       [](const MeshDescription &d,
          Triangulation<2>      &t,
          const std::string     &where) {
         MeshLabels labels;
         labels.boundaries = patch_of_file(d, where).create_mesh(t);
         return labels;
       },
       [](const MeshDescription &d,
          const unsigned int     degree,
          const std::string     &where) {
         const NurbsPatchFile file  = patch_of_file(d, where);
         const NurbsPatch    &first = file.geometry.patches.front();
         if (first.xi.degree() != degree || first.eta.degree() != degree)
           throw InputError(where + "/Element/Degree",
                            "is " + std::to_string(degree) +
                              ", but the patch of '" + d.file +
                              "' is of degrees " +
                              std::to_string(first.xi.degree()) + ", " +
                              std::to_string(first.eta.degree()) +
                              " (a NURBS body takes its file's degree, the "
                              "same in both directions)");
         return file.geometry;
       }},
      {"gmsh",
       "the .msh file File, whose named physical lines become boundaries",
       true,
       [](ParameterHandler &) {},
       [](const ParameterHandler &prm, const std::string &where) -> std::any {
         refuse_angles(prm, "gmsh", where);
         return {};
       },
       [](const MeshDescription &d, const std::string &where) {
         refuse_grading(d, "gmsh", where);
         if (d.file.empty())
           throw InputError(where + "/Mesh/File", "gmsh meshes need a File");
       },
       [](const MeshDescription &d,
          Triangulation<2>      &t,
          const std::string     &where) {
         return read_gmsh(d.file, t, where + "/Mesh/File");
       },
       // (no exact patch: a Gmsh mesh's geometry is its elements')
       {}}};
    return list;
  }



  void
  MeshFactory::declare_parameters(ParameterHandler &prm)
  {
    for (const MeshType &entry : types())
      entry.declare_parameters(prm);
  }
} // namespace glissade

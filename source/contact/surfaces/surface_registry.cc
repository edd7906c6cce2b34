#include <glissade/base/input_error.h>
#include <glissade/contact/surfaces/composite_surface.h>
#include <glissade/contact/surfaces/surface_registry.h>
#include <glissade/description/scene_description.h>

namespace glissade
{
  using namespace dealii;

  // Each surface's factory, defined in the surface's own file.
  std::unique_ptr<MasterSurface>
  make_faceted_surface(const SurfaceContext &);
  void
  declare_faceted_parameters(ParameterHandler &);
  std::any
  parse_faceted_parameters(const ParameterHandler &,
                           const std::string &,
                           const std::string &);
  std::unique_ptr<MasterSurface>
  make_bspline_surface(const SurfaceContext &);
  std::unique_ptr<MasterSurface>
  make_hermite_surface(const SurfaceContext &);
  std::unique_ptr<MasterSurface>
  make_nurbs_surface(const SurfaceContext &);
  std::unique_ptr<MasterSurface>
  make_line_obstacle(const SurfaceContext &);
  void
  declare_line_parameters(ParameterHandler &);
  std::any
  parse_line_parameters(const ParameterHandler &,
                        const std::string &,
                        const std::string &);
  std::unique_ptr<MasterSurface>
  make_disk_obstacle(const SurfaceContext &);
  std::unique_ptr<MasterSurface>
  make_hole_obstacle(const SurfaceContext &);
  void
  declare_circle_parameters(ParameterHandler &);
  std::any
  parse_disk_parameters(const ParameterHandler &,
                        const std::string &,
                        const std::string &);
  std::any
  parse_hole_parameters(const ParameterHandler &,
                        const std::string &,
                        const std::string &);
  std::unique_ptr<MasterSurface>
  make_casing_obstacle(const SurfaceContext &);
  void
  declare_casing_parameters(ParameterHandler &);
  std::any
  parse_casing_parameters(const ParameterHandler &,
                          const std::string &,
                          const std::string &);
  std::unique_ptr<MasterSurface>
  make_nurbs_curve_obstacle(const SurfaceContext &);
  void
  declare_nurbs_curve_parameters(ParameterHandler &);
  std::any
  parse_nurbs_curve_parameters(const ParameterHandler &,
                               const std::string &,
                               const std::string &);



  const std::vector<SurfaceRegistry::Entry> &
  SurfaceRegistry::entries()
  {
    // One line per surface.
    static const std::vector<Entry> list = {
      {"faceted",
       Kind::deformable,
       "the element edges (the paper's Q4)",
       make_faceted_surface,
       declare_faceted_parameters,
       parse_faceted_parameters},
      {"bspline",
       Kind::deformable,
       "cubic uniform interpolating B-spline through the master nodes, "
       "closed if the boundary is",
       make_bspline_surface},
      {"hermite",
       Kind::deformable,
       "the C1 edges of a master body of Hermite elements",
       make_hermite_surface},
      {"nurbs",
       Kind::deformable,
       "the exact boundary of a master body of NURBS elements (Element/Space "
       "= nurbs), C^(p-1) along a side of its patch",
       make_nurbs_surface},
      {"line",
       Kind::rigid,
       "the half-plane behind a line (Point, Normal)",
       make_line_obstacle,
       declare_line_parameters,
       parse_line_parameters},
      {"disk",
       Kind::rigid,
       "a solid disk (Point its centre, Radius)",
       make_disk_obstacle,
       declare_circle_parameters,
       parse_disk_parameters},
      {"hole",
       Kind::rigid,
       "the outside of a circular hole (Point its centre, Radius)",
       make_hole_obstacle,
       declare_circle_parameters,
       parse_hole_parameters},
      {"casing",
       Kind::rigid,
       "the inside of a casing ovalised into lobes (Point its centre, "
       "Radius, Lobes, Lobe depth), e.g. about a turning blade",
       make_casing_obstacle,
       declare_casing_parameters,
       parse_casing_parameters},
      {"nurbs curve",
       Kind::rigid,
       "a rigid body bounded by the NURBS curve of Curve file (exact: a "
       "circle, an ellipse, a die's rounded profile), moved by Motion and "
       "Rotation about Point; walking along the curve, the obstacle is on "
       "the right",
       make_nurbs_curve_obstacle,
       declare_nurbs_curve_parameters,
       parse_nurbs_curve_parameters},
    };
    return list;
  }



  std::unique_ptr<MasterSurface>
  SurfaceRegistry::create(const SurfaceContext &context)
  {
    const Kind         kind = context.master ? Kind::deformable : Kind::rigid;
    const std::string &name = kind == Kind::deformable ?
                                context.description.surface :
                                context.description.obstacle;
    for (const auto &entry : entries())
      if (entry.kind == kind && entry.name == name)
        {
          if (kind == Kind::rigid)
            return entry.create(context);
          // A boundary of several curves (a body with holes): a surface
          // of the pair's kind on each, as one CompositeSurface.
          const unsigned int n_curves =
            MasterChain::build_all(*context.master,
                                   context.description.master_boundary,
                                   context.description.entry +
                                     "/Master boundary")
              .size();
          if (n_curves == 1)
            return entry.create(context);
          std::vector<std::unique_ptr<CurveSurface>> curves;
          for (unsigned int c = 0; c < n_curves; ++c)
            {
              SurfaceContext of_curve                = context;
              of_curve.curve                         = c;
              std::unique_ptr<MasterSurface> surface = entry.create(of_curve);
              Assert(dynamic_cast<CurveSurface *>(surface.get()) != nullptr,
                     ExcMessage("a deformable surface is a CurveSurface"));
              curves.emplace_back(
                static_cast<CurveSurface *>(surface.release()));
            }
          return std::make_unique<CompositeSurface>(std::move(curves));
        }
    throw InputError(context.description.entry + (kind == Kind::deformable ?
                                                    "/Surface" :
                                                    "/Obstacle/Type"),
                     "unknown surface '" + name +
                       "' (known: " + names_as_pattern(kind) + ")");
  }



  void
  SurfaceRegistry::declare_parameters(ParameterHandler &prm, const Kind kind)
  {
    for (const auto &entry : entries())
      if (entry.kind == kind && entry.declare_parameters)
        entry.declare_parameters(prm);
  }



  std::any
  SurfaceRegistry::parse_parameters(const ParameterHandler &prm,
                                    const Kind              kind,
                                    const std::string      &name,
                                    const std::string      &where,
                                    const std::string      &prm_file)
  {
    for (const auto &entry : entries())
      if (entry.kind == kind && entry.name == name && entry.parse_parameters)
        return entry.parse_parameters(prm, where, prm_file);
    return {};
  }



  std::string
  SurfaceRegistry::names_as_pattern(const Kind kind)
  {
    std::string names;
    for (const auto &entry : entries())
      if (entry.kind == kind)
        names += (names.empty() ? "" : "|") + entry.name;
    return names;
  }



  std::string
  SurfaceRegistry::documentation(const Kind kind)
  {
    std::string text;
    for (const auto &entry : entries())
      if (entry.kind == kind)
        text +=
          (text.empty() ? "" : "; ") + entry.name + ": " + entry.description;
    return text + ".";
  }
} // namespace glissade

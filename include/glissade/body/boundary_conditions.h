#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <glissade/body/rigid_motion.h>
#include <glissade/description/scene_description.h>
#include <glissade/fe/element_space.h>
#include <glissade/mesh/mesh_factory.h>

#include <map>
#include <memory>
#include <tuple>
#include <vector>

namespace glissade
{
  /**
   * Where a boundary condition acts: a named boundary of the mesh or one mesh
   * vertex, given as point(x, y). Resolved once against the mesh, so that a
   * name the mesh lacks is reported before anything is computed.
   */
  struct Location
  {
    bool                       is_vertex = false;
    dealii::types::boundary_id boundary  = 0;
    unsigned int               vertex    = 0;
    dealii::Point<2>           point;
    /** A point inside a straight boundary face (point loads only). */
    bool         on_face    = false;
    unsigned int cell_index = 0; // active cell index
    unsigned int face       = 0;
    double       fraction   = 0.; // from the face's vertex 0 to vertex 1
  };

  /**
   * A body's Dirichlet and Neumann data, compiled from the scene description:
   * the muParser expressions are parsed once and evaluated at the load
   * program's time t.
   */
  class BoundaryConditions
  {
  public:
    /** For `body`, whose element space is `space` (what it supports). */
    BoundaryConditions(const BodyDescription          &body,
                       const ElementSpace             &space,
                       const BoundaryNames            &boundary_names,
                       const dealii::Triangulation<2> &triangulation);

    /**
     * Fills `constraints` for a Newton correction: the element space's own
     * constraints, then each Dirichlet relation with the inhomogeneity
     * (target at time t) - (current value), zero after the first iteration
     * of an increment.
     */
    void
    make_constraints(
      const dealii::DoFHandler<2>             &dof_handler,
      const ElementSpace                      &space,
      const double                             time,
      const dealii::Vector<double>            &current_displacement,
      const dealii::AffineConstraints<double> &element_constraints,
      dealii::AffineConstraints<double>       &constraints) const;

    /**
     * The radial dofs of the nodes on the axis of an axisymmetric body:
     * held at u_r = 0 by every make_constraints() (a node on the axis
     * cannot move off it), whatever the Dirichlet data say.
     */
    void
    hold_on_axis(const std::vector<dealii::types::global_dof_index> &dofs)
    {
      axis_dofs = dofs;
    }

    /**
     * How much each Dirichlet relation would be violated by each motion of
     * `basis`: row i, column j is the value that relation i takes (in its
     * homogeneous form) under motion j. A combination of the motions that
     * leaves every row zero is one the supports do not hold.
     */
    std::vector<std::vector<double>>
    support_rows(const dealii::DoFHandler<2>      &dof_handler,
                 const ElementSpace               &space,
                 const std::array<RigidMotion, 3> &basis) const;

    /** Point loads at time t, as a vector of nodal forces. */
    void
    add_point_loads(const dealii::DoFHandler<2> &dof_handler,
                    const ElementSpace          &space,
                    const double                 time,
                    dealii::Vector<double>      &external_forces) const;

    struct SurfaceLoad
    {
      dealii::types::boundary_id           boundary;
      bool                                 is_pressure;
      std::shared_ptr<dealii::Function<2>> function; // time set by the caller
    };

    const std::vector<SurfaceLoad> &
    surface_loads() const
    {
      return loads_on_boundaries;
    }

    /**
     * Resolves "left" or "point(x, y)"; `entry` names the .prm entry. A point
     * must be a mesh vertex, or, if `allow_face_point`, lie on a straight
     * boundary face. `known_diameter`, the mesh's if the caller has it
     * (0: computed here), scales the tolerance of "on a vertex".
     */
    static Location
    resolve(const std::string              &location,
            const BoundaryNames            &boundary_names,
            const dealii::Triangulation<2> &triangulation,
            const std::string              &body_name,
            const std::string              &entry,
            const bool                      allow_face_point = false,
            const double                    known_diameter   = 0.);

    /**
     * For a space whose dofs are not nodal values (NURBS): a vertex
     * location as a point of a boundary face that ends at it (on_face,
     * cell_index, face, fraction 0 or 1), where the element's functions
     * give the displacement there. An input error naming `entry` if the
     * vertex is not on the boundary.
     */
    static void
    locate_on_boundary_face(Location                       &where,
                            const dealii::Triangulation<2> &triangulation,
                            const std::string              &body_name,
                            const std::string              &entry);

    /** A function nonzero at a point: its dof, the displacement component
     *  it moves, its value there. */
    struct FunctionAtPoint
    {
      dealii::types::global_dof_index dof;
      unsigned int                    component;
      double                          value;
    };

    /**
     * The functions nonzero at a point of a boundary face (where.on_face),
     * so that u(X)_c = sum value u(dof) over those of component c: how a
     * point of a space whose dofs are not nodal values is held or loaded.
     */
    static std::vector<FunctionAtPoint>
    functions_at_face_point(const dealii::DoFHandler<2> &dof_handler,
                            const ElementSpace          &space,
                            const Location              &where);

    /** The same at `fraction` along face `face` of `cell`. */
    static std::vector<FunctionAtPoint>
    functions_at_face_point(
      const ElementSpace                                         &space,
      const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
      unsigned int                                                face,
      double                                                      fraction);

    /** The two global value dofs (x, y) at vertex v of a cell. */
    static std::array<dealii::types::global_dof_index, 2>
    cell_vertex_dofs(
      const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
      const unsigned int                                          v,
      const ElementSpace                                         &space);

    /** The two global value dofs (x, y) at a mesh vertex. */
    static std::array<dealii::types::global_dof_index, 2>
    vertex_dofs(const dealii::DoFHandler<2> &dof_handler,
                const ElementSpace          &space,
                const unsigned int           vertex);

  private:
    struct DirichletItem
    {
      Location            where;
      std::array<bool, 2> components;
      bool                all_derivatives;
      /** A symmetry line: the component normal to it (0 x, 1 y), or -1. */
      int                                  symmetry_normal = -1;
      std::shared_ptr<dealii::Function<2>> displacement; // 2 components
      /** n or t supports: each node and the direction held there. */
      std::vector<std::pair<unsigned int, dealii::Tensor<1, 2>>>
        directed_vertices;
    };

    /** A symmetry line's normal component (0 x, 1 y): its boundary's faces
     *  all on one line along y (0) or along x (1), or the entry refused. */
    static int
    symmetry_normal(const Location                 &where,
                    const dealii::Triangulation<2> &tria,
                    const std::string              &body_name,
                    const std::string              &entry);

    /** The nodes of a location and the (unit) direction d with d . u = 0. */
    static std::vector<std::pair<unsigned int, dealii::Tensor<1, 2>>>
    support_directions(const Location                       &where,
                       const DirichletDescription::Direction direction,
                       const dealii::Triangulation<2>       &tria,
                       const std::string                    &body_name,
                       const std::string                    &entry);
    struct PointLoad
    {
      Location                             where;
      std::shared_ptr<dealii::Function<2>> force;
    };

    /**
     * The value dofs of the vertices named by point(x, y) items: finding a
     * vertex's dofs walks the cells, which must not happen at every
     * assembly.
     */
    std::array<dealii::types::global_dof_index, 2>
    cached_vertex_dofs(const dealii::DoFHandler<2> &dof_handler,
                       const ElementSpace          &space,
                       const unsigned int           vertex) const;

    mutable std::map<unsigned int,
                     std::array<dealii::types::global_dof_index, 2>>
      vertex_dof_cache;

    /**
     * functions_at_face_point() of the points that supports and loads
     * name, found once (make_constraints and add_point_loads ask at every
     * iteration; the mesh does not change), by (cell, face, fraction).
     */
    const std::vector<FunctionAtPoint> &
    cached_functions_at(
      const ElementSpace                                         &space,
      const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
      unsigned int                                                face,
      double fraction) const;
    /** The same at a location on a face (where.on_face). */
    const std::vector<FunctionAtPoint> &
    cached_functions_at(const dealii::DoFHandler<2> &dof_handler,
                        const ElementSpace          &space,
                        const Location              &where) const;

    mutable std::map<std::tuple<unsigned int, unsigned int, double>,
                     std::vector<FunctionAtPoint>>
      function_cache;

    /** The space's dofs are nodal values: a vertex has dofs of its own
     *  (not NURBS: its points are held and loaded through the functions
     *  there, functions_at_face_point). */
    bool vertex_has_dofs = true;

    std::vector<DirichletItem>                   dirichlet_items;
    std::vector<dealii::types::global_dof_index> axis_dofs;
    std::vector<PointLoad>                       point_loads;
    std::vector<PointLoad>   nodal_loads; // on every vertex of a boundary
    std::vector<SurfaceLoad> loads_on_boundaries;
  };
} // namespace glissade

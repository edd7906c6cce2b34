#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <glissade/description/scene_description.h>
#include <glissade/mesh/mesh_labels.h>
#include <glissade/mesh/nurbs_multipatch.h>

#include <any>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * Builds a body's triangulation from its MeshDescription: the paper's
   * shapes (rectangle/beam, square, half ring, ring) or a Gmsh file.
   *
   * Curved shapes get a PolarManifold, so that higher-order mappings and
   * elements see the exact circle while Q1 keeps the straight chords of the
   * paper's Q4 meshes. Ring cells are numbered with the radial direction as
   * the first reference coordinate so that every cell is positively
   * oriented.
   */
  class MeshFactory
  {
  public:
    /**
     * One kind of mesh a .prm may name (Mesh/Type): the registry that the
     * entry's pattern and help, the checks of its entries and the
     * construction all read. A new kind is one line in types().
     */
    struct MeshType
    {
      std::string name;
      /** One sentence for the parameter documentation. */
      std::string documentation;
      /** Read from a file (its regions and cell order come from there),
       *  rather than generated from the entries. */
      bool from_file;
      /**
       * Declares the entries of the type's shape in the Mesh subsection
       * (Corner 1, Center, Inner radius, ...), for every body.
       */
      std::function<void(dealii::ParameterHandler &)> declare_parameters;
      /**
       * Reads them for a body of this type and checks them, naming
       * `where`/Mesh/<entry>: the shape its create() finds in
       * MeshDescription::shape.
       */
      std::function<std::any(const dealii::ParameterHandler &,
                             const std::string &where)>
        parse_parameters;
      /**
       * Checks what the generic entries mean for the type (a ring needs
       * three elements around; gmsh, a File).
       */
      std::function<void(const MeshDescription &, const std::string &where)>
        check;
      std::function<MeshLabels(const MeshDescription &,
                               dealii::Triangulation<2> &,
                               const std::string &where)>
        create;
      /**
       * The shape as an exact NURBS patch of the given degree whose knot
       * spans are the cells create() makes, cell k the span (k % n_xi,
       * k / n_xi), each cell's first reference direction along xi (an
       * isogeometric body, Element/Space = nurbs); empty for a type that
       * has none (a Gmsh file).
       */
      std::function<NurbsMultipatch(const MeshDescription &,
                                    unsigned int       degree,
                                    const std::string &where)>
        exact_patch;
    };

    static const std::vector<MeshType> &
    types();

    /** The type named `name` (one of types(): the pattern checked it). */
    static const MeshType &
    type(const std::string &name);

    /** Every type's own entries, in the current (Mesh) subsection. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** "rectangle|square|..." for Patterns::Selection. */
    static std::string
    names_as_pattern();

    /** "rectangle: ...; square: ..." for the parameter documentation. */
    static std::string
    documentation();

    /** `where` names the .prm subsection, for messages. */
    static MeshLabels
    create(const MeshDescription    &description,
           dealii::Triangulation<2> &triangulation,
           const std::string        &where);

  private:
    /** Mesh/Boundary parts: each part's faces under its own name and id. */
    static void
    take_boundary_parts(const MeshDescription    &description,
                        dealii::Triangulation<2> &triangulation,
                        MeshLabels               &labels,
                        const std::string        &where);

    /** Refuses a mesh with a hanging node (a vertex inside another edge). */
    static void
    check_mesh_is_conforming(const dealii::Triangulation<2> &triangulation,
                             const std::string              &where);

    /** Refuses a cell with a zero or negative Jacobian at a corner. */
    static void
    check_cells_are_not_folded(const dealii::Triangulation<2> &triangulation,
                               const std::string              &where);
  };
} // namespace glissade

#pragma once

#include <deal.II/grid/tria.h>

#include <glissade/description/scene_description.h>
#include <glissade/mesh/mesh_labels.h>

#include <map>
#include <string>

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
    /** `where` names the .prm subsection, for messages. */
    static MeshLabels
    create(const MeshDescription    &description,
           dealii::Triangulation<2> &triangulation,
           const std::string        &where);

  private:
    static BoundaryNames
    create_rectangle(const dealii::Point<2>   &lower_left,
                     const dealii::Point<2>   &upper_right,
                     const MeshDescription    &description,
                     dealii::Triangulation<2> &triangulation);

    static BoundaryNames
    create_ring(const MeshDescription    &description,
                const bool                closed,
                dealii::Triangulation<2> &triangulation);

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

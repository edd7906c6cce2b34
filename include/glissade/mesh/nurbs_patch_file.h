#pragma once

#include <deal.II/grid/tria.h>

#include <glissade/mesh/mesh_labels.h>
#include <glissade/mesh/nurbs_patch.h>

#include <array>
#include <string>

namespace glissade
{
  /**
   * A NURBS patch read from a file (Mesh/Type = nurbs patch; the format is
   * in doc/user_guide.md, "NURBS patch files"):
   *
   *   # a comment
   *   degrees 2 2
   *   knots xi 0 0 0 1 1 1
   *   knots eta 0 0 0 1 1 1
   *   control points 3 3
   *   1 0 1                  (x y w, n_xi n_eta lines, xi fastest)
   *   ...
   *   boundary inner xi0     (a name for a side: xi0, xi1, eta0, eta1)
   *
   * Every mistake (a knot vector that decreases or is not open, a weight
   * that is not positive, too few control points for the degree, a patch
   * whose Jacobian is not positive at a Gauss point of an element: inverted
   * or folded) stops with a message naming `entry`, the file, its line or
   * the element.
   */
  struct NurbsPatchFile
  {
    NurbsPatch patch;
    /** The sides' names: xi0, xi1, eta0, eta1 unless the file renames
     *  them. */
    std::array<std::string, 4> side_names = {{"xi0", "xi1", "eta0", "eta1"}};

    static NurbsPatchFile
    read(const std::string &file, const std::string &entry);

    /**
     * Splits every element into `subdivisions` parts in each parameter by
     * knot insertion (the patch unchanged), their parametric lengths in
     * geometric progression, the last `grading` times the first (1: equal
     * parts).
     */
    void
    refine(const std::array<unsigned int, 2> &subdivisions,
           const std::array<double, 2>       &grading = {{1., 1.}});

    /**
     * The mesh of the patch's elements: cell k is span (k % n_xi,
     * k / n_xi), its vertices the patch's points at the knots; the sides
     * get boundary ids 0 (xi0) to 3 (eta1) and their names.
     */
    BoundaryNames
    create_mesh(dealii::Triangulation<2> &mesh) const;
  };
} // namespace glissade

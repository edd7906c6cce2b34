#pragma once

#include <deal.II/grid/tria.h>

#include <glissade/mesh/mesh_labels.h>
#include <glissade/mesh/nurbs_multipatch.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * The lines of a NURBS file without its comments (from #) and blank
   * lines, each with its number; a file that cannot be opened throws an
   * InputError at `where` naming the `kind` of file.
   */
  std::vector<std::pair<unsigned int, std::string>>
  meaningful_lines(const std::string &file,
                   const std::string &kind,
                   const std::string &where);

  /**
   * The checks of a knot vector of degree `degree` read from a file:
   * non-decreasing, open (its ends repeated degree + 1 times), long enough,
   * no inner knot repeated more than degree times (the functions would not
   * be continuous). A mistake throws an InputError at `where` that starts
   * with `label` ("knots xi").
   */
  void
  check_knot_vector(const std::vector<double> &knots,
                    unsigned int               degree,
                    const std::string         &label,
                    const std::string         &where);

  /**
   * Control point k (from 0) of a file, its line `line` "x y w": the
   * numbers, checked (three, finite, w > 0); a mistake throws an
   * InputError at `where` (the file and line).
   */
  std::array<double, 3>
  read_control_point(const std::string &line,
                     unsigned int       k,
                     const std::string &where);

  /**
   * A NURBS body read from a file (Mesh/Type = nurbs patch; the format is
   * in doc/user_guide.md, "NURBS patch files"): one patch,
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
   * or several, each begun by a line `patch`, joined C0 along whole sides
   * (`join 1 xi1 2 xi0`: patch 1's side xi1 is patch 2's side xi0), their
   * boundaries named by patch and side (`boundary outer 1 eta1 2 eta1`).
   *
   * Every mistake (a knot vector that decreases or is not open, a weight
   * that is not positive, too few control points for the degree, a patch
   * whose Jacobian is not positive at a Gauss point of an element: inverted
   * or folded; joined sides that are not the same curve with the same
   * knots, patches that touch where no join says so) stops with a message
   * naming `entry`, the file, its line, the patch or the element.
   */
  struct NurbsPatchFile
  {
    NurbsMultipatch geometry;
    /** Each patch's sides' names (empty: joined). One patch: xi0, xi1,
     *  eta0, eta1 unless the file renames them; several: patch<k>.xi0 and
     *  so on (k from 1) unless the file names them. */
    std::vector<std::array<std::string, 4>> side_names;
    /** The file and entry, for the messages of refine() and create_mesh(). */
    std::string where;

    static NurbsPatchFile
    read(const std::string &file, const std::string &entry);

    /**
     * Splits every element of every patch into `subdivisions` parts in each
     * parameter by knot insertion (the shape unchanged), their parametric
     * lengths in geometric progression, the last `grading` times the first
     * (1: equal parts); the joins checked again and the control points
     * numbered for the body.
     */
    void
    refine(const std::array<unsigned int, 2> &subdivisions,
           const std::array<double, 2>       &grading = {{1., 1.}});

    /**
     * The mesh of the patches' elements (NurbsMultipatch::cell_span), its
     * vertices the patches' points at the knots, a joined side's once; the
     * sides' faces get a boundary id per name.
     */
    BoundaryNames
    create_mesh(dealii::Triangulation<2> &mesh) const;
  };
} // namespace glissade

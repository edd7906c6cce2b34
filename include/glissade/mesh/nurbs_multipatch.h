#pragma once

#include <deal.II/base/point.h>

#include <glissade/mesh/nurbs_patch.h>

#include <array>
#include <string>
#include <vector>

namespace glissade
{
  /** A side of a patch: 0 xi0, 1 xi1, 2 eta0, 3 eta1 (the number deal.II
   *  gives the faces of the patch's cells there). */
  struct PatchSide
  {
    unsigned int patch = 0;
    unsigned int side  = 0;
  };

  /** The sides' keys in files and messages: xi0, xi1, eta0, eta1. */
  const std::array<std::string, 4> &
  patch_side_keys();

  /** "patch 2's side xi1" (patches counted from 1, as files number them). */
  std::string
  describe(const PatchSide &side);

  /**
   * A NURBS body: one patch, or several joined C0 along whole sides (the
   * multi-patch bodies of Cottrell, Hughes & Bazilevs, Isogeometric
   * Analysis, 2009, section 2.4), for shapes that one patch cannot map
   * without a degenerate corner (an L, a disk, a die with a round nose).
   *
   * Two joined sides must be conforming: the same control points, in the
   * same or the reverse order, weights in the same proportion, and knot
   * vectors that are the same after the affine map of one side's
   * parameter range onto the other's (reversed with the points). Their
   * functions along the side are then the same functions of the point,
   * and their control points are numbered once for the body
   * (NurbsPatch::body_numbers): the displacement is continuous across the
   * join, and only C0, as across a knot repeated p times inside a patch.
   *
   * The body's cells are the patches' elements, patch after patch, each
   * patch's xi fastest (cell_span).
   */
  class NurbsMultipatch
  {
  public:
    NurbsMultipatch() = default;

    /** A body of one patch. */
    explicit NurbsMultipatch(NurbsPatch patch);

    std::vector<NurbsPatch>               patches;
    std::vector<std::array<PatchSide, 2>> joins;

    /**
     * Checks every join and numbers the body's control points, once each
     * (after any knot insertion: the numbers are those of the patches' last
     * control nets). A join whose sides are not conforming, or a side
     * joined twice, throws an InputError at `where` naming the patches and
     * sides and what differs.
     */
    void
    number_controls(const std::string &where);

    /** The body's distinct control points. */
    unsigned int
    n_controls() const
    {
      return n_body_controls;
    }

    /** The body's elements. */
    unsigned int
    n_cells() const;

    /** The patch of cell `cell` and its span there. */
    struct CellSpan
    {
      unsigned int                patch;
      std::array<unsigned int, 2> span;
    };
    CellSpan
    cell_span(const unsigned int cell) const;

    /** The degree of the patches (all of one degree, in both directions;
     *  checked by number_controls). */
    unsigned int
    degree() const
    {
      return patches.front().xi.degree();
    }

    /** Each body control point's position, by its number. */
    std::vector<dealii::Point<2>>
    control_points() const;

  private:
    unsigned int n_body_controls = 0;
  };
} // namespace glissade

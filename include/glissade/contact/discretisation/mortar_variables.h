#pragma once

#include <deal.II/base/point.h>

#include <glissade/base/dual_number.h>
#include <glissade/contact/discretisation/contact_linearization.h>

#include <array>
#include <utility>
#include <vector>

/**
 * The dual numbers mortar contact differentiates its integrals with, and
 * the sparse rows it sums them into (source/contact/discretisation/
 * mortar.cc; doc/contact.md, "Mortar").
 */
namespace glissade::mortar
{
  /**
   * The coordinates a segment pair's integrals depend on: up to four
   * slave points (the slave segment's two nodes and their neighbours,
   * whose faces make the nodal normals) and the master segment's two
   * nodes, two coordinates each (12); on a smooth master curve, eight
   * more: at each of the four Gauss points, the curve point's change
   * sum_k phi_k dX_k, through which every node of the curve acts
   * (mapped to them afterwards).
   */
  constexpr int n_mortar_variables = 20;
  using MortarDual                 = Dual<n_mortar_variables>;

  struct DualPoint
  {
    MortarDual x, y;
  };

  inline DualPoint
  operator-(const DualPoint &a, const DualPoint &b)
  {
    return {a.x - b.x, a.y - b.y};
  }

  inline DualPoint
  operator+(const DualPoint &a, const DualPoint &b)
  {
    return {a.x + b.x, a.y + b.y};
  }

  inline DualPoint
  operator*(const MortarDual &s, const DualPoint &a)
  {
    return {s * a.x, s * a.y};
  }

  inline MortarDual
  cross(const DualPoint &a, const DualPoint &b)
  {
    return a.x * b.y - a.y * b.x;
  }

  /** e3 x v: the left normal of a direction of travel. */
  inline DualPoint
  left_normal(const DualPoint &v)
  {
    return {-v.y, v.x};
  }

  /** A value and its derivatives over the pair's dofs, summed from
   * segment pairs. */
  struct Accumulated
  {
    double    value = 0.;
    DofVector gradient;

    /** Adds a segment pair's value; `dofs` maps its variables to dofs
     *  (each variable a combination of dofs: a node's one, a NURBS curve's
     *  node its control points'). */
    void
    add(const MortarDual                                &v,
        const std::array<DofVector, n_mortar_variables> &dofs,
        const unsigned int                               n_used)
    {
      value += v.value;
      for (unsigned int i = 0; i < n_used; ++i)
        if (v.derivative[i] != 0.)
          for (const DofCoefficient &e : dofs[i])
            gradient.push_back({e.body, e.dof, e.value * v.derivative[i]});
    }
  };

  /** One entry per dof. */
  void
  merge_entries(DofVector &v);

  /**
   * The root of A s^2 + B s + C that Newton reaches from the linear
   * estimate -C / B; NaN if it does not.
   */
  double
  root_near_linear(const double A, const double B, const double C);

  /**
   * The coordinates of some points as dual variables 0, 1, 2, ... in
   * the order they are added, and the dofs each variable stands for.
   */
  struct LocalVariables
  {
    std::vector<DualPoint>                    coordinates;
    std::array<DofVector, n_mortar_variables> dofs{};

    /** Adds a point of `body` at x made of `shares` (a node: its dofs
     *  with weight 1); its index. */
    unsigned int
    add(const unsigned int      body,
        const SlaveShares      &shares,
        const dealii::Point<2> &x)
    {
      const unsigned int l = coordinates.size();
      coordinates.push_back({MortarDual::variable(x[0], 2 * l),
                             MortarDual::variable(x[1], 2 * l + 1)});
      for (unsigned int c = 0; c < 2; ++c)
        {
          dofs[2 * l + c].clear();
          for (const SlaveShare &share : shares)
            dofs[2 * l + c].push_back({body, share.dofs[c], share.weight});
        }
      return l;
    }

    unsigned int
    n_used() const
    {
      return 2 * coordinates.size();
    }
  };

  /**
   * The tangent's terms with proportional rows, merged: load_1 (x) row_1
   * + load_2 (x) r row_1 = (load_1 + r load_2) (x) row_1. A curve's force
   * weights come in such families (a node's two components; a Hermite
   * end's four derivative dofs, T_k times one integral), and every term
   * costs the condensed step one more solve with the bodies' tangents.
   * (Proportional to round-off: rows that differ by more are kept apart.)
   */
  void
  merge_proportional_terms(std::vector<ContactLinearization::Term> &terms);

  /** c a, appended to `out`. */
  void
  add_scaled(DofVector &out, const double c, const DofVector &a);
} // namespace glissade::mortar

#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>

#include <string>

namespace glissade
{
  using namespace dealii;

  /**
   * An element space: what a body needs to discretise its displacement.
   *
   * It bundles the vector-valued finite element (two displacement
   * components), the geometry mapping (isoparametric for the Lagrange
   * spaces, so Q1 bodies have straight edges exactly as the paper's Q4), and
   * the quadrature rules. Bodies only talk to this interface, so a new
   * element type is one new class plus one line in ElementSpaceRegistry.
   */
  class ElementSpace
  {
  public:
    virtual ~ElementSpace() = default;

    /** The name it is chosen by in the .prm ("q1", ...). */
    virtual std::string
    name() const = 0;

    virtual const FiniteElement<2> &
    finite_element() const = 0;

    virtual const Mapping<2> &
    mapping() const = 0;

    virtual const Quadrature<2> &
    cell_quadrature() const = 0;

    virtual const Quadrature<1> &
    face_quadrature() const = 0;
  };
} // namespace glissade

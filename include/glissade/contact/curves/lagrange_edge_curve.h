#pragma once

#include <glissade/contact/curves/master_curve.h>

namespace glissade
{
  /**
   * The boundary of a mesh of quadratic (Q8) or cubic (Q12) elements: on
   * each segment the Lagrange polynomial of degree p through the segment's
   * two vertices and its p - 1 edge nodes, equally spaced in s. Smooth inside
   * an element, only C0 at the vertices: the normal still jumps there, which
   * is what the geometric study shows for higher-order elements.
   *
   * The data nodes (MasterCurve::nodes()) are the vertices; the edge nodes
   * are given per segment to update(vertices, edge_nodes), in order of
   * increasing s. In weights(), edge node j of segment i has the index
   * n_nodes() + i (p - 1) + j, after the vertices.
   */
  class LagrangeEdgeCurve : public MasterCurve
  {
  public:
    LagrangeEdgeCurve(const unsigned int degree, const bool closed);

    /** Keeps the edge nodes of the last call (they must exist). */
    void
    update(const std::vector<Point> &vertices) override;

    /** edge_nodes: (p - 1) points per segment, segment after segment. */
    void
    update(const std::vector<Point> &vertices,
           const std::vector<Point> &edge_nodes);

    unsigned int
    n_segments() const override;
    bool
    is_closed() const override;

    Point
    value(unsigned int segment, double s) const override;
    Point
    derivative(unsigned int segment, double s) const override;
    Point
    second_derivative(unsigned int segment, double s) const override;

    void
    bounding_box(unsigned int segment, Point &low, Point &high) const override;

    void
    weights_and_derivatives(unsigned int               segment,
                            double                     s,
                            NodeWeightsAndDerivatives &weights) const override;

  private:
    /** The p + 1 points of a segment, in order of s. */
    std::vector<Point>
    segment_points(unsigned int segment) const;

    /** Lagrange basis on s_j = j/p and its first two derivatives. */
    void
    basis(double               s,
          std::vector<double> &value,
          std::vector<double> &first,
          std::vector<double> &second) const;

    Point
    combine(unsigned int segment, double s, unsigned int order) const;

    const unsigned int degree;
    const bool         closed;
    std::vector<Point> edge_nodes;
  };
} // namespace glissade

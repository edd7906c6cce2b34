#include <glissade/mesh/mesh_diameter.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace glissade
{
  using namespace dealii;

  double
  mesh_diameter(const Triangulation<2> &mesh)
  {
    // The boundary vertices, once each.
    const auto       &vertices = mesh.get_vertices();
    std::vector<bool> on_boundary(vertices.size(), false);
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          for (const unsigned int v : face->vertex_indices())
            on_boundary[face->vertex_index(v)] = true;
    std::vector<Point<2>> points;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (on_boundary[v])
        points.push_back(vertices[v]);
    if (points.size() < 2)
      return 0.;

    // Their convex hull (Andrew's monotone chain). A vertex on a hull edge
    // is dropped: no distance from it exceeds both of the edge's ends'.
    std::sort(points.begin(),
              points.end(),
              [](const Point<2> &a, const Point<2> &b) {
                return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
              });
    const auto turn =
      [](const Point<2> &o, const Point<2> &a, const Point<2> &b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
      };
    std::vector<Point<2>> hull(2 * points.size());
    std::size_t           k = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.)
          --k;
        hull[k++] = points[i];
      }
    for (std::size_t i = points.size() - 1, lower = k + 1; i > 0; --i)
      {
        while (k >= lower &&
               turn(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.)
          --k;
        hull[k++] = points[i - 1];
      }
    hull.resize(k > 1 ? k - 1 : k);

    // Every pair of hull vertices, as deal.II compares them (the square of
    // the distance, then one square root): the same bits.
    double largest = 0.;
    for (std::size_t i = 0; i < hull.size(); ++i)
      for (std::size_t j = i + 1; j < hull.size(); ++j)
        largest = std::max(largest, (hull[i] - hull[j]).norm_square());
    return std::sqrt(largest);
  }
} // namespace glissade

// The vertex nearest to a point (include/glissade/mesh/nearest_vertex.h).

#include <glissade/mesh/nearest_vertex.h>

#include <limits>

namespace glissade
{
  NearestVertex
  nearest_vertex(const std::vector<dealii::Point<2>> &vertices,
                 const dealii::Point<2>              &point,
                 const std::vector<bool>             *used)
  {
    NearestVertex nearest;
    nearest.distance = std::numeric_limits<double>::max();
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (used == nullptr || (*used)[v])
        if (const double d = vertices[v].distance(point); d < nearest.distance)
          {
            nearest.index    = v;
            nearest.distance = d;
          }
    return nearest;
  }
} // namespace glissade

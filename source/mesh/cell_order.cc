// Cells in the order of a Hilbert curve (include/glissade/mesh/cell_order.h).

#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>

#include <glissade/mesh/cell_order.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

namespace glissade
{
  using namespace dealii;

  void
  order_cells_along_hilbert_curve(Triangulation<2> &mesh)
  {
    auto [vertices, cells, faces] =
      GridTools::get_coarse_mesh_description(mesh);
    if (cells.size() < 2)
      return;

    // The centres on a grid of 2^16 x 2^16 over the mesh's bounding square
    // (one scale for both directions: a long body is walked along).
    std::vector<Point<2>> centres(cells.size());
    Point<2>              low = vertices[cells[0].vertices[0]], high = low;
    for (std::size_t c = 0; c < cells.size(); ++c)
      {
        for (const unsigned int v : cells[c].vertices)
          {
            centres[c] += vertices[v] / double(cells[c].vertices.size());
            for (unsigned int d = 0; d < 2; ++d)
              {
                low[d]  = std::min(low[d], vertices[v][d]);
                high[d] = std::max(high[d], vertices[v][d]);
              }
          }
      }
    // (deal.II's overload for points scales each direction to its own
    // extent: a long body's pieces would be thin slices across it)
    const int    bits  = 16;
    const double side  = std::max(high[0] - low[0], high[1] - low[1]);
    const double scale = side > 0. ? ((1u << bits) - 1) / side : 0.;
    std::vector<std::array<std::uint64_t, 2>> grid_points(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c)
      for (unsigned int d = 0; d < 2; ++d)
        grid_points[c][d] = std::lround((centres[c][d] - low[d]) * scale);
    const auto key =
      Utilities::inverse_Hilbert_space_filling_curve<2>(grid_points, bits);

    // (stable: cells whose centres share a grid point keep the file's order)
    std::vector<std::size_t> order_of_cells(cells.size());
    std::iota(order_of_cells.begin(), order_of_cells.end(), 0);
    std::stable_sort(order_of_cells.begin(),
                     order_of_cells.end(),
                     [&](const std::size_t a, const std::size_t b) {
                       return key[a] < key[b];
                     });
    std::vector<CellData<2>> ordered;
    ordered.reserve(cells.size());
    for (const std::size_t c : order_of_cells)
      ordered.push_back(cells[c]);

    // (the manifolds, a second-order file's curved edges, are kept: the
    // ids of cells and faces come back with the description)
    std::map<types::manifold_id, std::unique_ptr<Manifold<2>>> manifolds;
    for (const types::manifold_id id : mesh.get_manifold_ids())
      if (id != numbers::flat_manifold_id)
        manifolds[id] = mesh.get_manifold(id).clone();
    mesh.clear();
    mesh.create_triangulation(vertices, ordered, faces);
    for (auto &[id, manifold] : manifolds)
      mesh.set_manifold(id, *manifold);
  }
} // namespace glissade

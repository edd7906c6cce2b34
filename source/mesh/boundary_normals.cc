#include <glissade/mesh/boundary_normals.h>

namespace glissade
{
  using namespace dealii;

  std::map<unsigned int, dealii::Tensor<1, 2>>
  boundary_vertex_normals(
    const dealii::Triangulation<2>                        &triangulation,
    const std::function<bool(dealii::types::boundary_id)> &on_boundary)
  {
    std::map<unsigned int, dealii::Tensor<1, 2>> normals;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            on_boundary(cell->face(f)->boundary_id()))
          {
            const dealii::Tensor<1, 2> along =
              cell->face(f)->vertex(1) - cell->face(f)->vertex(0);
            dealii::Tensor<1, 2> n({along[1], -along[0]});
            if (n * (cell->face(f)->center() - cell->center()) < 0.)
              n = -n;
            for (const unsigned int v : {0u, 1u})
              normals[cell->face(f)->vertex_index(v)] += n / n.norm();
          }
    return normals;
  }
} // namespace glissade

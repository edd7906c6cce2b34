// A body's mesh shared out over the processes (include/glissade/mesh/
// process_mesh.h).

#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/grid/tria_description.h>

#include <glissade/mesh/nearest_vertex.h>
#include <glissade/mesh/process_mesh.h>

#include <algorithm>
#include <stdexcept>

namespace glissade
{
  using namespace dealii;

  std::unique_ptr<Triangulation<2>>
  distribute_mesh(const Triangulation<2>      &serial,
                  const std::vector<Point<2>> &kept_points,
                  MPI_Comm                     communicator)
  {
    // (every mesh of the scene is a coarse mesh: no refined levels)
    AssertThrow(serial.n_levels() == 1, ExcNotImplemented());
    int rank = 0, size = 1;
    MPI_Comm_rank(communicator, &rank);
    MPI_Comm_size(communicator, &size);
    const std::size_t n = serial.n_active_cells();
    // The processes' shares: ranges of the serial mesh's cells, in its
    // order, as on a replicated mesh. (Its dofs are numbered cell after
    // cell, and a dof between two shares belongs to the lower rank: each
    // process then owns a contiguous range of the serial numbers, which
    // deal.II's distributed vectors (DataOut's) need. A METIS partition,
    // tried, owns scattered numbers, and DataOut's index-owner search never
    // ended in deal.II 9.4.)
    // (the ranges processes::share gives, process p cells n p / P to
    // n (p + 1) / P)
    std::vector<unsigned int> owner(n);
    for (std::size_t p = 0; p < std::size_t(size); ++p)
      for (std::size_t cell = n * p / size; cell < n * (p + 1) / size; ++cell)
        owner[cell] = p;

    // The vertices whose cells this process holds: those of its own
    // cells, of the boundary, and the vertex nearest to each kept point.
    std::vector<bool> marked(serial.n_vertices(), false);
    for (const auto &cell : serial.active_cell_iterators())
      {
        const bool own = owner[cell->active_cell_index()] == unsigned(rank);
        for (const unsigned int f : cell->face_indices())
          if (own || cell->face(f)->at_boundary())
            for (const unsigned int v : cell->face(f)->vertex_indices())
              marked[cell->face(f)->vertex_index(v)] = true;
      }
    const auto &vertices = serial.get_vertices();
    const auto &used     = serial.get_used_vertices();
    for (const Point<2> &point : kept_points)
      marked[nearest_vertex(vertices, point, &used).index] = true;

    std::vector<bool> held(n, false);
    for (const auto &cell : serial.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        held[cell->active_cell_index()] =
          held[cell->active_cell_index()] || marked[cell->vertex_index(v)];

    // The held cells in the serial order, their vertices numbered in the
    // serial order too: walks over cells and vertices (contact nodes,
    // chains, supports) meet them in the order one process does.
    std::vector<unsigned int> local_vertex(vertices.size(),
                                           numbers::invalid_unsigned_int);
    for (const auto &cell : serial.active_cell_iterators())
      if (held[cell->active_cell_index()])
        for (const unsigned int v : cell->vertex_indices())
          local_vertex[cell->vertex_index(v)] = 0;
    TriangulationDescription::Description<2, 2> description;
    description.comm      = communicator;
    description.settings  = TriangulationDescription::default_setting;
    description.smoothing = Triangulation<2>::none;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (local_vertex[v] == 0)
        {
          local_vertex[v] = description.coarse_cell_vertices.size();
          description.coarse_cell_vertices.push_back(vertices[v]);
        }
    description.cell_infos.resize(1);
    for (const auto &cell : serial.active_cell_iterators())
      {
        const unsigned int index = cell->active_cell_index();
        if (!held[index])
          continue;
        CellData<2> coarse;
        coarse.material_id = cell->material_id();
        coarse.manifold_id = cell->manifold_id();
        for (const unsigned int v : cell->vertex_indices())
          coarse.vertices[v] = local_vertex[cell->vertex_index(v)];
        description.coarse_cells.push_back(coarse);
        description.coarse_cell_index_to_coarse_cell_id.push_back(index);

        TriangulationDescription::CellData<2> info;
        info.id                 = CellId(index, {}).to_binary<2>();
        info.subdomain_id       = owner[index];
        info.level_subdomain_id = numbers::artificial_subdomain_id;
        info.manifold_id        = cell->manifold_id();
        for (const unsigned int l : cell->line_indices())
          info.manifold_line_ids[l] = cell->line(l)->manifold_id();
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            info.boundary_ids.emplace_back(f, cell->face(f)->boundary_id());
          else if (!held[cell->neighbor(f)->active_cell_index()])
            info.boundary_ids.emplace_back(f, cut_boundary_id);
        description.cell_infos[0].push_back(info);
      }

    auto distributed =
      std::make_unique<parallel::fullydistributed::Triangulation<2>>(
        communicator);
    for (const types::manifold_id id : serial.get_manifold_ids())
      if (id != numbers::flat_manifold_id)
        distributed->set_manifold(id, serial.get_manifold(id));
    distributed->create_triangulation(description);
    return distributed;
  }



  void
  number_dofs_as_serial(DoFHandler<2> &distributed, const DoFHandler<2> &serial)
  {
    const auto serial_cell = [&serial](const auto &cell) {
      return DoFHandler<2>::active_cell_iterator(&serial.get_triangulation(),
                                                 0,
                                                 serial_cell_index(cell),
                                                 &serial);
    };
    const unsigned int n = distributed.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> held(n), one_process(n);
    const IndexSet owned = distributed.locally_owned_dofs();
    std::vector<types::global_dof_index> new_numbers(
      owned.n_elements(), numbers::invalid_dof_index);
    for (const auto &cell : distributed.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(held);
          serial_cell(cell)->get_dof_indices(one_process);
          for (unsigned int i = 0; i < n; ++i)
            if (owned.is_element(held[i]))
              new_numbers[owned.index_within_set(held[i])] = one_process[i];
        }
    distributed.renumber_dofs(new_numbers);

    // (the cells' local dofs in the same order on both meshes: lines
    // oriented alike, which the serial order of vertices gives)
    for (const auto &cell : distributed.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(held);
          serial_cell(cell)->get_dof_indices(one_process);
          if (held != one_process)
            throw std::logic_error(
              "the distributed mesh's dofs differ from the serial mesh's on "
              "cell " +
              std::to_string(serial_cell_index(cell)));
        }
  }
} // namespace glissade

#pragma once

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <mpi.h>

#include <memory>
#include <vector>

namespace glissade
{
  /**
   * A body's mesh shared out over the processes of a run (doc/parallel.md).
   *
   * Each process holds, as a parallel::fullydistributed::Triangulation:
   * - its own cells: the share of the serial mesh's active cells that it
   *   integrates (processes::share, in the mesh's order, as on a
   *   replicated mesh), and the cells that touch them (deal.II's ghost
   *   layer);
   * - every cell that touches the boundary or one of the points the body's
   *   supports and loads name, as ghost cells of their owners.
   * So contact surfaces, supports, loads and reactions see the whole
   * boundary on every process, with the serial mesh's cell and vertex
   * order, and the interior is held once. (deal.II's own descriptions hold
   * one layer of ghost cells; p::d::Triangulation would replicate the
   * whole of a mesh that is its own coarse mesh, as every mesh here is.)
   *
   * A face between a held cell and one that is not is a boundary face of
   * the held mesh: it gets cut_boundary_id, which no named boundary has.
   */
  std::unique_ptr<dealii::Triangulation<2>>
  distribute_mesh(const dealii::Triangulation<2>      &serial,
                  const std::vector<dealii::Point<2>> &kept_points,
                  MPI_Comm                             communicator);

  /** The boundary id of the faces that cut the serial mesh. */
  constexpr dealii::types::boundary_id cut_boundary_id = 254;

  /**
   * Renumbers the dofs of a distributed mesh's handler as `serial` numbers
   * them on the mesh it was made from (the same element): every dof then
   * has the number one process gives it, so that the bodies' vectors,
   * their factorisations and checkpoints are those of one process. Throws
   * std::logic_error if a held cell's dofs differ from its serial cell's
   * afterwards.
   */
  void
  number_dofs_as_serial(dealii::DoFHandler<2>       &distributed,
                        const dealii::DoFHandler<2> &serial);

  /** The serial mesh's active cell index of a cell of a distributed mesh
   *  (or of the serial mesh itself). */
  template <class CellIterator>
  inline unsigned int
  serial_cell_index(const CellIterator &cell)
  {
    return cell->id().get_coarse_cell_id();
  }
} // namespace glissade

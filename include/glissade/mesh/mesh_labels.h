#pragma once

#include <deal.II/base/types.h>

#include <map>
#include <string>

namespace glissade
{
  /** Boundary names of a mesh and the deal.II boundary ids they stand for. */
  using BoundaryNames = std::map<std::string, dealii::types::boundary_id>;

  /** Material region names (Gmsh Physical Surfaces) and their cells' ids. */
  using RegionNames = std::map<std::string, dealii::types::material_id>;

  /** The names a mesh gives its boundaries and regions. */
  struct MeshLabels
  {
    BoundaryNames boundaries;
    RegionNames   regions;
    /** Read from second-order quadrilaterals (their curved edges kept). */
    bool second_order = false;
  };
} // namespace glissade

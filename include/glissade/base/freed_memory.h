#pragma once

namespace glissade
{
  /**
   * Gives the operating system back the pages of the heap that nothing
   * uses any more (glibc's malloc_trim).
   *
   * Debian's SuperLU_DIST, loaded with PETSc through deal.II whether a run
   * uses it or not, turns off glibc's mapping of large blocks and its
   * trimming of the heap when it is loaded (CombBLAS's mallopt, in a static
   * initialiser): without this, the pages of every array freed (the set-up's
   * sparsity patterns, the factorisations' workspace, the contact
   * algebra's dense blocks) stay in the process, and its resident memory
   * only grows. Called between the phases of a Newton iteration
   * (Simulation), where 64 MB or more of the heap lie free: the
   * million-dof rings' peak on one process fell from 3.10 to 2.96 GB
   * (doc/performance.md).
   */
  void
  return_freed_memory();
} // namespace glissade

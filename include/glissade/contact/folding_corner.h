#pragma once

#include <string>

namespace glissade
{
  class ContactPair;

  /**
   * Why a run that stopped did so at a slave corner that folds, or "" if
   * it did not: a slave node in contact at a sharp corner of its body's
   * boundary (the boundary turns by 45 degrees or more there in the
   * reference mesh) whose cells are crushed at the current state (a
   * corner Jacobian, deformed over reference, below 0.5 at one of their
   * vertices).
   *
   * A sharp corner that sticks on its master is a singular point of exact
   * (non-penetrating) contact: the node takes a concentrated share of the
   * normal force, the cell behind it is squeezed between the node and the
   * material that slides, and the equilibrium with the corner stuck ends
   * at a limit point at a load that decreases with the cell size
   * (doc/studies/rubber_block.md). The text says so, with the node, its
   * status and force, the crushed cell, and what would carry on.
   */
  std::string
  describe_folding_corner(const ContactPair &pair);
} // namespace glissade

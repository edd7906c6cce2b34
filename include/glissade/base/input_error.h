#pragma once

#include <stdexcept>
#include <string>

namespace glissade
{
  /**
   * The one exception type for mistakes in the user's input: a wrong .prm
   * entry, a missing mesh file, a boundary that the mesh does not have.
   *
   * The message always names where the mistake is (file and entry), so that
   * main() can print it as it is and stop with a non-zero exit code before
   * any computation starts.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &where, const std::string &what)
      : std::runtime_error(where.empty() ? what : where + ": " + what)
    {}
  };

  /**
   * Raised when the nonlinear solver gives up on a load increment after all
   * allowed cut-backs. The message names the increment and carries the
   * residual history of the last attempt.
   */
  class ConvergenceFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace glissade

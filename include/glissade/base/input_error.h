#pragma once

#include <stdexcept>
#include <string>
#include <vector>

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
   * Collects the mistakes of independent parts of the input (each body,
   * each contact pair, the load program) so that the user reads all of them
   * in one message rather than one per run.
   */
  class InputErrorList
  {
  public:
    /** Runs check(); an InputError it throws is recorded, not propagated. */
    template <typename Check>
    void
    collect(const Check &check)
    {
      try
        {
          check();
        }
      catch (const InputError &e)
        {
          messages.emplace_back(e.what());
        }
    }

    /** Throws one InputError listing every recorded mistake, if any. */
    void
    throw_if_any() const
    {
      if (messages.size() == 1)
        throw InputError("", messages.front());
      if (messages.size() > 1)
        {
          std::string all = std::to_string(messages.size()) + " mistakes:";
          for (const auto &m : messages)
            all += "\n  " + m;
          throw InputError("", all);
        }
    }

  private:
    std::vector<std::string> messages;
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

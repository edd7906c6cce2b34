// Load program (the stages of t and their increments) and Newton (when an
// increment has converged).

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <glissade/base/input_error.h>
#include <glissade/description/scene_description.h>
#include <glissade/scene/section_reader.h>

#include <cstdlib>
#include <string>

namespace glissade
{
  using namespace dealii;

  void
  LoadProgram::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load program");
    prm.declare_entry("Stage end times",
                      "1",
                      Patterns::List(Patterns::Double(), 1),
                      "Time t at the end of each stage (increasing). Loads "
                      "and motions are expressions in t.");
    prm.declare_entry("Stage increments",
                      "1",
                      Patterns::List(Patterns::Integer(1), 1),
                      "Number of equal increments of each stage.");
    prm.declare_entry("Maximum cut-back depth",
                      "6",
                      Patterns::Integer(0, 30),
                      "How many times an increment that does not converge "
                      "may be bisected before the run stops.");
    prm.leave_subsection();
  }



  void
  LoadProgram::parse_parameters(SectionReader &prm)
  {
    prm.enter_subsection("Load program");
    stage_end_times.clear();
    for (const auto &t :
         Utilities::split_string_list(prm.get("Stage end times"), ','))
      try
        {
          stage_end_times.push_back(std::stod(t));
        }
      catch (const std::exception &)
        {
          throw InputError(prm.file() + ": Load program/Stage end times",
                           "'" + t +
                             "' is not a double-precision number "
                             "(out of range?)");
        }
    stage_increments.clear();
    for (const auto &n :
         Utilities::split_string_list(prm.get("Stage increments"), ','))
      {
        const long value = std::strtol(n.c_str(), nullptr, 10);
        if (value < 1 || value > 100000000)
          throw InputError(prm.file() + ": Load program/Stage increments",
                           "'" + n +
                             "' is not a number of increments "
                             "between 1 and 1e8");
        stage_increments.push_back(value);
      }
    max_cut_back_depth = prm.get_integer("Maximum cut-back depth");
    prm.leave_subsection();
    const auto &times = stage_end_times;
    prm.check([&]() {
      if (times.size() != stage_increments.size())
        throw InputError(prm.file() + ": Load program/Stage increments",
                         "needs one value per stage end time");
    });
    prm.check([&]() {
      for (unsigned int i = 0; i < times.size(); ++i)
        if (!(times[i] > (i == 0 ? 0. : times[i - 1])))
          throw InputError(prm.file() + ": Load program/Stage end times",
                           "must be positive and increasing");
    });
  }



  void
  NewtonSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Maximum iterations",
                      "25",
                      Patterns::Integer(1),
                      "Newton iterations per increment before a cut-back.");
    prm.declare_entry("Residual tolerance",
                      "1e-9",
                      Patterns::Double(0.),
                      "Converged when |R| <= tol * max(|F_int|, |F_ext|) on "
                      "the free dofs...");
    prm.declare_entry("Displacement tolerance",
                      "1e-9",
                      Patterns::Double(0.),
                      "...and |du| <= tol * |u| (tol * 1e-12 * the largest "
                      "body's diameter while u = 0).");
    prm.declare_entry(
      "Last correction with previous tangent",
      "true",
      Patterns::Bool(),
      "When the residual already meets its tolerance, the state is the "
      "solution and the last correction only confirms it for the "
      "displacement test: solve it with the previous iteration's "
      "factorisation (one back-substitution instead of a factorisation). "
      "It differs from the full Newton correction by about the relative "
      "size of the correction before it (at most 1e-3, else the full one "
      "is made), so the displacement test decides as it would. false: "
      "factorise at every correction.");
    prm.leave_subsection();
  }



  void
  NewtonSettings::parse_parameters(SectionReader &prm)
  {
    prm.enter_subsection("Newton");
    max_iterations         = prm.get_integer("Maximum iterations");
    residual_tolerance     = prm.get_double("Residual tolerance");
    displacement_tolerance = prm.get_double("Displacement tolerance");
    last_correction_with_previous_tangent =
      prm.get_bool("Last correction with previous tangent");
    prm.leave_subsection();
    prm.check([&]() {
      if (!(residual_tolerance > 0.))
        throw InputError(prm.file() + ": Newton/Residual tolerance",
                         "must be > 0: a residual is never exactly zero in "
                         "floating point (1e-9 to 1e-12 is usual)");
      if (!(displacement_tolerance > 0.))
        throw InputError(prm.file() + ": Newton/Displacement tolerance",
                         "must be > 0 (1e-6 to 1e-10 is usual)");
    });
  }
} // namespace glissade

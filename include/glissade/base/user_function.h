#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace glissade
{
  /**
   * A value of a user's expression, checked: log(t - 0.5) before t = 0.5,
   * 1/t at t = 0 or sqrt of a negative would otherwise carry a NaN into the
   * solution and end as "did not converge" (or in a VTU). Returns the value
   * if finite; otherwise throws an InputError naming the entry, the
   * expression, the time and the point.
   */
  double
  checked_user_value(double                  value,
                     const std::string      &entry,
                     const std::string      &expression,
                     double                  time,
                     const dealii::Point<2> &X);

  /**
   * The user's expressions of x, y and t from one .prm entry (loads,
   * prescribed displacements, an obstacle's motion), each value checked
   * with checked_user_value where it is evaluated.
   */
  class UserFunction : public dealii::Function<2>
  {
  public:
    UserFunction(const std::vector<std::string> &expressions,
                 const std::string              &entry);

    double
    value(const dealii::Point<2> &X,
          const unsigned int      component) const override;

  private:
    mutable dealii::FunctionParser<2> parser;
    const std::vector<std::string>    expressions;
    const std::string                 entry;
  };
} // namespace glissade

#include <deal.II/base/numbers.h>

#include <glissade/base/input_error.h>
#include <glissade/base/user_function.h>

#include <cmath>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  double
  checked_user_value(const double            value,
                     const std::string      &entry,
                     const std::string      &expression,
                     const double            time,
                     const dealii::Point<2> &X)
  {
    if (std::isfinite(value))
      return value;
    std::ostringstream message;
    message << "'" << expression << "' evaluates to " << value
            << " at t = " << time << ", (x, y) = (" << X[0] << ", " << X[1]
            << "): give an expression that is finite wherever and whenever "
               "it is used (the load program's times, cut-backs included)";
    throw InputError(entry, message.str());
  }



  UserFunction::UserFunction(const std::vector<std::string> &expressions,
                             const std::string              &entry)
    : dealii::Function<2>(expressions.size())
    , parser(expressions.size())
    , expressions(expressions)
    , entry(entry)
  {
    parser.initialize("x,y,t",
                      expressions,
                      {{"pi", dealii::numbers::PI}},
                      true);
  }



  double
  UserFunction::value(const dealii::Point<2> &X,
                      const unsigned int      component) const
  {
    parser.set_time(this->get_time());
    return checked_user_value(parser.value(X, component),
                              entry,
                              expressions[component],
                              this->get_time(),
                              X);
  }
} // namespace glissade

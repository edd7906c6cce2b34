// The reader that the scene's sections parse through, and the value formats
// they share (coordinates, expressions, "a: b; c: d" lists).

#include <deal.II/base/function_parser.h>
#include <deal.II/lac/vector.h>

#include <glissade/base/text.h>
#include <glissade/scene/section_reader.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  double
  SectionReader::number_or_inherited(const std::string &entry,
                                     const double       inherited,
                                     const std::string &where,
                                     const std::string &hint) const
  {
    const std::string value = text::trim(prm.get(entry));
    if (value.empty())
      return inherited;
    try
      {
        std::size_t  used   = 0;
        const double result = std::stod(value, &used);
        if (used == value.size() && std::isfinite(result))
          return result;
      }
    catch (const std::exception &)
      {}
    throw InputError(where + "/" + entry,
                     "'" + value + "' is not a number" + hint);
  }



  namespace entry_format
  {
    void
    check_expressions(const std::vector<std::string> &expressions,
                      const std::string              &where)
    {
      // muParser accepts an assignment ("t=5" sets t and yields 5) and
      // rand(): neither belongs in a boundary datum, and both ran silently.
      for (const auto &e : expressions)
        {
          for (std::size_t i = 0; i < e.size(); ++i)
            if (e[i] == '=' &&
                (i == 0 ||
                 std::string("<>!=").find(e[i - 1]) == std::string::npos) &&
                (i + 1 == e.size() || e[i + 1] != '='))
              throw InputError(where,
                               "'" + e +
                                 "' assigns with '=': an expression "
                                 "gives a value (compare with '==')");
          if (e.find("rand") != std::string::npos)
            throw InputError(where,
                             "'" + e +
                               "' uses rand(): boundary data must be "
                               "the same in every run");
        }
      // deal.II's parser prints muparser's diagnosis to std::cerr before it
      // throws; the user gets it once, in the InputError below.
      std::ostringstream diagnosis;
      std::streambuf    *standard_error = std::cerr.rdbuf(diagnosis.rdbuf());
      struct Restore
      {
        std::streambuf *buffer;
        ~Restore()
        {
          std::cerr.rdbuf(buffer);
        }
      } restore{standard_error};
      try
        {
          FunctionParser<2> function(expressions.size());
          function.initialize("x,y,t",
                              expressions,
                              {{"pi", numbers::PI}},
                              true);
          Vector<double> values(expressions.size());
          function.vector_value(Point<2>(), values);
        }
      catch (const std::exception &e)
        {
          std::string list;
          for (const auto &s : expressions)
            list += (list.empty() ? "" : ", ") + s;
          throw InputError(where,
                           "cannot evaluate the expression(s) '" + list +
                             "' (variables are x, y, t; constant pi): " +
                             text::essential_message(e));
        }
    }

    Point<2>
    coordinates(const std::string &text_value, const std::string &where)
    {
      const auto x = text::coordinates(text_value, where);
      return Point<2>(x[0], x[1]);
    }

    std::vector<std::vector<std::string>>
    items(const std::string &value,
          const unsigned int n_fields,
          const std::string &where,
          const std::string &syntax)
    {
      std::vector<std::vector<std::string>> items;
      for (const auto &item : text::split_top_level(value, ';'))
        {
          if (item.empty())
            continue;
          const auto fields = text::split_top_level(item, ':');
          if (fields.size() != n_fields)
            throw InputError(where,
                             "cannot read '" + item + "': expected '" + syntax +
                               "'");
          items.push_back(fields);
        }
      return items;
    }
  } // namespace entry_format
} // namespace glissade

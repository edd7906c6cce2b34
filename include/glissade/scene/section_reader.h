#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <glissade/base/input_error.h>

#include <string>
#include <vector>

namespace glissade
{
  /**
   * What the sections of a scene read their values through: the parsed
   * ParameterHandler, the name of the file (for messages), and the list of
   * mistakes found so far.
   *
   * Each description of scene_description.h declares its own entries and
   * reads them back (declare_parameters, parse_parameters, as the parameter
   * structs of deal.II's step-44), in the file of its subject. The mistakes
   * of independent parts (each body's mesh, material and boundary
   * conditions, each contact pair, the load program) are collected by
   * check() and reported together, so that a user reads all of a file's
   * mistakes in one message.
   */
  class SectionReader
  {
  public:
    SectionReader(dealii::ParameterHandler &prm, const std::string &source)
      : prm(prm)
      , source(source)
    {}

    /** The parsed file, for the parts that read their own entries (the
     *  master surfaces' plug-ins). */
    const dealii::ParameterHandler &
    handler() const
    {
      return prm;
    }

    /** The file read, for messages ("scene.prm"). */
    const std::string &
    file() const
    {
      return source;
    }

    void
    enter_subsection(const std::string &name)
    {
      prm.enter_subsection(name);
      ++depth;
    }

    void
    leave_subsection()
    {
      prm.leave_subsection();
      --depth;
    }

    std::string
    get(const std::string &entry) const
    {
      return prm.get(entry);
    }

    long int
    get_integer(const std::string &entry) const
    {
      return prm.get_integer(entry);
    }

    double
    get_double(const std::string &entry) const
    {
      return prm.get_double(entry);
    }

    bool
    get_bool(const std::string &entry) const
    {
      return prm.get_bool(entry);
    }

    /**
     * Runs `part`; an InputError it throws is recorded and the subsections
     * it entered are left, so that the next part is read where it expects.
     */
    template <typename Part>
    void
    check(const Part &part)
    {
      const unsigned int level = depth;
      mistakes.collect([&]() {
        try
          {
            part();
          }
        catch (...)
          {
            while (depth > level)
              leave_subsection();
            throw;
          }
      });
    }

    /** One InputError listing every recorded mistake, if any. */
    void
    throw_if_any() const
    {
      mistakes.throw_if_any();
    }

    /**
     * An entry that may be left empty to inherit a value (a material
     * region's moduli, a pair's old Contact solver entries): `inherited`
     * if empty, else the number it holds; anything else is an input error
     * naming `where`/entry, with `hint` after the complaint.
     */
    double
    number_or_inherited(const std::string &entry,
                        const double       inherited,
                        const std::string &where,
                        const std::string &hint = "") const;

  private:
    dealii::ParameterHandler &prm;
    const std::string         source;
    unsigned int              depth = 0;
    InputErrorList            mistakes;
  };

  /**
   * The value formats that several sections share. Each throws an
   * InputError naming `where` (file and entry).
   */
  namespace entry_format
  {
    /** "x, y", two finite numbers below 1e100 and nothing else. */
    dealii::Point<2>
    coordinates(const std::string &text, const std::string &where);

    /**
     * Compiles muParser expressions in x, y, t once, so that a typing
     * slip is an input error; refuses an assignment and rand().
     */
    void
    check_expressions(const std::vector<std::string> &expressions,
                      const std::string              &where);

    /**
     * Splits "a: b: c; d: e: f" into items of `n_fields` fields; `syntax`
     * is what the message says was expected.
     */
    std::vector<std::vector<std::string>>
    items(const std::string &value,
          const unsigned int n_fields,
          const std::string &where,
          const std::string &syntax);
  } // namespace entry_format
} // namespace glissade

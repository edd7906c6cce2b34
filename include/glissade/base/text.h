#pragma once

#include <array>
#include <exception>
#include <string>
#include <vector>

namespace glissade
{
  /** Small text helpers for the mini-syntax of .prm list entries. */
  namespace text
  {
    std::string
    trim(const std::string &s);

    /**
     * Splits at `separator` where it is not nested in parentheses, so that
     * "0, min(t, 1)" gives two expressions and not three.
     */
    std::vector<std::string>
    split_top_level(const std::string &s, const char separator);

    /** The items with `separator` between them ("a|b|c", "a, b, c"). */
    std::string
    joined(const std::vector<std::string> &items, const std::string &separator);

    /**
     * "x, y": two finite numbers below 1e100 in magnitude and nothing else
     * ("0.5abc" and "0.5*t" are refused); an InputError naming `where`
     * otherwise.
     */
    std::array<double, 2>
    coordinates(const std::string &text_value, const std::string &where);

    /** True for "point(x, y)"; fills x and y. */
    bool
    parse_point_location(const std::string &location, double &x, double &y);

    /**
     * deal.II's exception text carries the library's source location and a
     * stack trace; the user needs only the "Additional information" part,
     * which names the line and the entry of the .prm file.
     */
    std::string
    essential_message(const std::exception &e);

    /**
     * A path named in `file` (a mesh in a scene, a scene in a study), taken
     * relative to the folder of that file unless it is absolute or empty.
     */
    std::string
    path_beside(const std::string &file, const std::string &path);

    /**
     * True for a regular file of at most `largest` bytes: what the readers
     * accept before reading to the end (a device such as /dev/zero never
     * ends).
     */
    bool
    is_regular_file_of_at_most(const std::string &path,
                               unsigned long long largest);
  } // namespace text
} // namespace glissade

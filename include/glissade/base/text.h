#pragma once

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

    /** True for "point(x, y)"; fills x and y. */
    bool
    parse_point_location(const std::string &location, double &x, double &y);
  } // namespace text
} // namespace glissade

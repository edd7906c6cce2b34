#pragma once

#include <glissade/fe/element_space.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * The list of element spaces a .prm may name. Adding a space is one line
   * in element_space_registry.cc: its name, a one-sentence description (it
   * becomes the parameter's documentation) and how to create it.
   */
  class ElementSpaceRegistry
  {
  public:
    struct Entry
    {
      std::string name;
      std::string description;
      /** Makes it; `degree` is Element/Degree, which only the spaces
       *  that are not named by their degree read (nurbs). */
      std::function<std::unique_ptr<ElementSpace>(unsigned int degree)> create;
    };

    static const std::vector<Entry> &
    entries();

    static std::unique_ptr<ElementSpace>
    create(const std::string &name, const unsigned int degree = 2);

    /** "q1|q2|..." for Patterns::Selection. */
    static std::string
    names_as_pattern();

    /** The names of the spaces whose capabilities `wanted` accepts, as
     *  "q2, q3 or q8", for the messages that send a user to them. */
    static std::string
    names_that(
      const std::function<bool(const ElementSpace::Capabilities &)> &wanted);

    /** "q1: ...; q2: ..." for the parameter documentation. */
    static std::string
    documentation();
  };
} // namespace glissade

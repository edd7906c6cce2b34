#pragma once

#include <glissade/contact/master_surface.h>
#include <glissade/description/scene_description.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  class Body;

  /** What a surface is built from: its pair's settings and its master body. */
  struct SurfaceContext
  {
    const ContactDescription &description;
    /** nullptr for a rigid obstacle. */
    const Body *master;
  };

  /**
   * The master surfaces a .prm may name: `Surface` of a pair with a master
   * body (deformable), `Obstacle/Type` of a pair with `Master body = rigid`.
   * Adding a surface is one file that defines its factory and one line in
   * surface_registry.cc (doc/adding_a_surface.md).
   */
  class SurfaceRegistry
  {
  public:
    enum class Kind
    {
      deformable,
      rigid
    };

    struct Entry
    {
      std::string name;
      Kind        kind;
      std::string description;
      std::function<std::unique_ptr<MasterSurface>(const SurfaceContext &)>
        create;
    };

    static const std::vector<Entry> &
    entries();

    /** The surface of a contact pair (the kind follows from its master). */
    static std::unique_ptr<MasterSurface>
    create(const SurfaceContext &context);

    /** "faceted|bspline|..." for Patterns::Selection. */
    static std::string
    names_as_pattern(Kind kind);

    /** "faceted: ...; bspline: ..." for the parameter documentation. */
    static std::string
    documentation(Kind kind);
  };
} // namespace glissade

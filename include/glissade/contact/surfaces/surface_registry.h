#pragma once

#include <deal.II/base/parameter_handler.h>

#include <glissade/contact/surfaces/master_surface.h>
#include <glissade/description/scene_description.h>

#include <any>
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
    /** Which curve of the master boundary (MasterChain::build_all): a
     *  boundary of several curves gets a surface per curve. */
    unsigned int curve = 0;
  };

  /**
   * The master surfaces a .prm may name: `Surface` of a pair with a master
   * body (deformable), `Obstacle/Type` of a pair with `Master body = rigid`.
   * Adding a surface is one file that defines its factory and one line in
   * surface_registry.cc (doc/adding_a_surface.md).
   *
   * A surface with options of its own declares and reads them itself, as
   * ASPECT's plug-ins do: its entry's `declare_parameters` declares them
   * in the pair's subsection (a deformable surface) or in its Obstacle
   * subsection (a rigid one), for every pair, and `parse_parameters` reads
   * them for a pair that chose it, into the settings its factory finds in
   * ContactDescription::surface_settings. The generic description never
   * sees them.
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
      /** Declares the surface's own entries (none if empty). */
      std::function<void(dealii::ParameterHandler &)> declare_parameters = {};
      /**
       * Reads them for a pair that chose the surface (in the subsection
       * they were declared in); `where` names the subsection for messages
       * ("file.prm: Contact <pair>"), `prm_file` is the .prm file they are
       * read from (a file an entry names is beside it). Returns the
       * surface's settings.
       */
      std::function<std::any(const dealii::ParameterHandler &,
                             const std::string &where,
                             const std::string &prm_file)>
        parse_parameters = {};
    };

    static const std::vector<Entry> &
    entries();

    /** The surface of a contact pair (the kind follows from its master). */
    static std::unique_ptr<MasterSurface>
    create(const SurfaceContext &context);

    /** Every surface's own entries, of one kind, in the current subsection. */
    static void
    declare_parameters(dealii::ParameterHandler &prm, Kind kind);

    /** The settings of the surface `name` from its own entries (empty if it
     *  has none). */
    static std::any
    parse_parameters(const dealii::ParameterHandler &prm,
                     Kind                            kind,
                     const std::string              &name,
                     const std::string              &where,
                     const std::string              &prm_file);

    /** "faceted|bspline|..." for Patterns::Selection. */
    static std::string
    names_as_pattern(Kind kind);

    /** "faceted: ...; bspline: ..." for the parameter documentation. */
    static std::string
    documentation(Kind kind);
  };
} // namespace glissade

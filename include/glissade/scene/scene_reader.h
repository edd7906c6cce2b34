#pragma once

#include <deal.II/base/parameter_handler.h>

#include <glissade/description/scene_description.h>

#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * Reads a scene from a .prm file.
   *
   * The set of bodies is itself an input ("Scene/Bodies = beam, ring"), and a
   * ParameterHandler only parses entries it knows. So reading is two passes:
   * the first learns the body names (skipping everything else), the second
   * declares a "Body <name>" subsection for each and parses the whole file
   * strictly, so that a misspelt entry is an error, not silently ignored.
   *
   * Every mistake is reported as an InputError naming the file and the entry.
   */
  class SceneReader
  {
  public:
    /**
     * Overrides are "Subsection/.../Entry=value" strings applied after the
     * file (the command line's --set), e.g. "Body beam/Mesh/Subdivisions=60,4".
     */
    static SceneDescription
    read_file(const std::string              &filename,
              const std::vector<std::string> &overrides = {});

    /** The same from text in memory (tests); name is used in messages. */
    static SceneDescription
    read_string(const std::string              &text,
                const std::string              &name,
                const std::vector<std::string> &overrides = {});

    /**
     * The "Study" entry of a file: "simulation" (the default: run the scene)
     * or the name of a study driver ("geometric").
     */
    static std::string
    study_type(const std::string &filename);

    /**
     * The study drivers a program offers beside "simulation", by name with
     * one sentence each: the Study entry's pattern and help are made from
     * them. The program registers its table before it reads a file
     * (applications/glissade/main.cc); a program without drivers (the
     * tests) registers none, and its Study is "simulation".
     */
    static void
    register_studies(
      const std::vector<std::pair<std::string, std::string>> &studies);

    /**
     * prm.get_double() and get_integer() for study drivers: a value that
     * matches its pattern but does not convert (a denormal, an integer out
     * of range) is an InputError that names the file and the entry, like
     * any other mistake in the input.
     */
    static double
    get_double(const dealii::ParameterHandler &prm,
               const std::string              &entry,
               const std::string              &filename);

    static long int
    get_integer(const dealii::ParameterHandler &prm,
                const std::string              &entry,
                const std::string              &filename);

    /**
     * Parses a study driver's file into `prm` (whose entries the driver has
     * declared) and applies the command line's overrides, with the same
     * messages as for scenes.
     */
    static void
    parse_study(dealii::ParameterHandler       &prm,
                const std::string              &filename,
                const std::vector<std::string> &overrides);

    /** Every parameter with its documentation and default, for one body. */
    static void
    print_parameters(std::ostream &out);

  private:
    /** `regions`: each body's material regions (Material/Regions). */
    static void
    declare_parameters(
      dealii::ParameterHandler                              &prm,
      const std::vector<std::string>                        &body_names,
      const std::vector<std::string>                        &contact_names,
      const std::map<std::string, std::vector<std::string>> &regions = {});

    static SceneDescription
    parse_parameters(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &body_names,
                     const std::vector<std::string> &contact_names,
                     const std::string              &source);
  };
} // namespace glissade

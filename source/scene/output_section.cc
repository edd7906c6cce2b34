// Output (what is written, how often, how compressed) and Checkpoint (a
// long run in batches).

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/description/scene_description.h>
#include <glissade/scene/section_reader.h>

#include <algorithm>
#include <string>

namespace glissade
{
  using namespace dealii;

  void
  OutputSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::Anything(),
                      "Where VTU/PVD, history.csv and summary.txt go "
                      "(relative paths: from the working directory).");
    prm.declare_entry("VTU interval",
                      "1",
                      Patterns::Integer(0),
                      "Write a VTU every this many increments (0: only the "
                      "initial and final states).");
    prm.declare_entry("Initial state",
                      "true",
                      Patterns::Bool(),
                      "Write the VTU files and contact tables of increment "
                      "0 (the reference configuration, no contact force); "
                      "false: only the increments that the intervals ask "
                      "for and the final state.");
    prm.declare_entry("VTU compression",
                      "fast",
                      Patterns::Selection("fast|small|none"),
                      "zlib compression of the bodies' VTU files: fast "
                      "(zlib level 1), small (level 9, deal.II's default: "
                      "a little smaller, written several times slower; "
                      "doc/performance.md), none (uncompressed).");
    prm.declare_entry("VTU fields",
                      "displacement, stress",
                      Patterns::MultipleSelection("displacement|stress"),
                      "The fields of the bodies' VTU files: displacement, "
                      "and stress (sigma_xx, sigma_yy, sigma_xy, sigma_zz "
                      "and von_Mises, computed at the output; Plots colours "
                      "the deformed mesh by it). Only displacement writes "
                      "the VTU files several times faster "
                      "(doc/performance.md).");
    prm.declare_entry("Contact table interval",
                      "0",
                      Patterns::Integer(0),
                      "Write contact-<pair>-<increment>.csv (every slave "
                      "node's gap, reaction, status) every this many "
                      "increments; 0: with the VTU files.");
    prm.declare_entry(
      "Contact tables",
      "per pair",
      Patterns::Selection("per pair|per body"),
      "per pair: contact-<pair>-<increment>.csv and .vtu, each pair's slave "
      "nodes. per body: contact-of-<body>-<increment>.csv and .vtu, each "
      "body's slave nodes once over all the pairs it is the slave of (forces "
      "summed, the smallest gap, the pair that carries most): where "
      "automatic contact makes many pairs.");
    prm.declare_entry(
      "History",
      "",
      Patterns::Anything(),
      "Columns of history.csv, ';'-separated: displacement(body, point(x, "
      "y)), max_displacement(body), reaction(body, boundary), "
      "contact_force(pair) (total force on the slave and active nodes), "
      "contact_force_on(body) (every pair's force on the body), "
      "contact_node(pair, point(x, y)) (r_n, r_t, |f|, gap of the slave node "
      "at that reference position).");
    prm.declare_entry("Progress",
                      "true",
                      Patterns::Bool(),
                      "Print one line per increment.");
    prm.declare_entry("Plots",
                      "false",
                      Patterns::Bool(),
                      "At the end of the run (or at a stop), draw PNGs "
                      "from the written files: history.png (every history "
                      "column against t, and the Newton iterations), and "
                      "contact-<pair>-pressure.png (the pressure along "
                      "each slave boundary at the written increments) and "
                      "deformed-mesh.png (the bodies in their last written "
                      "state, coloured by von Mises). "
                      "Needs Debian's /usr/bin/python3 with matplotlib; "
                      "without it the run says so and goes on.");
    prm.declare_entry(
      "Plot curves",
      "",
      Patterns::Anything(),
      "With Plots: curves.png, one panel per 'x column: y "
      "column' item (';'-separated), each a column of "
      "history.csv (or time), e.g. a force-displacement "
      "curve 'pad_uy_0_10: pad_Ry_top'. Checked, but drawn only with "
      "Plots = true.");
    prm.leave_subsection();
  }



  void
  OutputSettings::parse_parameters(SectionReader &prm)
  {
    prm.enter_subsection("Output");
    directory    = prm.get("Directory");
    vtu_interval = prm.get_integer("VTU interval");
    {
      using Compression       = OutputSettings::Compression;
      const std::string level = prm.get("VTU compression");
      vtu_compression         = level == "small" ? Compression::small :
                                level == "none"  ? Compression::none :
                                                   Compression::fast;
    }
    const std::string fields = prm.get("VTU fields");
    {
      const auto listed = Utilities::split_string_list(fields);
      const auto has    = [&](const char *field) {
        return std::find(listed.begin(), listed.end(), field) != listed.end();
      };
      vtu_displacement = has("displacement");
      vtu_stress       = has("stress");
    }
    initial_state          = prm.get_bool("Initial state");
    contact_table_interval = prm.get_integer("Contact table interval");
    contact_tables         = prm.get("Contact tables") == "per body" ?
                               ContactTables::per_body :
                               ContactTables::per_pair;
    for (const auto &item : text::split_top_level(prm.get("History"), ';'))
      if (!item.empty())
        history.push_back(item);
    progress                 = prm.get_bool("Progress");
    plots                    = prm.get_bool("Plots");
    const std::string curves = prm.get("Plot curves");
    prm.leave_subsection();
    prm.check([&]() {
      if (!vtu_displacement && !vtu_stress)
        throw InputError(prm.file() + ": Output/VTU fields",
                         "names no field: list displacement, stress or "
                         "both (to write no VTU file at all, see VTU "
                         "interval and Initial state)");
    });
    prm.check([&]() {
      for (const auto &item : text::split_top_level(curves, ';'))
        {
          if (text::trim(item).empty())
            continue;
          const auto parts = Utilities::split_string_list(item, ':');
          if (parts.size() != 2 || parts[0].empty() || parts[1].empty())
            throw InputError(prm.file() + ": Output/Plot curves",
                             "'" + text::trim(item) +
                               "' is not 'x column: y column' (names of "
                               "history.csv, e.g. 'pad_uy_0_10: "
                               "pad_Ry_top')");
          plot_curves.emplace_back(parts[0], parts[1]);
        }
    });
  }



  void
  CheckpointSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.declare_entry("Interval",
                      "0",
                      Patterns::Integer(0),
                      "Write <Output directory>/checkpoint.bin every this "
                      "many converged increments (0: never). 'glissade "
                      "scene.prm --restart' continues from it to the same "
                      "output as an uninterrupted run.");
    prm.declare_entry("Stop after increment",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint after this increment and stop "
                      "cleanly (0: run to the end): a long study in "
                      "batches of a queue's time limit.");
    prm.leave_subsection();
  }



  void
  CheckpointSettings::parse_parameters(SectionReader     &prm,
                                       const LoadProgram &load_program)
  {
    prm.enter_subsection("Checkpoint");
    interval   = prm.get_integer("Interval");
    stop_after = prm.get_integer("Stop after increment");
    prm.leave_subsection();
    unsigned int n_increments = 0;
    for (const unsigned int n : load_program.stage_increments)
      n_increments += n;
    prm.check([&]() {
      if (stop_after > n_increments)
        throw InputError(prm.file() + ": Checkpoint/Stop after increment",
                         "is " + std::to_string(stop_after) +
                           ", beyond the last increment of the load program (" +
                           std::to_string(n_increments) + ")");
    });
  }
} // namespace glissade

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/plotting.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <paper_studies/friction_study.h>
#include <paper_studies/study_progress.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** "0.1" rather than "0.100000". */
    std::string
    short_number(const double value)
    {
      std::ostringstream text;
      text << value;
      return text.str();
    }

    /**
     * The overrides that give every deformable master the variant's
     * surface (hermite: its body's elements too; the slave bodies keep
     * theirs) and every pair the friction coefficient.
     */
    std::vector<std::string>
    variant_overrides(const SceneDescription &scene,
                      const std::string      &variant,
                      const double            friction)
    {
      if (variant != "q4" && variant != "bspline" && variant != "hermite")
        throw InputError("Friction study/Variants",
                         "unknown variant '" + variant +
                           "' (known: q4, bspline, hermite)");
      std::vector<std::string> overrides;
      for (const auto &contact : scene.contacts)
        {
          overrides.push_back(
            "Contact " + contact.name +
            "/Friction coefficient=" + short_number(friction));
          if (contact.master == ContactDescription::MasterKind::obstacle)
            continue;
          overrides.push_back("Contact " + contact.name + "/Surface=" +
                              (variant == "q4" ? "faceted" : variant));
          if (variant == "hermite")
            overrides.push_back("Body " + contact.master_body +
                                "/Element/Space=hermite");
        }
      return overrides;
    }
  } // namespace



  FrictionRun
  FrictionStudy::run_variant(const std::string              &scene_file,
                             const std::string              &variant,
                             const double                    friction,
                             const std::string              &output_directory,
                             const std::vector<std::string> &extra_overrides)
  {
    const SceneDescription base =
      SceneReader::read_file(scene_file, extra_overrides);
    std::vector<std::string> overrides = extra_overrides;
    for (const auto &o : variant_overrides(base, variant, friction))
      overrides.push_back(o);
    overrides.push_back("Output/Progress=false");
    overrides.push_back("Output/Directory=" + output_directory + "/" + variant +
                        "-mu" + short_number(friction));
    Simulation simulation(SceneReader::read_file(scene_file, overrides));

    FrictionRun run;
    run.variant  = variant;
    run.friction = friction;
    for (const auto &b : simulation.bodies())
      run.dofs += b->n_dofs();
    const auto &pairs = simulation.contact().contact_pairs();

    run.first_stage_end = base.load_program.stage_end_times.at(0);
    for (const auto &pair : pairs)
      for (const auto &node : pair->nodes())
        {
          run.node_positions.push_back(
            {{node.reference_position[0], node.reference_position[1]}});
          run.node_pairs.push_back(pair->name());
        }

    simulation.on_increment = [&](const unsigned int, const double time) {
      double       normal = 0., tangential = 0., largest_rn = 0., excess = 0.;
      unsigned int sticking = 0, slipping = 0, open = 0;
      std::vector<double>        norms;
      std::vector<unsigned char> status;
      for (const auto &pair : pairs)
        for (const auto &node : pair->nodes())
          {
            const bool closed = node.active && node.reaction[1] > 0.;
            if (!closed)
              {
                ++open;
                status.push_back(0);
                continue;
              }
            const double rn = node.reaction[1], rt = node.reaction[0];
            normal += rn;
            tangential += std::abs(rt);
            largest_rn = std::max(largest_rn, rn);
            norms.push_back(node.force().norm());
            // Coulomb's bound, widened at a faceted vertex met with its
            // cone (the Faceted vertex rule vertex normal).
            const double bound = cone_slope(pair->settings().friction,
                                            node.linearization.vertex_cone);
            excess             = std::max(excess, std::abs(rt) - bound * rn);
            // The solver's status; a frictionless closed node slides.
            const bool sticks =
              bound > 0. && node.status == BiPotentialSolver::NodeStatus::stick;
            ++(sticks ? sticking : slipping);
            status.push_back(sticks ? 1 : 2);
          }
      if (largest_rn > 0.)
        run.worst_cone_excess =
          std::max(run.worst_cone_excess, excess / largest_rn);
      double mean = 0., spread = 0.;
      for (const double f : norms)
        mean += f / norms.size();
      for (const double f : norms)
        spread = std::max(spread, 100. * std::abs(f - mean) / mean);
      run.time.push_back(time);
      run.normal_force.push_back(normal);
      run.tangential_force.push_back(tangential);
      run.sticking.push_back(sticking);
      run.slipping.push_back(slipping);
      run.open.push_back(open);
      run.spread_percent.push_back(spread);
      run.status.push_back(std::move(status));
    };

    Timer timer;
    simulation.run();
    run.wall_seconds      = timer.wall_time();
    run.newton_iterations = simulation.statistics().newton_iterations;
    run.cut_backs         = simulation.statistics().cut_backs;
    return run;
  }



  void
  FrictionStudy::run(const std::string              &prm_file,
                     const std::vector<std::string> &command_line)
  {
    ParameterHandler prm;
    prm.declare_entry("Study", "friction", Patterns::Selection("friction"));
    prm.enter_subsection("Friction study");
    prm.declare_entry("Scene",
                      "",
                      Patterns::Anything(),
                      "The scene (relative to this file's folder).");
    prm.declare_entry("Variants",
                      "q4, bspline, hermite",
                      Patterns::List(Patterns::Selection("q4|bspline|hermite")),
                      "Master surfaces: q4 (faceted), bspline, hermite (the "
                      "master bodies' elements too; the slave bodies keep "
                      "theirs).");
    prm.declare_entry("Friction coefficients",
                      "0, 0.1, 0.3",
                      Patterns::List(Patterns::Double(0., 100.)),
                      "Coulomb's mu, set on every contact pair.");
    prm.declare_entry("Scene changes",
                      "",
                      Patterns::Anything(),
                      "Entries of the scene to change, 'Section/Entry=value' "
                      "separated by ';' (as --set would, e.g. to shorten the "
                      "load program).");
    prm.declare_entry("Output directory",
                      "output/friction_study",
                      Patterns::Anything(),
                      "Where CSVs and PNGs go.");
    prm.leave_subsection();
    SceneReader::parse_study(prm, prm_file, command_line);
    prm.enter_subsection("Friction study");
    if (text::trim(prm.get("Scene")).empty())
      throw InputError(prm_file + ": Friction study/Scene",
                       "is empty: name the scene to study");
    const std::string scene = text::path_beside(prm_file, prm.get("Scene"));
    const auto        variants =
      Utilities::split_string_list(prm.get("Variants"), ',');
    std::vector<double> coefficients;
    for (const auto &mu :
         Utilities::split_string_list(prm.get("Friction coefficients"), ','))
      coefficients.push_back(Utilities::string_to_double(mu));
    std::vector<std::string> changes;
    for (const auto &change :
         Utilities::split_string_list(prm.get("Scene changes"), ';'))
      if (!text::trim(change).empty())
        changes.push_back(text::trim(change));
    const std::string directory = prm.get("Output directory");
    prm.leave_subsection();
    std::filesystem::create_directories(directory);

    std::vector<FrictionRun> runs;
    StudyProgress            progress(variants.size() * coefficients.size());
    for (const auto &variant : variants)
      for (const double mu : coefficients)
        {
          progress.next(variant + ", mu = " + short_number(mu));
          runs.push_back(run_variant(scene, variant, mu, directory, changes));
        }

    AtomicFile history(directory + "/friction_history.csv");
    history.stream() << "variant,friction,increment,time,normal_force,"
                        "tangential_force,sticking,slipping,open,"
                        "spread_percent\n";
    AtomicFile status(directory + "/friction_status.csv");
    status.stream() << "variant,friction,increment,status\n";
    for (const auto &r : runs)
      for (unsigned int i = 0; i < r.time.size(); ++i)
        {
          history.stream() << std::setprecision(10) << r.variant << ','
                           << r.friction << ',' << i + 1 << ',' << r.time[i]
                           << ',' << r.normal_force[i] << ','
                           << r.tangential_force[i] << ',' << r.sticking[i]
                           << ',' << r.slipping[i] << ',' << r.open[i] << ','
                           << r.spread_percent[i] << '\n';
          // One character per slave node: o open, t stick, s slip.
          std::string codes;
          for (const unsigned char c : r.status[i])
            codes += c == 0 ? 'o' : c == 1 ? 't' : 's';
          status.stream() << r.variant << ',' << r.friction << ',' << i + 1
                          << ',' << codes << '\n';
        }
    history.commit();
    status.commit();
    AtomicFile nodes(directory + "/friction_nodes.csv");
    nodes.stream() << "node,pair,x,y\n" << std::setprecision(12);
    if (!runs.empty())
      for (unsigned int k = 0; k < runs[0].node_positions.size(); ++k)
        nodes.stream() << k << ',' << runs[0].node_pairs[k] << ','
                       << runs[0].node_positions[k][0] << ','
                       << runs[0].node_positions[k][1] << '\n';
    nodes.commit();

    std::cout << "\nFriction study of " << scene
              << " (at the end; ratio: sum |r_t| / sum r_n; spread: largest "
                 "over the increments after the first stage)\n"
              << std::setw(9) << "master" << std::setw(6) << "mu"
              << std::setw(8) << "dofs" << std::setw(10) << "wall (s)"
              << std::setw(8) << "Newton" << std::setw(6) << "cuts"
              << std::setw(14) << "sum r_n" << std::setw(14) << "sum |r_t|"
              << std::setw(11) << "ratio" << std::setw(7) << "stick"
              << std::setw(6) << "slip" << std::setw(13) << "spread (%)"
              << std::setw(13) << "cone excess" << '\n';
    for (const auto &r : runs)
      {
        // Case 3's uniformity measure, after the first stage (there: the
        // rotation of a uniformly loaded interface); a scene of one stage
        // has no such stage, and its spread is in the CSV.
        const bool one_stage =
          r.time.empty() || r.time.back() <= r.first_stage_end * (1. + 1e-12);
        double spread = 0.;
        for (unsigned int i = 0; i < r.time.size(); ++i)
          if (r.time[i] > r.first_stage_end * (1. + 1e-12))
            spread = std::max(spread, r.spread_percent[i]);
        std::ostringstream spread_text;
        spread_text << std::setprecision(3) << spread;
        const double n = r.normal_force.empty() ? 0. : r.normal_force.back();
        const double t =
          r.tangential_force.empty() ? 0. : r.tangential_force.back();
        std::cout << std::setw(9) << r.variant << std::setw(6) << r.friction
                  << std::setw(8) << r.dofs << std::setw(10)
                  << std::setprecision(3) << r.wall_seconds << std::setw(8)
                  << r.newton_iterations << std::setw(6) << r.cut_backs
                  << std::setw(14) << std::setprecision(6) << n << std::setw(14)
                  << t << std::setw(11) << std::setprecision(4)
                  << (n > 0. ? t / n : 0.) << std::setw(7)
                  << (r.sticking.empty() ? 0 : r.sticking.back())
                  << std::setw(6)
                  << (r.slipping.empty() ? 0 : r.slipping.back())
                  << std::setw(13) << (one_stage ? "-" : spread_text.str())
                  << std::setw(13) << std::setprecision(2)
                  << r.worst_cone_excess << '\n';
      }
    std::cout << "(Newton: iterations in the run; cuts: increments cut "
                 "back; cone excess: max over closed nodes of |r_t| - mu r_n, "
                 "relative to the increment's largest r_n; Coulomb's law "
                 "holds if it is at round-off)\n"
              << std::flush;
    plot_with_python("plot_friction.py", directory);
  }
} // namespace glissade

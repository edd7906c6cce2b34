#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/plotting.h>
#include <glissade/scene/scene_reader.h>

#include <paper_studies/study_progress.h>
#include <paper_studies/trade_measures.h>
#include <paper_studies/trade_study.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** One discretisation at one mesh parameter, and what it gave. */
    struct SweepPoint
    {
      std::string  discretisation;
      unsigned int n = 0;
      TradePoint   figures;
      double       peak_megabytes = 0.;
      double       error          = 0.;
    };

    /** The sections of the .prm, one per group of measures. */
    std::string
    section_of(const std::string &measure)
    {
      if (measure.rfind("geometric", 0) == 0)
        return "Geometric";
      if (measure == "table1")
        return "Table 1";
      if (measure == "hertz")
        return "Hertz";
      // "case3_torque" reads case 3's settings.
      return "Case " + measure.substr(4, 1);
    }

    /**
     * "q4: 40 80 160; hermite: 20 40" -> {(q4, 40), (q4, 80), ...}, each
     * discretisation checked against those the measure knows.
     */
    std::vector<std::pair<std::string, unsigned int>>
    parse_sweep(const std::string &text,
                const std::string &measure,
                const std::string &entry)
    {
      std::vector<std::pair<std::string, unsigned int>> points;
      const auto &known = TradeMeasures::discretisations(measure);
      for (const std::string &group : text::split_top_level(text, ';'))
        {
          if (text::trim(group).empty())
            continue;
          const auto        colon = group.find(':');
          const std::string name =
            text::trim(group.substr(0, colon == std::string::npos ? 0 : colon));
          if (colon == std::string::npos ||
              std::find(known.begin(), known.end(), name) == known.end())
            {
              std::string list;
              for (const auto &k : known)
                list += (list.empty() ? "" : ", ") + k;
              throw InputError(entry,
                               "'" + text::trim(group) +
                                 "' is not 'discretisation: n n ...' "
                                 "with a discretisation among " +
                                 list);
            }
          std::istringstream numbers(group.substr(colon + 1));
          std::string        word;
          while (numbers >> word)
            {
              const bool digits =
                word.find_first_not_of("0123456789") == std::string::npos;
              const long n = digits && word.size() < 7 ? std::stol(word) : 0;
              const bool even =
                measure.rfind("geometric", 0) != 0 || n % 2 == 0;
              if (n < 4 || !even)
                throw InputError(entry,
                                 "'" + word + "' after '" + name +
                                   "' is not a number of elements of "
                                   "at least 4" +
                                   (even ? "" : " and even"));
              points.emplace_back(name, static_cast<unsigned int>(n));
            }
        }
      return points;
    }

    /**
     * Runs one point in a child process, so that its peak memory (wait4's
     * ru_maxrss) is its own and not the largest of the sweep so far. The
     * figures come back through a pipe; a failed point ends the study with
     * the child's message above.
     */
    TradePoint
    run_in_child(const std::function<TradePoint()> &point,
                 double                            &peak_megabytes)
    {
      int channel[2];
      if (pipe(channel) != 0)
        throw std::runtime_error("trade study: cannot create a pipe");
      std::cout << std::flush;
      const pid_t child = fork();
      if (child < 0)
        throw std::runtime_error("trade study: cannot fork");
      if (child == 0)
        {
          close(channel[0]);
          int status = 0;
          try
            {
              const TradePoint p = point();
              if (write(channel[1], &p, sizeof(p)) != sizeof(p))
                status = 1;
            }
          catch (const std::exception &e)
            {
              std::cerr << "\ntrade study: " << text::essential_message(e)
                        << std::endl;
              status = 1;
            }
          close(channel[1]);
          std::cout << std::flush;
          _exit(status);
        }
      close(channel[1]);
      TradePoint    p;
      const ssize_t got = read(channel[0], &p, sizeof(p));
      close(channel[0]);
      int           status = 0;
      struct rusage usage;
      wait4(child, &status, 0, &usage);
      if (got != sizeof(p) || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("trade study: a point of the sweep failed "
                                 "(see the message above)");
      peak_megabytes = usage.ru_maxrss / 1024.; // Linux: kilobytes
      return p;
    }

    /** y = factor n^exponent, least squares in log-log. */
    struct PowerLaw
    {
      bool   valid  = false;
      double factor = 0., exponent = 0.;

      PowerLaw(const std::vector<double> &n, const std::vector<double> &y)
      {
        std::vector<double> x, v;
        for (unsigned int i = 0; i < n.size(); ++i)
          if (y[i] > 0.)
            {
              x.push_back(std::log(n[i]));
              v.push_back(std::log(y[i]));
            }
        const double m = x.size();
        if (m < 2)
          return;
        double sx = 0., sy = 0., sxx = 0., sxy = 0.;
        for (unsigned int i = 0; i < m; ++i)
          {
            sx += x[i];
            sy += v[i];
            sxx += x[i] * x[i];
            sxy += x[i] * v[i];
          }
        if (m * sxx - sx * sx <= 0.)
          return;
        exponent = (m * sxy - sx * sy) / (m * sxx - sx * sx);
        factor   = std::exp((sy - exponent * sx) / m);
        valid    = true;
      }

      double
      operator()(const double n) const
      {
        return factor * std::pow(n, exponent);
      }
    };

    std::string
    figure(const double x, const int digits = 3)
    {
      std::ostringstream s;
      s << std::setprecision(digits) << x;
      return s.str();
    }

    /**
     * The markdown table of one measure and its cross-overs: for each
     * point that is not plain Q4, the cheapest Q4 point of the sweep at
     * least as accurate, or, beyond the sweep, the power laws fitted to the
     * Q4 points (labelled as an extrapolation).
     */
    std::string
    report(const std::string             &measure,
           const std::vector<SweepPoint> &points,
           const std::string             &reference)
    {
      std::ostringstream out;
      out << "### " << measure << ": " << TradeMeasures::error_name(measure)
          << "\n\n";
      if (!reference.empty())
        out << "Reference: " << reference << ".\n\n";
      out << "| discretisation | n | dofs | Newton | active | wall (s) | "
             "peak (MB) | error |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
      for (const auto &p : points)
        out << "| " << p.discretisation << " | " << p.n << " | "
            << p.figures.dofs << " | " << p.figures.newton_iterations << " | "
            << p.figures.active_nodes << " | " << figure(p.figures.wall_seconds)
            << " | " << figure(p.peak_megabytes) << " | " << figure(p.error)
            << " |\n";

      std::vector<double> n, error, time, dofs;
      for (const auto &p : points)
        if (p.discretisation == "q4")
          {
            n.push_back(p.n);
            error.push_back(p.error);
            time.push_back(p.figures.wall_seconds);
            dofs.push_back(p.figures.dofs);
          }
      const PowerLaw error_law(n, error), time_law(n, time), dofs_law(n, dofs);
      out << '\n';
      if (error_law.valid)
        out << "Q4 over the sweep: error ~ n^" << figure(error_law.exponent)
            << ", wall time ~ n^" << figure(time_law.exponent) << ", dofs ~ n^"
            << figure(dofs_law.exponent) << ".\n\n";
      out << "| point | its error | its time (s) | the Q4 that matches | "
             "Q4 time (s) | Q4 dofs |\n|---|---:|---:|---|---:|---:|\n";
      for (const auto &p : points)
        {
          if (p.discretisation == "q4")
            continue;
          const SweepPoint *match = nullptr;
          for (const auto &q : points)
            if (q.discretisation == "q4" && q.error <= p.error &&
                (!match ||
                 q.figures.wall_seconds < match->figures.wall_seconds))
              match = &q;
          out << "| " << p.discretisation << ' ' << p.n << " | "
              << figure(p.error) << " | " << figure(p.figures.wall_seconds)
              << " | ";
          if (match)
            out << "q4 " << match->n << " (in the sweep) | "
                << figure(match->figures.wall_seconds) << " | "
                << match->figures.dofs << " |\n";
          else if (error_law.valid && error_law.exponent > -0.3)
            // (an extrapolation of a Q4 error that hardly falls would name
            // meshes of 1e20 elements: Q4 does not get there)
            out << "none: Q4's error hardly falls (n^"
                << figure(error_law.exponent) << ") | | |\n";
          else if (error_law.valid && p.error > 0.)
            {
              const double needed =
                std::pow(p.error / error_law.factor, 1. / error_law.exponent);
              out << "about " << figure(needed, 2)
                  << " (fit, beyond the sweep) | "
                  << figure(time_law(needed), 2) << " | "
                  << figure(dofs_law(needed), 2) << " |\n";
            }
          else
            out << "none in the sweep, no fit | | |\n";
        }
      out << '\n';
      return out.str();
    }
  } // namespace



  void
  TradeStudy::run(const std::string              &prm_file,
                  const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    prm.declare_entry("Study", "trade", Patterns::Selection("trade"));
    prm.enter_subsection("Trade study");
    {
      std::string measures;
      for (const auto &m : TradeMeasures::names())
        measures += (measures.empty() ? "" : "|") + m;
      prm.declare_entry("Measures",
                        "geometric_gap, geometric_normal, table1, case1, "
                        "case2, case3, hertz",
                        Patterns::List(Patterns::Selection(measures)),
                        "The paper's measures of accuracy to sweep.");
      prm.declare_entry("Output directory",
                        "output/trade_study",
                        Patterns::Anything(),
                        "Where the CSVs, PNGs and "
                        "trade_tables.md go.");
      const auto sweep = [&](const std::string &default_value,
                             const std::string &what) {
        prm.declare_entry("Sweep",
                          default_value,
                          Patterns::Anything(),
                          "'discretisation: n n ...; ...': " + what);
      };
      prm.enter_subsection("Geometric");
      sweep("q4: 8 16 32 64 128 256; q8: 8 16 32 64; q12: 8 16 32 64; "
            "bspline: 8 16 32 64; hermite: 8 16 32 64; nurbs2: 8 16 32; "
            "nurbs3: 8 16 32",
            "elements along the half ring's outer edge (even).");
      prm.leave_subsection();
      prm.enter_subsection("Table 1");
      prm.declare_entry("Scene",
                        "table1_beam.prm",
                        Patterns::Anything(),
                        "Table 1's beam (relative to this file's folder).");
      sweep("q4: 30 60 120 240 480; q8: 30 60 120; q9: 30 60 120; "
            "q12: 30 60 120; hermite: 30 60 120; nurbs2: 30 60 120; "
            "nurbs3: 30 60 120",
            "elements along the beam (n/15 across).");
      prm.declare_entry("Reference",
                        "q16: 240",
                        Patterns::Anything(),
                        "'discretisation: n': the run the errors are taken "
                        "against.");
      prm.leave_subsection();
      prm.enter_subsection("Case 1");
      prm.declare_entry("Scene",
                        "case1_beam_ring.prm",
                        Patterns::Anything(),
                        "Case 1 with the deformable ring.");
      sweep("q4: 30 60 120; bspline: 30 60 120; bspline-spline: 60; "
            "hermite: 30 60",
            "elements along the beam and the ring (n/15 across).");
      prm.declare_entry("Reference",
                        "hermite: 120",
                        Patterns::Anything(),
                        "'discretisation: n': the run the errors are taken "
                        "against.");
      prm.leave_subsection();
      prm.enter_subsection("Case 2");
      prm.declare_entry("Scene",
                        "case2_sliding.prm",
                        Patterns::Anything(),
                        "Case 2's scene.");
      sweep(
        "q4: 60 120 240; bspline: 60 120; bspline-spline: 120; "
        "hermite: 60 120",
        "elements around each ring (n/15 across; the square about n/12 a side, even).");
      prm.declare_entry("Increments",
                        "250",
                        Patterns::Integer(1),
                        "Increments of the push (250 over half the scene's "
                        "load: the paper's 1e-4 m each, the contact phase).");
      prm.declare_entry("Load fraction",
                        "0.5",
                        Patterns::Double(0., 1.),
                        "Share of the scene's load program that is run.");
      prm.leave_subsection();
      prm.enter_subsection("Case 3");
      prm.declare_entry("Scene",
                        "case3_rings.prm",
                        Patterns::Anything(),
                        "Case 3's scene.");
      sweep("q4: 40 80 160; bspline: 40 80; bspline-spline: 40; "
            "hermite: 20 40 80; nurbs2-mortar: 12 20 40; "
            "nurbs3-mortar: 8 12 20 40",
            "elements around the rings (multiples of 4; Hermite: the outer "
            "ring, the inner Q4 ring keeps 40; nurbs2-mortar, "
            "nurbs3-mortar: both rings NURBS, mortar on the inner one's "
            "boundary).");
      prm.declare_entry("Rotation angle",
                        "9",
                        Patterns::Double(0.),
                        "Degrees of rotation after the compression: the same "
                        "for every point (9: one element at 40).");
      prm.declare_entry("Increments per element",
                        "50",
                        Patterns::Integer(1),
                        "Rotation increments per element crossed, so that "
                        "every mesh samples its ripple alike (the paper: 50).");
      prm.leave_subsection();
      prm.enter_subsection("Hertz");
      prm.declare_entry("Scene",
                        "hertz_trade.prm",
                        Patterns::Anything(),
                        "Hertz's quarter cylinder (radius Radius, its arc "
                        "the slave 'touch' pair) on the flat block, both of "
                        "one material, small strain.");
      sweep("q4: 30 60 120 240; bspline: 30 60 120 240; hermite: 30 60 "
            "120; mortar: 30 60 120 240 480; nurbs2-mortar: 30 60 120 240; "
            "nurbs3-mortar: 30 60 120 240",
            "elements along the cylinder's arc and the block's top (5 n / 12 "
            "inwards), graded as the scene grades them.");
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(0.),
                        "The cylinder's radius: Hertz's R.");
      prm.leave_subsection();
    }
    prm.leave_subsection();
    SceneReader::parse_study(prm, prm_file, overrides);

    prm.enter_subsection("Trade study");
    const std::vector<std::string> measures =
      Utilities::split_string_list(prm.get("Measures"), ',');
    const std::string directory = prm.get("Output directory");
    std::filesystem::create_directories(directory);

    std::string tables =
      "# The speed-accuracy trade: the figures of this run\n\n"
      "Errors: smaller is better. Wall time of the point alone (Release "
      "build wanted); peak memory of its process. Cross-overs: the "
      "cheapest plain Q4 mesh that is as accurate.\n\n";
    for (const std::string &measure : measures)
      {
        const std::string section = section_of(measure);
        prm.enter_subsection(section);
        const std::string where = "Trade study/" + section + "/";
        const auto        points =
          parse_sweep(prm.get("Sweep"), measure, where + "Sweep");
        std::string         scene;
        std::vector<double> settings;
        if (measure.rfind("geometric", 0) != 0)
          scene = text::path_beside(prm_file, prm.get("Scene"));
        if (measure == "case2")
          settings = {double(
                        SceneReader::get_integer(prm, "Increments", prm_file)),
                      SceneReader::get_double(prm, "Load fraction", prm_file)};
        if (measure == "hertz")
          settings = {SceneReader::get_double(prm, "Radius", prm_file)};
        if (measure.rfind("case3", 0) == 0)
          settings = {SceneReader::get_double(prm, "Rotation angle", prm_file),
                      double(SceneReader::get_integer(prm,
                                                      "Increments per element",
                                                      prm_file))};
        std::vector<std::pair<std::string, unsigned int>> reference;
        if (TradeMeasures::needs_reference(measure))
          {
            reference =
              parse_sweep(prm.get("Reference"), measure, where + "Reference");
            if (reference.size() != 1)
              throw InputError(where + "Reference",
                               "give one 'discretisation: n'");
          }
        prm.leave_subsection();

        StudyProgress progress(points.size() + reference.size());
        const auto    run_point = [&](const std::string &discretisation,
                                   const unsigned int n) {
          progress.next("trade study, " + measure + ": " + discretisation +
                          ", n = " + std::to_string(n),
                        "");
          SweepPoint p;
          p.discretisation = discretisation;
          p.n              = n;
          p.figures        = run_in_child(
            [&]() {
              return TradeMeasures::run(
                measure, discretisation, n, scene, settings, directory);
            },
            p.peak_megabytes);
          std::cout << " value " << std::setprecision(6) << p.figures.value
                    << ", " << p.figures.dofs << " dofs, "
                    << std::setprecision(3) << p.figures.wall_seconds
                    << " s, peak " << p.peak_megabytes << " MB" << std::endl;
          return p;
        };

        std::string reference_text;
        double      reference_value = 0.;
        if (!reference.empty())
          {
            const SweepPoint r =
              run_point(reference[0].first, reference[0].second);
            reference_value = r.figures.value;
            reference_text  = reference[0].first +
                             " at n = " + std::to_string(r.n) + ", value " +
                             figure(r.figures.value, 8) + ", " +
                             figure(r.figures.dofs) + " dofs, " +
                             figure(r.figures.wall_seconds) + " s";
          }
        std::vector<SweepPoint> results;
        for (const auto &[discretisation, n] : points)
          {
            results.push_back(run_point(discretisation, n));
            results.back().error =
              TradeMeasures::error(measure,
                                   results.back().figures.value,
                                   reference_value);
          }

        AtomicFile csv(directory + "/trade_" + measure + ".csv");
        csv.stream() << "discretisation,n,dofs,newton_iterations,active_nodes,"
                        "wall_seconds,peak_memory_mb,value,error\n"
                     << std::setprecision(8);
        for (const auto &p : results)
          csv.stream() << p.discretisation << ',' << p.n << ','
                       << p.figures.dofs << ',' << p.figures.newton_iterations
                       << ',' << p.figures.active_nodes << ','
                       << p.figures.wall_seconds << ',' << p.peak_megabytes
                       << ',' << p.figures.value << ',' << p.error << '\n';
        csv.commit();

        const std::string table = report(measure, results, reference_text);
        std::cout << '\n' << table << std::flush;
        tables += table;
      }
    prm.leave_subsection();

    AtomicFile markdown(directory + "/trade_tables.md");
    markdown.stream() << tables;
    markdown.commit();
    plot_with_python("plot_trade.py", directory);
  }
} // namespace glissade

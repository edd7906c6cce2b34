#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <glissade/base/text.h>
#include <glissade/io/atomic_file.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/study/case3_study.h>
#include <glissade/study/plotting.h>
#include <glissade/study/trade_study.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <cmath>
#include <map>
#include <stdexcept>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>

namespace glissade
{
  namespace
  {
    /** "q480" -> "q4 80", "hermite" -> "hermite 40" (Case3Result labels). */
    std::pair<std::string, std::string>
    family_and_elements(const std::string &label)
    {
      for (const std::string family : {"bspline", "hermite", "q4"})
        if (label.rfind(family, 0) == 0)
          {
            const std::string digits = label.substr(family.size());
            return {family, digits.empty() ? "40" : digits};
          }
      return {label, "?"};
    }

    /**
     * Runs one point of the sweep in a child process, so that the peak
     * memory (wait4's ru_maxrss) is that point's alone and not the largest
     * of the run so far. The figures come back through a pipe.
     */
    template <typename Point>
    Case3Result
    run_in_child(const Point &point, double &peak_megabytes)
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
              const Case3Result r = point();
              const double figures[5] = {double(r.dofs),
                                         r.wall_seconds,
                                         double(r.newton_iterations),
                                         double(r.active_nodes),
                                         r.worst_spread};
              if (write(channel[1], figures, sizeof(figures)) !=
                    sizeof(figures) ||
                  write(channel[1], r.variant.c_str(), r.variant.size()) !=
                    static_cast<ssize_t>(r.variant.size()))
                status = 1;
            }
          catch (const std::exception &e)
            {
              std::cerr << "trade study: " << e.what() << std::endl;
              status = 1;
            }
          close(channel[1]);
          std::cout << std::flush;
          _exit(status);
        }
      close(channel[1]);
      double  figures[5] = {0., 0., 0., 0., 0.};
      ssize_t got        = read(channel[0], figures, sizeof(figures));
      std::string label;
      char        buffer[64];
      for (ssize_t k; (k = read(channel[0], buffer, sizeof(buffer))) > 0;)
        label.append(buffer, k);
      close(channel[0]);
      int           status = 0;
      struct rusage usage;
      wait4(child, &status, 0, &usage);
      if (got != sizeof(figures) || !WIFEXITED(status) ||
          WEXITSTATUS(status) != 0)
        throw std::runtime_error("trade study: a point of the sweep failed "
                                 "(see the message above)");
      peak_megabytes = usage.ru_maxrss / 1024.; // Linux: kilobytes
      Case3Result r;
      r.variant           = label;
      r.dofs              = static_cast<unsigned int>(figures[0]);
      r.wall_seconds      = figures[1];
      r.newton_iterations = static_cast<unsigned int>(figures[2]);
      r.active_nodes      = static_cast<unsigned int>(figures[3]);
      r.worst_spread      = figures[4];
      return r;
    }

    std::vector<unsigned int>
    integer_list(const std::string &text)
    {
      std::vector<unsigned int> values;
      for (const auto &n : Utilities::split_string_list(text, ','))
        values.push_back(Utilities::string_to_int(n));
      return values;
    }
  } // namespace



  void
  TradeStudy::run(const std::string              &prm_file,
                  const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    prm.declare_entry("Study", "trade", Patterns::Selection("trade"));
    prm.enter_subsection("Trade study");
    prm.declare_entry("Scene", "case3_rings.prm", Patterns::Anything(),
                      "Case 3's scene (relative to this file's folder).");
    prm.declare_entry("Q4 elements", "40, 80, 160",
                      Patterns::List(Patterns::Integer(4)),
                      "Elements around both rings for plain Q4 (multiples "
                      "of 4: the supports sit at 0, 90, 180, 270 degrees).");
    prm.declare_entry("B-spline elements", "40, 80",
                      Patterns::List(Patterns::Integer(4)),
                      "Elements around both rings for Q4 + B-spline.");
    prm.declare_entry("Hermite elements", "20, 40",
                      Patterns::List(Patterns::Integer(4)),
                      "Elements around the Hermite outer ring (the inner Q4 "
                      "ring keeps 40, as in the paper's fig 29).");
    prm.declare_entry("Rotation angle", "9", Patterns::Double(0.),
                      "Degrees of rotation after the compression: the same "
                      "for every point (9: one element at 40).");
    prm.declare_entry("Increments per element", "50", Patterns::Integer(1),
                      "Rotation increments per element crossed, so that every "
                      "mesh samples its ripple alike (the paper: 50).");
    prm.declare_entry("Output directory", "output/trade_study",
                      Patterns::Anything(), "Where the CSV and PNG go.");
    prm.leave_subsection();
    SceneReader::parse_study(prm, prm_file, overrides);

    prm.enter_subsection("Trade study");
    const std::string scene = text::path_beside(prm_file, prm.get("Scene"));
    const std::map<std::string, std::vector<unsigned int>> sweep = {
      {"q4", integer_list(prm.get("Q4 elements"))},
      {"bspline", integer_list(prm.get("B-spline elements"))},
      {"hermite", integer_list(prm.get("Hermite elements"))}};
    const double       angle     = prm.get_double("Rotation angle");
    const unsigned int per_element = prm.get_integer("Increments per element");
    const std::string  directory = prm.get("Output directory");
    prm.leave_subsection();
    std::filesystem::create_directories(directory);

    std::vector<Case3Result> points;
    std::vector<double>      peak_memory; // MB, per point
    for (const std::string variant : {"q4", "bspline", "hermite"})
      for (const unsigned int n : sweep.at(variant))
        {
          // The rotation crosses angle / (360 / n) elements of the finer of
          // the two rings (Hermite: its inner ring keeps 40).
          const unsigned int finest = variant == "hermite" ? std::max(n, 40u) : n;
          const unsigned int increments = static_cast<unsigned int>(
            std::ceil(angle / (360. / finest) * per_element));
          std::cout << "trade study: " << variant << ", " << n
                    << " elements around, " << increments
                    << " rotation increments ..." << std::flush;
          double peak_megabytes = 0.;
          points.push_back(run_in_child(
            [&]() {
              return Case3Study::run_variant(
                scene, variant, angle, increments, directory, n);
            },
            peak_megabytes));
          peak_memory.push_back(peak_megabytes);
          const Case3Result &p = points.back();
          std::cout << " spread " << std::setprecision(3) << p.worst_spread
                    << " %, " << p.dofs << " dofs, " << p.wall_seconds
                    << " s, peak " << peak_megabytes << " MB" << std::endl;
        }

    AtomicFile csv(directory + "/trade_case3.csv");
    csv.stream() << "discretisation,elements,dofs,newton_iterations,"
                    "active_nodes,wall_seconds,peak_memory_mb,"
                    "worst_spread_percent\n";
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const Case3Result &p = points[i];
        const auto [family, elements] = family_and_elements(p.variant);
        csv.stream() << family << ',' << elements << ',' << p.dofs << ',' << p.newton_iterations << ','
                     << p.active_nodes << ',' << std::setprecision(6)
                     << p.wall_seconds << ',' << peak_memory[i] << ','
                     << p.worst_spread << '\n';
      }
    csv.commit();

    // The table, then the cross-overs: for each smoothed point, the
    // cheapest Q4 point at least as accurate, if the sweep has one.
    std::cout << "\nCase 3: accuracy (worst contact-force spread) against "
                 "cost\n"
              << std::setw(12) << "method" << std::setw(8) << "dofs"
              << std::setw(10) << "Newton" << std::setw(9) << "active"
              << std::setw(11) << "wall (s)" << std::setw(11) << "peak (MB)"
              << std::setw(13) << "spread (%)" << '\n';
    const auto name = [](const Case3Result &p) {
      const auto [family, elements] = family_and_elements(p.variant);
      return family + " " + elements;
    };
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const Case3Result &p = points[i];
        std::cout << std::setw(12) << name(p) << std::setw(8) << p.dofs
                  << std::setw(10) << p.newton_iterations << std::setw(9)
                  << p.active_nodes << std::setw(11) << std::setprecision(3)
                  << p.wall_seconds << std::setw(11) << peak_memory[i]
                  << std::setw(13) << p.worst_spread << '\n';
      }
    // spread = a n^b and time = c n^d over the Q4 points (least squares in
    // log-log): the rates at which Q4 buys accuracy and pays for it.
    struct
    {
      bool   valid = false;
      double spread_factor, spread_exponent, time_factor, time_exponent;
    } q4_fit;
    {
      std::vector<double> log_n, log_spread, log_time;
      for (const auto &p : points)
        if (p.variant.rfind("q4", 0) == 0 && p.worst_spread > 0.)
          {
            log_n.push_back(
              std::log(std::stod(family_and_elements(p.variant).second)));
            log_spread.push_back(std::log(p.worst_spread));
            log_time.push_back(std::log(p.wall_seconds));
          }
      const auto fit = [&](const std::vector<double> &y, double &factor,
                           double &exponent) {
        const double m = log_n.size();
        double sx = 0., sy = 0., sxx = 0., sxy = 0.;
        for (unsigned int i = 0; i < m; ++i)
          {
            sx += log_n[i];
            sy += y[i];
            sxx += log_n[i] * log_n[i];
            sxy += log_n[i] * y[i];
          }
        exponent = (m * sxy - sx * sy) / (m * sxx - sx * sx);
        factor   = std::exp((sy - exponent * sx) / m);
      };
      if (log_n.size() >= 2)
        {
          fit(log_spread, q4_fit.spread_factor, q4_fit.spread_exponent);
          fit(log_time, q4_fit.time_factor, q4_fit.time_exponent);
          q4_fit.valid = q4_fit.spread_exponent < 0.;
          std::cout << "\nQ4 over the sweep: spread ~ n^"
                    << std::setprecision(3) << q4_fit.spread_exponent
                    << ", wall time ~ n^" << q4_fit.time_exponent
                    << " (n: elements around)\n";
        }
    }
    std::cout << "\nCross-overs (the cheapest Q4 mesh of the sweep that is "
                 "as accurate):\n";
    for (const auto &smooth : points)
      {
        if (smooth.variant.rfind("q4", 0) == 0)
          continue;
        const Case3Result *match = nullptr;
        for (const auto &q4 : points)
          if (q4.variant.rfind("q4", 0) == 0 &&
              q4.worst_spread <= smooth.worst_spread &&
              (!match || q4.wall_seconds < match->wall_seconds))
            match = &q4;
        std::cout << "  " << std::setw(10) << name(smooth) << " ("
                  << std::setprecision(3) << smooth.worst_spread << " %, "
                  << smooth.wall_seconds << " s): ";
        if (match)
          std::cout << name(*match) << ", " << match->wall_seconds << " s, "
                    << match->dofs << " dofs\n";
        else if (q4_fit.valid)
          {
            // Beyond the sweep: the power laws fitted to the Q4 points.
            const double n = std::pow(smooth.worst_spread / q4_fit.spread_factor,
                                      1. / q4_fit.spread_exponent);
            std::cout << "no Q4 mesh of the sweep is as accurate; the fit "
                         "extrapolates to about "
                      << std::setprecision(2) << std::scientific << n
                      << " elements around and "
                      << q4_fit.time_factor * std::pow(n, q4_fit.time_exponent)
                      << " s" << std::defaultfloat << std::setprecision(6)
                      << '\n';
          }
        else
          std::cout << "no Q4 mesh of the sweep is as accurate\n";
      }
    std::cout << std::flush;
    plot_with_python("plot_trade.py", directory);
  }
} // namespace glissade

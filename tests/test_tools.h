#pragma once

// What glissade_tests' tests share beyond the harness (harness.h): checks
// of figures against references, and scenes and closed forms that several
// tests use.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness.h"

namespace glissade_tests
{
  /** |measured - expected| <= tolerance * |expected|, printed either way. */
  inline void
  check_relative(const double       measured,
                 const double       expected,
                 const double       tolerance,
                 const std::string &what)
  {
    const double deviation =
      std::abs(measured - expected) / std::max(std::abs(expected), 1e-300);
    std::cout << "  " << what << ": measured " << measured << ", expected "
              << expected << ", relative deviation " << deviation
              << " (tolerance " << tolerance << ")" << std::endl;
    check(deviation <= tolerance, what + " is out of tolerance");
  }

  /**
   * The largest contact work of a step over a dynamic run, as it goes
   * (record() the EnergyAccount after each step), and the largest of the
   * energies it is to be compared with.
   */
  struct ContactWorkWatch
  {
    double largest = 0., previous = 0., energies = 0.;
    template <class EnergyAccount>
    void
    record(const EnergyAccount &e)
    {
      largest  = std::max(largest, e.contact_work - previous);
      previous = e.contact_work;
      energies =
        std::max({energies, e.kinetic + e.strain, std::abs(e.work_of_loads)});
    }
  };

  /**
   * Two runs that solve the same equations by two linear-algebra paths (or
   * the same path on another BLAS kernel) take the same increments and,
   * in each, Newton iterations equal or within one: round-off decides
   * whether the last correction falls just below or just above its
   * tolerance (doc/design.md, "Assertions that round-off must not
   * decide"). Prints both lists either way.
   */
  inline void
  check_iterations_within_one(const std::vector<unsigned int> &a,
                              const std::vector<unsigned int> &b,
                              const std::string               &what)
  {
    unsigned int       differ = 0, apart = 0;
    std::ostringstream lists;
    for (const auto *list : {&a, &b})
      {
        lists << (list == &a ? " (" : "; ");
        for (unsigned int i = 0; i < list->size(); ++i)
          lists << (i ? " " : "") << (*list)[i];
      }
    for (unsigned int i = 0; i < std::min(a.size(), b.size()); ++i)
      {
        differ += a[i] != b[i];
        apart += a[i] + 1 < b[i] || b[i] + 1 < a[i];
      }
    std::cout << "  " << what << ": Newton iterations per increment"
              << lists.str() << "); " << differ << " increments differ by one, "
              << apart << " by more" << std::endl;
    check(a.size() == b.size(), what + ": not the same number of increments");
    check(apart == 0,
          what + ": Newton iterations differ by more than one in some "
                 "increment");
  }

  /**
   * The times a sampled signal crosses zero (linear interpolation between
   * samples), and the angular frequency they give: pi per half period.
   * record() each sample; samples up to `from` are only remembered.
   */
  struct ZeroCrossings
  {
    double              from       = 0.;
    double              previous_t = 0., previous_u = 0.;
    std::vector<double> times;

    void
    record(const double t, const double u)
    {
      if (t > from && (previous_u < 0.) != (u < 0.))
        times.push_back(previous_t +
                        (t - previous_t) * previous_u / (previous_u - u));
      previous_t = t;
      previous_u = u;
    }

    double
    angular_frequency() const
    {
      return M_PI * (times.size() - 1) / (times.back() - times.front());
    }
  };

  /**
   * The override that gives a run an output directory of its own, named
   * from `prefix` and `label`: ctest runs tests side by side in one folder,
   * and two runs may not share one.
   */
  inline std::vector<std::string>
  own_output_directory(const std::string &prefix, const std::string &label)
  {
    std::string name = prefix;
    for (const char c : label)
      name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return {"Output/Directory=" + name};
  }

  /** The path of a file in the source tree (set by CMake). */
  std::string
  source_path(const std::string &relative);

  /**
   * prm/thick_cylinder.prm's cylinder as its plane-strain cross-section: a
   * quarter ring (radii 1 and 2, q2, 32 x 16 cells, symmetry supports)
   * under the bore pressure `pressure` (an expression of t), the overrides
   * that turn the axisymmetric section into it.
   */
  inline std::vector<std::string>
  thick_cylinder_as_plane_ring(const std::string &pressure)
  {
    return {"Body cylinder/Material/Hypothesis=plane strain",
            "Body cylinder/Mesh/Type=half ring",
            "Body cylinder/Mesh/Inner radius=1",
            "Body cylinder/Mesh/Outer radius=2",
            "Body cylinder/Mesh/Start angle=0",
            "Body cylinder/Mesh/End angle=90",
            "Body cylinder/Mesh/Subdivisions=32, 16",
            "Body cylinder/Boundary conditions/Fixed=start: y; end: x",
            "Body cylinder/Boundary conditions/Pressure=inner: " + pressure};
  }

  /**
   * The first bending mode of prm/blade_casing.prm's cantilever blade
   * (clamped at y = 200, L = 100): Euler-Bernoulli's omega_1 = 1.8751^2 h
   * / L^2 sqrt(E / (12 rho)), and its shape with a tip value of about 200
   * as an Initial velocity expression of y.
   */
  struct BladeFirstMode
  {
    double      omega_1;
    std::string shape;
  };

  inline BladeFirstMode
  blade_first_mode(const double E, const double rho, const double h)
  {
    const double      L = 100.;
    const std::string b = "1.8751*(y-200)/100";
    return {1.8751 * 1.8751 * h / (L * L) * std::sqrt(E / (12. * rho)),
            "100*(cosh(" + b + ")-cos(" + b + ")-0.7341*(sinh(" + b + ")-sin(" +
              b + ")))"};
  }
  /**
   * A body named `name` on a rectangle mesh (corners, subdivisions as the
   * .prm writes them), of element space `space`, E = 1000, nu = 0.3, with
   * the Boundary conditions subsection's lines `conditions`: the block of
   * the contact tests.
   */
  inline std::string
  rectangle_body(const std::string &name,
                 const std::string &corner_1,
                 const std::string &corner_2,
                 const std::string &subdivisions,
                 const std::string &space,
                 const std::string &conditions)
  {
    return "subsection Body " + name +
           "\n subsection Mesh\n  set Type = rectangle\n  set Corner 1 = " +
           corner_1 + "\n  set Corner 2 = " + corner_2 +
           "\n  set Subdivisions = " + subdivisions +
           "\n end\n subsection Element\n  set Space = " + space +
           "\n end\n subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n end\n subsection Boundary conditions\n" +
           conditions + "\n end\nend\n";
  }
} // namespace glissade_tests

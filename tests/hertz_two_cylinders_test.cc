// Hertz between two curved bodies: prm/hertz_two_cylinders.prm presses a
// cylinder (R1 = 1) on another (R2 = 2) of the same material, plane
// strain, a / R* about 0.05 with R* = R1 R2 / (R1 + R2). The master is the
// lower cylinder's arc: where the Hertz tests of mortar_test.cc have a
// flat master, this one is curved, as the smoothed masters are made for.

#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>

#include "line_contact_points.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

// With mortar on the faceted and the B-spline master: Hertz's a and p0 at
// the load the contact carries within 1 % (measured, faceted and B-spline:
// a -0.47 % and -0.43 %, p0 +0.69 % and +0.67 %), the profile within 1.5 %
// of p0 inside 0.9 a (0.78 %, 0.84 %), the load the top's reaction to
// 1e-8. Node-to-segment on the B-spline master: a within 1 % (-0.54 %);
// its pressure oscillates from node to node on non-matching meshes (one
// pass fails the patch test: p0 7.6 % low at the centre node), printed,
// not asserted.
GLISSADE_TEST(contact_hertz_two_cylinders)
{
  const double E_star         = 200. / (2. * (1. - 0.3 * 0.3));
  const double reduced_radius = 1. * 2. / (1. + 2.);
  for (const auto &[surface, discretisation] :
       std::vector<std::pair<std::string, std::string>>{{"faceted", "mortar"},
                                                        {"bspline", "mortar"},
                                                        {"bspline",
                                                         "node-to-segment"}})
    {
      const std::string        label = discretisation + " on the " + surface;
      std::vector<std::string> overrides =
        own_output_directory("hertz_two_cylinders_", label);
      overrides.push_back("Output/Progress=false");
      overrides.push_back("Output/Contact table interval=0");
      overrides.push_back("Load program/Stage increments=2");
      overrides.push_back("Contact touch/Surface=" + surface);
      overrides.push_back("Contact touch/Discretisation=" + discretisation);
      Simulation simulation(
        SceneReader::read_file(source_path("prm/hertz_two_cylinders.prm"),
                               overrides));
      simulation.run();
      const ContactPair &pair = *simulation.contact().contact_pairs()[0];
      const LineContact  contact(pair);
      const double       P = pair.total_force()[1];
      const auto [a, p0]   = hertz_cylinders(P, reduced_radius, E_star);
      const double profile = contact.profile_error(a, p0);
      std::cout << "  " << label << ": P = " << P
                << ", a / R* = " << a / reduced_radius << "; a "
                << contact.half_width << " (Hertz " << a << "), p0 "
                << contact.peak_pressure << " (Hertz " << p0
                << "), profile within " << profile << " of p0" << std::endl;
      check_relative(-support_reaction(simulation.body("upper"), "top")[1],
                     P,
                     1e-8,
                     label + ": the contact's load against the top's reaction");
      check(a / reduced_radius > 0.04 && a / reduced_radius < 0.06,
            "a / R* is not about 0.05");
      check_relative(contact.half_width, a, 0.01, label + ": a");
      if (discretisation == "mortar")
        {
          check_relative(contact.peak_pressure, p0, 0.01, label + ": p0");
          check(profile <= 0.015,
                label + ": the pressure is more than 1.5 % of p0 off Hertz's");
        }
    }
}

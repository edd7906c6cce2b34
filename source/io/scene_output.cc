#include <deal.II/base/timer.h>

#include <glissade/base/processes.h>
#include <glissade/base/timing_sections.h>
#include <glissade/body/body_measures.h>
#include <glissade/contact/surfaces/abradable_coating.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/body_output.h>
#include <glissade/io/plotting.h>
#include <glissade/io/pvd_index.h>
#include <glissade/io/scene_output.h>

#include <cmath>
#include <iomanip>

namespace glissade
{
  using namespace dealii;

  SceneOutput::SceneOutput(const OutputSettings                     &settings,
                           const std::vector<std::unique_ptr<Body>> &bodies,
                           ContactProblem                           &contact,
                           TimerOutput                              &timer)
    : settings(settings)
    , bodies(bodies)
    , contact(contact)
    , timer(timer)
  {
    if (settings.contact_tables == OutputSettings::ContactTables::per_body)
      for (const auto &body : bodies)
        body_contact_outputs.emplace_back(*body);
    body_contact_records.resize(body_contact_outputs.size());
    follow_new_pairs();
  }



  void
  SceneOutput::follow_new_pairs()
  {
    const auto &pairs = contact.contact_pairs();
    for (std::size_t p = contact_outputs.size(); p < pairs.size(); ++p)
      {
        const ContactPair &pair = *pairs[p];
        contact_outputs.emplace_back(pair);
        if (pair.surface().is_rigid())
          obstacles.emplace_back(pair.name(), &pair.surface());
        if (pair.coating() != nullptr)
          coatings.push_back({&pair, {}, {}, {}});
      }
    pvd_records.resize(bodies.size() + contact_outputs.size());
  }



  void
  SceneOutput::write_initial_state()
  {
    if (settings.initial_state)
      write_vtu(0, 0.);
  }



  bool
  SceneOutput::vtu_due(const unsigned int increment, const bool last) const
  {
    if (increment == 0)
      return settings.initial_state;
    return last || (settings.vtu_interval > 0 &&
                    increment % settings.vtu_interval == 0);
  }



  void
  SceneOutput::write_increment(const unsigned int increment,
                               const double       t,
                               const bool         last)
  {
    const unsigned int table_interval = settings.contact_table_interval;
    if (table_interval > 0 && (last || increment % table_interval == 0) &&
        processes::writes_files())
      write_contact_tables(increment, t);
    if (vtu_due(increment, last))
      write_vtu(increment, t);
    if (processes::writes_files())
      write_coating_profiles(t, last);
  }



  void
  SceneOutput::write_coating_profiles(const double t, const bool last)
  {
    for (auto &coating : coatings)
      {
        const int revolution = static_cast<int>(std::floor(
          std::abs(coating.pair->surface().rotation()) / (2. * M_PI) + 1e-9));
        const int written =
          coating.revolutions.empty() ? 0 : coating.revolutions.back();
        if (!(revolution > written || last))
          continue;
        if (!coating.revolutions.empty() && coating.times.back() == t)
          continue;
        coating.revolutions.push_back(revolution);
        coating.times.push_back(t);
        coating.profiles.push_back(coating.pair->coating()->profile());
        AtomicFile file(settings.directory + "/coating-" +
                        coating.pair->name() + ".csv");
        file.write_and_commit([&](std::ostream &out) {
          out << "revolution,time,angle,worn_depth\n" << std::setprecision(12);
          for (unsigned int s = 0; s < coating.profiles.size(); ++s)
            {
              const auto &profile = coating.profiles[s];
              for (unsigned int k = 0; k < profile.size(); ++k)
                out << coating.revolutions[s] << ',' << coating.times[s] << ','
                    << 360. * k / profile.size() << ',' << profile[k] << '\n';
            }
        });
      }
  }



  void
  SceneOutput::write_last_converged_state(const unsigned int increment,
                                          const double       t)
  {
    // An increment that failed was not the last converged one: only the
    // intervals count.
    const unsigned int table_interval = settings.contact_table_interval;
    if (!vtu_due(increment, false))
      write_vtu(increment, t);
    else if (table_interval > 0 && increment % table_interval != 0 &&
             processes::writes_files())
      write_contact_tables(increment, t);
  }



  void
  SceneOutput::write_interrupted_state(const unsigned int increment,
                                       const double       t,
                                       const bool         last)
  {
    if (!vtu_due(increment, last))
      write_vtu(increment, t);
  }



  void
  SceneOutput::write_vtu(const unsigned int increment, const double t)
  {
    TimerOutput::Scope scope(timer, timing::output);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        // (every process writes its piece of a body; process 0 the rest)
        const std::string vtu =
          write_body_vtu(*bodies[b], settings.directory, increment, settings);
        pvd_records[b].emplace_back(t, vtu);
        if (processes::writes_files())
          write_pvd_index(settings.directory + "/" + bodies[b]->name() + ".pvd",
                          pvd_records[b]);
      }
    if (settings.contact_table_interval == 0 && processes::writes_files())
      write_contact_tables(increment, t);
  }



  void
  SceneOutput::write_contact_tables(const unsigned int increment,
                                    const double       t)
  {
    follow_new_pairs();
    if (settings.contact_tables == OutputSettings::ContactTables::per_body)
      {
        for (unsigned int b = 0; b < body_contact_outputs.size(); ++b)
          body_contact_outputs[b].write(settings.directory,
                                        increment,
                                        t,
                                        contact.contact_pairs(),
                                        body_contact_records[b]);
        return;
      }
    for (unsigned int p = 0; p < contact_outputs.size(); ++p)
      contact_outputs[p].write(settings.directory,
                               increment,
                               t,
                               pvd_records[bodies.size() + p]);
  }



  void
  SceneOutput::draw_pictures() const
  {
    if (!settings.plots)
      return;
    // The rigid obstacles beside the bodies in deformed-mesh.png:
    // obstacle-<pair>.csv, the curve where the bodies are now.
    if (!obstacles.empty())
      {
        Point<2> lowest(1e300, 1e300), highest(-1e300, -1e300);
        for (const auto &body : bodies)
          {
            const auto &vertices = body->triangulation().get_vertices();
            const auto &used     = body->triangulation().get_used_vertices();
            const auto  moved    = vertex_displacements(*body);
            for (unsigned int v = 0; v < vertices.size(); ++v)
              for (unsigned int d = 0; d < 2 && used[v]; ++d)
                {
                  lowest[d] = std::min(lowest[d], vertices[v][d] + moved[v][d]);
                  highest[d] =
                    std::max(highest[d], vertices[v][d] + moved[v][d]);
                }
          }
        const Point<2> centre = 0.5 * (lowest + highest);
        const double   reach  = 0.6 * (highest - lowest).norm();
        for (const auto &[name, surface] : obstacles)
          {
            AtomicFile file(settings.directory + "/obstacle-" + name + ".csv");
            file.write_and_commit([&](std::ostream &out) {
              out << "x,y\n" << std::setprecision(10);
              for (const Point<2> &p : surface->outline(centre, reach))
                out << p[0] << ',' << p[1] << '\n';
            });
          }
      }
    // plot_scene.py's arguments for Output/Plot curves: "x:y" each.
    std::vector<std::string> curves;
    for (const auto &[x, y] : settings.plot_curves)
      curves.push_back(x + ":" + y);
    plot_with_python("plot_scene.py", settings.directory, curves);
  }
} // namespace glissade

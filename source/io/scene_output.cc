#include <deal.II/base/timer.h>

#include <glissade/base/timing_sections.h>
#include <glissade/io/plotting.h>
#include <glissade/io/pvd_index.h>
#include <glissade/io/scene_output.h>

namespace glissade
{
  using namespace dealii;

  SceneOutput::SceneOutput(const OutputSettings                     &settings,
                           const std::vector<std::unique_ptr<Body>> &bodies,
                           ContactProblem                           &contact,
                           TimerOutput                              &timer)
    : settings(settings)
    , bodies(bodies)
    , timer(timer)
  {
    for (const auto &pair : contact.contact_pairs())
      contact_outputs.emplace_back(*pair);
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
    if (table_interval > 0 && (last || increment % table_interval == 0))
      write_contact_tables(increment, t);
    if (vtu_due(increment, last))
      write_vtu(increment, t);
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
    else if (table_interval > 0 && increment % table_interval != 0)
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
        const std::string vtu =
          bodies[b]->write_vtu(settings.directory, increment, settings);
        pvd_records[b].emplace_back(t, vtu);
        write_pvd_index(settings.directory + "/" + bodies[b]->name() + ".pvd",
                        pvd_records[b]);
      }
    if (settings.contact_table_interval == 0)
      write_contact_tables(increment, t);
  }



  void
  SceneOutput::write_contact_tables(const unsigned int increment,
                                    const double       t)
  {
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
    // plot_scene.py's arguments for Output/Plot curves: "x:y" each.
    std::vector<std::string> curves;
    for (const auto &[x, y] : settings.plot_curves)
      curves.push_back(x + ":" + y);
    plot_with_python("plot_scene.py", settings.directory, curves);
  }
} // namespace glissade

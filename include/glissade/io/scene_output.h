#pragma once

#include <glissade/body/body.h>
#include <glissade/contact/step/contact_problem.h>
#include <glissade/description/scene_description.h>
#include <glissade/io/body_contact_output.h>
#include <glissade/io/contact_surface_output.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class TimerOutput;
}

namespace glissade
{
  /**
   * What a run writes as it goes, by its scene's Output section: each
   * body's VTU at the increments asked for (`VTU interval`, the initial
   * state, the last increment) with its PVD index, each contact pair's
   * tables and VTU/PVD (`Contact table interval`), and, at the end, the
   * PNGs (`Plots`). The Simulation says when an increment has converged
   * or when the run stops; this class decides what is due and writes it.
   * The PVD indices are part of a checkpoint (serialize()), so that a
   * restarted run appends to them. On several processes every process
   * calls it: each writes its piece of the bodies' VTU (write_body_vtu()),
   * and process 0 everything else.
   */
  class SceneOutput
  {
  public:
    SceneOutput(const OutputSettings                     &settings,
                const std::vector<std::unique_ptr<Body>> &bodies,
                ContactProblem                           &contact,
                dealii::TimerOutput                      &timer);

    /** The state before the first increment (if `Initial state` asks). */
    void
    write_initial_state();

    /** After the converged increment `increment` (at time t); `last`: the
     *  load program's last. */
    void
    write_increment(const unsigned int increment,
                    const double       t,
                    const bool         last);

    /**
     * A run that fails in the increment after `increment`: the VTU and
     * tables of `increment`, the last converged state, unless they were
     * written already, so that the output shows where the run stood.
     */
    void
    write_last_converged_state(const unsigned int increment, const double t);

    /** A run stopped by a signal after `increment`: its VTU (and the
     *  tables that go with it), unless written already. */
    void
    write_interrupted_state(const unsigned int increment,
                            const double       t,
                            const bool         last);

    /** The PNGs of the run (scripts/plot_scene.py), if `Plots` asks. */
    void
    draw_pictures() const;

    /** The PVD indices written so far (checkpoint and restart). */
    template <class Archive>
    void
    serialize(Archive &archive)
    {
      follow_new_pairs();
      archive &pvd_records;
      // (a checkpoint from before the contact surfaces had PVD files)
      pvd_records.resize(bodies.size() + contact_outputs.size());
      // (per body: a setting that restarts keep, so the archive knows it)
      if (settings.contact_tables == OutputSettings::ContactTables::per_body)
        archive &body_contact_records;
      for (auto &coating : coatings)
        archive &coating.revolutions &coating.times &coating.profiles;
    }

  private:
    /** Whether increment's VTU files are written by write_increment(). */
    bool
    vtu_due(const unsigned int increment, const bool last) const;

    /** Every body's VTU and PVD; the contact tables if they go with them. */
    void
    write_vtu(const unsigned int increment, const double t);

    void
    write_contact_tables(const unsigned int increment, const double t);

    /** The outputs of the pairs made since the last call (automatic
     *  contact makes a couple's pairs when its bodies come within reach). */
    void
    follow_new_pairs();

    /** A copy: the scene a Simulation was made from may be a temporary. */
    const OutputSettings                      settings;
    const std::vector<std::unique_ptr<Body>> &bodies;
    ContactProblem                           &contact;
    dealii::TimerOutput                      &timer;
    std::vector<ContactSurfaceOutput>         contact_outputs;
    /** Output/Contact tables = per body: each body's, over its pairs. */
    std::vector<BodyContactOutput> body_contact_outputs;
    std::vector<std::vector<std::pair<double, std::string>>>
      body_contact_records;
    /** The rigid obstacles, by pair name, that the pictures draw. */
    std::vector<std::pair<std::string, const MasterSurface *>> obstacles;

    /**
     * The worn profiles of a pair's abradable coating, one at each
     * revolution the casing completes and at the end:
     * coating-<pair>.csv (revolution, time, angle in degrees in the
     * casing's frame, worn depth), and its PNG (Plots).
     */
    struct CoatingProfiles
    {
      const ContactPair               *pair;
      std::vector<int>                 revolutions;
      std::vector<double>              times;
      std::vector<std::vector<double>> profiles;
    };
    std::vector<CoatingProfiles> coatings;

    /** A coating's profile, if a revolution was completed or `last`. */
    void
    write_coating_profiles(const double t, const bool last);
    /** (time, file) of every VTU written, per body then per contact pair. */
    std::vector<std::vector<std::pair<double, std::string>>> pvd_records;
  };
} // namespace glissade

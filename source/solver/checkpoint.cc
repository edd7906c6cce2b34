// Checkpoint and restart of a Simulation: the state that the next increment
// starts from, written with Boost serialization, so that a run stopped
// half-way continues to the same output files as an uninterrupted one; and
// the stop on SIGINT or SIGTERM, which leaves such a checkpoint.

#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/base/interruption.h>
#include <glissade/base/timing_sections.h>
#include <glissade/contact/surfaces/abradable_coating.h>
#include <glissade/io/atomic_file.h>
#include <glissade/solver/simulation.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <fstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    // Raised when the layout of the file or the numbering of the dofs
    // changes: an old file is refused. (4: the cells of a mesh read from a
    // Gmsh file are walked along a Hilbert curve, which numbers its dofs
    // anew; 6: the names of automatic contact's pairs made so far.)
    const std::string checkpoint_format = "glissade checkpoint 6";
  } // namespace



  std::string
  Simulation::checkpoint_file() const
  {
    return scene.output.directory + "/checkpoint.bin";
  }



  template <class Archive>
  void
  Simulation::serialize_state(Archive &archive)
  {
    archive &current_time;
    // Written: the totals so far (restored times plus this process's
    // TimerOutput sections); read: they become the restored times.
    RunStatistics totals = Archive::is_saving::value ? statistics() : stats;
    // (boost's archive operator, one line per group; clang-format would
    // read 'archive &x' as a declaration and break the chain mid-name)
    // clang-format off
    archive & totals.increments & totals.newton_iterations & totals.cut_backs;
    archive & totals.assembly_seconds & totals.factorization_seconds
            & totals.solve_seconds & totals.detection_seconds
            & totals.surface_build_seconds & totals.compliance_seconds
            & totals.local_solve_seconds & totals.output_seconds
            & totals.checkpoint_seconds & totals.wall_seconds;
    // clang-format on
    if (Archive::is_loading::value)
      stats = totals;
    // The pairs automatic contact has made, made again before the outputs
    // and the nodes that go with them are read.
    std::vector<std::string> made = contact_problem->automatic_pair_names();
    archive                 &made;
    if (Archive::is_loading::value)
      for (const std::string &name : made)
        if (contact_problem->pair_named(name) == nullptr)
          throw InputError(checkpoint_file(),
                           "has the contact pair '" + name +
                             "', which the scene's automatic contact "
                             "does not make");
    output->serialize(archive);
    history->serialize_rows(archive);
    for (auto &b : all_bodies)
      {
        // The sizes are written and compared so that a mismatch is a
        // message, not a read past the end.
        unsigned int n_dofs = b->n_dofs();
        archive     &n_dofs;
        if (n_dofs != b->n_dofs())
          throw InputError(checkpoint_file(),
                           "body '" + b->name() + "' has " +
                             std::to_string(n_dofs) +
                             " dofs in the checkpoint and " +
                             std::to_string(b->n_dofs()) + " in the scene");
        b->serialize_state(archive);
        // A dynamic scheme's velocity and acceleration (the scene decides
        // whether there is one: the fingerprint covers it).
        if (b->inertia())
          b->inertia()->serialize(archive, 0);
      }
    if (EnergyAccount *energies = integrator->energies())
      energies->serialize(archive, 0);
    for (auto &pair : contact_problem->contact_pairs())
      {
        unsigned int n_nodes = pair->nodes().size();
        archive     &n_nodes;
        if (n_nodes != pair->nodes().size())
          throw InputError(checkpoint_file(),
                           "contact pair '" + pair->name() +
                             "' has a different number of slave nodes");
        archive & pair->nodes();
        if (AbradableCoating *coating = pair->coating())
          coating->serialize(archive, 0);
      }
  }



  void
  Simulation::write_checkpoint(const unsigned int increment)
  {
    // (every process holds the same state: one file, written by one)
    if (!writes_files)
      return;
    TimerOutput::Scope scope(timer, timing::checkpoints);
    AtomicFile         file(checkpoint_file());
    file.write_and_commit([&](std::ostream &out) {
      boost::archive::binary_oarchive archive(out);
      std::string                     format      = checkpoint_format;
      std::string                     fingerprint = scene.fingerprint;
      unsigned int                    last        = increment;
      archive &format &fingerprint   &last;
      serialize_state(archive);
    });
  }



  unsigned int
  Simulation::read_checkpoint()
  {
    std::ifstream in(checkpoint_file(), std::ios::binary);
    if (!in)
      throw InputError(checkpoint_file(),
                       "cannot open the checkpoint to restart from (set "
                       "Checkpoint/Interval or Stop after increment in " +
                         scene.source + " and run without --restart first)");
    unsigned int increment = 0;
    try
      {
        boost::archive::binary_iarchive archive(in);
        std::string                     format, fingerprint;
        archive                        &format;
        if (format != checkpoint_format)
          throw InputError(checkpoint_file(),
                           "is not a checkpoint of this version of glissade");
        archive &fingerprint &increment;
        if (fingerprint != scene.fingerprint)
          throw InputError(checkpoint_file(),
                           "was written for another scene: " + scene.source +
                             " (with its --set overrides) or a mesh file it "
                             "reads has changed since; only the sections "
                             "Checkpoint and Linear solver may differ");
        serialize_state(archive);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        throw InputError(checkpoint_file(),
                         std::string("is unreadable (") + e.what() + ")");
      }
    return increment;
  }



  bool
  Simulation::checkpoint_due(const unsigned int increment) const
  {
    return scene.checkpoint.interval > 0 &&
           increment % scene.checkpoint.interval == 0;
  }



  void
  Simulation::stop_on_signal(const int          signal,
                             const unsigned int increment,
                             const unsigned int n_total,
                             const double       t,
                             const bool         last)
  {
    // (the state of this increment is in a checkpoint: the periodic one,
    // or one written now)
    if (!checkpoint_due(increment))
      write_checkpoint(increment);
    output->write_interrupted_state(increment, t, last);
    write_summary_file("stopped by " + interruption::signal_name(signal) +
                       " after increment " + std::to_string(increment) +
                       " of " + std::to_string(n_total) +
                       "; continue with --restart\n");
    throw RunInterrupted(
      interruption::signal_name(signal) +
      " received: stopped after increment " + std::to_string(increment) +
      " of " + std::to_string(n_total) + " (t = " + std::to_string(t) +
      "), its state in " + checkpoint_file());
  }
} // namespace glissade

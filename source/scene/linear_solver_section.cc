// The section Linear solver: what a user may choose about the bodies'
// factorisations (include/glissade/description/scene_description.h).

#include <glissade/description/scene_description.h>
#include <glissade/scene/section_reader.h>

#include <cstdlib>

namespace glissade
{
  using namespace dealii;

  void
  LinearSolverSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry(
      "Factors out of core",
      "false",
      Patterns::Bool(),
      "On several processes (mpirun; MUMPS): each process writes its share "
      "of the bodies' factors to files in 'Out-of-core directory' as they "
      "are made, and reads them back at each solve, instead of keeping them "
      "in memory: the largest part of a large run's memory (the million-dof "
      "rings on two processes: 1.36 GB per process instead of 2.09 GB, in "
      "the same time while the files fit the machine's page cache). The "
      "same figures to round-off. One process keeps its factors in memory "
      "(CHOLMOD, UMFPACK), and says so.");
    prm.declare_entry("Out-of-core directory",
                      "",
                      Patterns::Anything(),
                      "Where the factors' files go (made if it does not "
                      "exist; on a cluster, a disk local to each node): "
                      "empty for $TMPDIR, or /tmp. The files are removed "
                      "at the end of the run.");
    prm.leave_subsection();
  }



  void
  LinearSolverSettings::parse_parameters(SectionReader &prm)
  {
    prm.enter_subsection("Linear solver");
    factors_out_of_core   = prm.get_bool("Factors out of core");
    out_of_core_directory = prm.get("Out-of-core directory");
    prm.leave_subsection();
    if (out_of_core_directory.empty())
      {
        const char *tmpdir    = std::getenv("TMPDIR");
        out_of_core_directory = tmpdir != nullptr && *tmpdir != '\0' ?
                                  std::string(tmpdir) :
                                  std::string("/tmp");
      }
  }
} // namespace glissade

// glissade: the command-line program. It reads a scene from a .prm file,
// runs its load program, and reports mistakes in the input or a failed
// increment as one clear message with a non-zero exit code.

#include <deal.II/base/config.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <glissade/base/config.h>
#include <glissade/base/input_error.h>
#include <glissade/base/interruption.h>
#include <glissade/base/processes.h>
#include <glissade/base/text.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <paper_studies/case3_study.h>
#include <paper_studies/contact_case_study.h>
#include <paper_studies/friction_study.h>
#include <paper_studies/geometric_study.h>
#include <paper_studies/trade_study.h>

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{
  /** A study driver, by the name its file's Study entry gives. */
  struct StudyDriver
  {
    std::string name;
    std::string sentence;
    void (*run)(const std::string &, const std::vector<std::string> &);
  };

  /** The study drivers of applications/paper_studies: one line each. */
  const std::vector<StudyDriver> &
  study_drivers()
  {
    using namespace glissade;
    static const std::vector<StudyDriver> drivers = {
      {"geometric",
       "the geometric study of the paper's section 3.3 (see "
       "prm/geometric_study.prm)",
       &GeometricStudy::run},
      {"case1",
       "the beam on a half ring (section 4.1; prm/case1_study.prm)",
       &ContactCaseStudy::run},
      {"case2",
       "the square between two half rings (section 4.2; "
       "prm/case2_study.prm)",
       &ContactCaseStudy::run},
      {"case3",
       "the concentric rings of section 4.3 in several variants (see "
       "prm/case3_default.prm)",
       &Case3Study::run},
      {"friction",
       "a scene for every master and friction coefficient "
       "(prm/case3_friction.prm)",
       &FrictionStudy::run},
      {"trade",
       "time and dofs against accuracy (prm/trade_study.prm)",
       &TradeStudy::run}};
    return drivers;
  }

  /**
   * True if mpirun (Open MPI, MPICH) or srun started this process: MPI is
   * then initialised. A plain `glissade` does not initialise MPI at all, so
   * that one process starts as fast as before (doc/parallel.md).
   */
  bool
  started_by_mpi_launcher()
  {
    for (const char *variable :
         {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
      if (std::getenv(variable) != nullptr)
        return true;
    return false;
  }

  /**
   * Several processes on one machine share its cores: deal.II's threads
   * (assembly), OpenBLAS's (CHOLMOD, LAPACK) and
   * OpenMP's (MUMPS) would otherwise start a thread per core in each
   * process. Each process takes its share of the cores (at least one),
   * unless OPENBLAS_NUM_THREADS, OMP_NUM_THREADS or DEAL_II_NUM_THREADS
   * say otherwise. (On this 2-core machine it changes little: the rings
   * at 800 x 80 on 2 processes, 7 alternating runs against 2 deal.II and
   * OpenMP threads per process, wall time ratio 1.00; the million-dof
   * rings 58-61 s against 64 s, single runs.)
   */
  void
  share_cores_among_processes()
  {
    MPI_Comm node;
    MPI_Comm_split_type(
      MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    int processes_here = 1;
    MPI_Comm_size(node, &processes_here);
    MPI_Comm_free(&node);
    const int threads =
      std::max(1, int(dealii::MultithreadInfo::n_cores()) / processes_here);
    if (std::getenv("DEAL_II_NUM_THREADS") == nullptr)
      dealii::MultithreadInfo::set_thread_limit(threads);
    using SetThreads = void (*)(int);
    if (std::getenv("OPENBLAS_NUM_THREADS") == nullptr)
      if (auto set = reinterpret_cast<SetThreads>(
            dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
        set(threads);
    if (std::getenv("OMP_NUM_THREADS") == nullptr)
      if (auto set = reinterpret_cast<SetThreads>(
            dlsym(RTLD_DEFAULT, "omp_set_num_threads")))
        set(threads);
  }

  /**
   * The command that continues a stopped run: the scene and its --set
   * overrides (a restart refuses another scene), quoted for a shell, and
   * under mpirun the launcher (any number of processes may continue).
   * (The Simulation's summary.txt keeps its short form, "--restart".)
   */
  std::string
  continuation_command(const std::string              &scene,
                       const std::vector<std::string> &overrides)
  {
    const auto quoted = [](const std::string &word) {
      std::string text = "'";
      for (const char c : word)
        text += c == '\'' ? std::string("'\\''") : std::string(1, c);
      return text + "'";
    };
    std::string command = glissade::processes::count() > 1 ?
                            "mpirun -np " +
                              std::to_string(glissade::processes::count()) +
                              " glissade " :
                            "glissade ";
    command += scene;
    // (the planned stop that ended the run is left out: the next one is
    // the user's to choose)
    for (const std::string &entry : overrides)
      if (entry.rfind("Checkpoint/Stop after increment", 0) != 0)
        command += " --set " + quoted(entry);
    return command + " --restart";
  }

  void
  print_usage(std::ostream &out)
  {
    out
      << "usage: glissade <scene.prm> [--set 'Section/Entry=value' ...] "
         "[--restart]\n"
         "       glissade --print-parameters | --version | --help\n"
         "Runs the scene described by the .prm file; --set overrides an\n"
         "entry of the file (e.g. --set 'Body beam/Mesh/Subdivisions=60,4');\n"
         "--restart continues from <Output directory>/checkpoint.bin.\n"
         "Exit codes: 0 done, 1 command line, 2 input error, 3 an increment\n"
         "did not converge, 4 other error, 5 stopped by SIGTERM/SIGINT after\n"
         "writing a checkpoint.\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace glissade;
  using namespace dealii;
  // (threads: the cores of the machine shared out among its processes)
  std::unique_ptr<Utilities::MPI::MPI_InitFinalize> mpi;
  if (started_by_mpi_launcher())
    mpi = std::make_unique<Utilities::MPI::MPI_InitFinalize>(argc, argv);
  if (processes::count() > 1)
    share_cores_among_processes();
  // Messages from process 0 only: the others take the same decisions.
  std::ostream  silent(nullptr);
  std::ostream &err = processes::writes_files() ? std::cerr : silent;
  std::ostream &out = processes::writes_files() ? std::cout : silent;
  if (argc < 2)
    {
      print_usage(err);
      return 1;
    }
  {
    // (the Study entry's pattern and help are made from the drivers)
    std::vector<std::pair<std::string, std::string>> names;
    for (const StudyDriver &driver : study_drivers())
      names.emplace_back(driver.name, driver.sentence);
    SceneReader::register_studies(names);
  }
  if (std::strcmp(argv[1], "--print-parameters") == 0)
    {
      SceneReader::print_parameters(out);
      return 0;
    }
  if (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)
    {
      print_usage(out);
      return 0;
    }
  if (std::strcmp(argv[1], "--version") == 0)
    {
      out << "glissade " << GLISSADE_VERSION << " (deal.II "
          << DEAL_II_PACKAGE_VERSION << ")\n";
      return 0;
    }
  if (argv[1][0] == '-')
    {
      err << "glissade: unknown option '" << argv[1] << "'\n";
      print_usage(err);
      return 1;
    }

  std::vector<std::string> overrides;
  bool                     restart = false;
  for (int i = 2; i < argc; ++i)
    {
      if (std::strcmp(argv[i], "--set") == 0 && i + 1 < argc)
        overrides.emplace_back(argv[++i]);
      else if (std::strcmp(argv[i], "--restart") == 0)
        restart = true;
      else
        {
          err << "glissade: unknown argument '" << argv[i] << "'\n";
          print_usage(err);
          return 1;
        }
    }

  try
    {
      const std::string study = SceneReader::study_type(argv[1]);
      if (restart && study != "simulation")
        throw InputError(argv[1],
                         "--restart continues a scene; this file is a '" +
                           study +
                           "' study driver, which runs its scenes "
                           "from the start");
      for (const StudyDriver &driver : study_drivers())
        if (driver.name == study)
          {
            if (processes::count() > 1)
              throw InputError(argv[1],
                               "a '" + study +
                                 "' study driver runs in one process; run "
                                 "it without mpirun, or run its scenes "
                                 "under mpirun one by one");
            driver.run(argv[1], overrides);
            return 0;
          }
      const SceneDescription scene = SceneReader::read_file(argv[1], overrides);
      Simulation             simulation(scene);
      interruption::install_handlers();
      const bool completed = simulation.run(restart);
      out << simulation.summary() << '\n'
          << simulation.timing_table() << std::flush;
      if (!completed)
        out << "stopped at Checkpoint/Stop after increment; continue "
               "with: "
            << continuation_command(argv[1], overrides) << std::endl;
    }
  catch (const InputError &e)
    {
      err << "glissade: input error: " << e.what() << std::endl;
      return 2;
    }
  catch (const ConvergenceFailure &e)
    {
      err << "glissade: stopped: " << e.what() << std::endl;
      return 3;
    }
  catch (const RunInterrupted &e)
    {
      err << "glissade: " << e.what()
          << "; continue with: " << continuation_command(argv[1], overrides)
          << std::endl;
      return 5;
    }
  catch (const std::exception &e)
    {
      // Without deal.II's source location and stack trace. Input errors,
      // failed increments and signals are met by every process alike and
      // said once; this one may be a single process's (a file it could not
      // write): each says it, process 0 as usual, the others by number.
      if (processes::writes_files())
        std::cerr << "glissade: error: " << text::essential_message(e)
                  << std::endl;
      else
        std::cerr << "glissade (process " << processes::rank()
                  << "): error: " << text::essential_message(e) << std::endl;
      // (the other processes may be waiting for this one in a collective
      // call: stop them all rather than hang)
      if (processes::count() > 1)
        MPI_Abort(MPI_COMM_WORLD, 4);
      return 4;
    }
  return 0;
}

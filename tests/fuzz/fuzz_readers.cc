// A mutation fuzzer for the two readers of user files: the scene (.prm,
// SceneReader and the construction of bodies and contact pairs) and the
// Gmsh mesh (.msh, MeshFactory through a scene that imports it).
//
// Each mutant is made from a valid seed file by one to three random edits
// (a value replaced by a hostile one, a line deleted, duplicated or swapped,
// a byte changed, the file truncated). The readers must either accept it or
// refuse it with an InputError; any other exception is a finding and the
// program fails, printing the mutant. Crashes and undefined behaviour are
// caught by the sanitizer build (cmake -DGLISSADE_SANITIZE=ON).
//
//   glissade_fuzz prm <iterations> <seed> <seed files...>
//   glissade_fuzz msh <iterations> <seed> <seed .msh file>

#include <glissade/base/input_error.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace glissade;
using namespace dealii;

namespace
{
  std::string
  read_text(const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      {
        std::cerr << "glissade_fuzz: cannot open " << filename << std::endl;
        std::exit(2);
      }
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }

  std::vector<std::string>
  split_lines(const std::string &text)
  {
    std::vector<std::string> lines;
    std::istringstream       in(text);
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    return lines;
  }

  std::string
  join_lines(const std::vector<std::string> &lines)
  {
    std::string text;
    for (const auto &line : lines)
      text += line + '\n';
    return text;
  }

  // Values that have broken readers elsewhere: empty, non-finite, negative,
  // overflowing, malformed lists and expressions, names that may not exist.
  const std::vector<std::string> hostile_values = {"",
                                                   "nan",
                                                   "inf",
                                                   "-inf",
                                                   "-1",
                                                   "0",
                                                   "1e308",
                                                   "-1e308",
                                                   "1e-320",
                                                   "4294967296",
                                                   "99999999999999999999",
                                                   "abc",
                                                   "1,2,3",
                                                   ",",
                                                   "point(",
                                                   "point(1e308, nan)",
                                                   "(",
                                                   "1/0*t",
                                                   "sqrt(-1)",
                                                   "xy",
                                                   "rigid",
                                                   "bottom",
                                                   "left: ",
                                                   ": xy",
                                                   "0, 0; ;",
                                                   "\"",
                                                   "\\",
                                                   "end"};

  /** One to three random edits of a text file. */
  std::string
  mutate(const std::string &seed_text, std::mt19937 &random, const bool numbers)
  {
    auto       lines = split_lines(seed_text);
    const auto pick  = [&](const std::size_t n) {
      return std::uniform_int_distribution<std::size_t>(0, n - 1)(random);
    };
    const unsigned int n_edits = 1 + pick(3);
    for (unsigned int e = 0; e < n_edits && !lines.empty(); ++e)
      {
        std::string &line = lines[pick(lines.size())];
        switch (pick(7))
          {
            case 0: // a value (after '=' in a .prm, a field in a .msh)
              if (!numbers)
                {
                  const auto eq = line.find('=');
                  if (eq != std::string::npos)
                    line = line.substr(0, eq + 1) + " " +
                           hostile_values[pick(hostile_values.size())];
                }
              else
                {
                  std::istringstream       in(line);
                  std::vector<std::string> fields;
                  for (std::string f; in >> f;)
                    fields.push_back(f);
                  if (!fields.empty())
                    {
                      fields[pick(fields.size())] =
                        hostile_values[pick(hostile_values.size())];
                      line.clear();
                      for (const auto &f : fields)
                        line += f + ' ';
                    }
                }
              break;
            case 1:
              lines.erase(lines.begin() + pick(lines.size()));
              break;
            case 2:
              lines.insert(lines.begin() + pick(lines.size()), line);
              break;
            case 3:
              std::swap(line, lines[pick(lines.size())]);
              break;
            case 4: // one byte, printable or not
              if (!line.empty())
                line[pick(line.size())] = static_cast<char>(pick(256));
              break;
            case 5: // truncation
              lines.resize(pick(lines.size()) + 1);
              if (!lines.back().empty())
                lines.back().resize(pick(lines.back().size()));
              break;
            default: // a digit changed, so that counts and indices move
              for (auto &c : line)
                if (c >= '0' && c <= '9' && pick(3) == 0)
                  c = static_cast<char>('0' + pick(10));
              break;
          }
      }
    return join_lines(lines);
  }

  // A scene that imports the mesh file and fixes/pulls its named boundaries.
  std::string
  plate_scene(const std::string &mesh_file)
  {
    return "subsection Scene\n set Bodies = plate\nend\n"
           "subsection Body plate\n subsection Mesh\n  set Type = gmsh\n"
           "  set File = " +
           mesh_file +
           "\n end\n subsection Boundary conditions\n"
           "  set Fixed = clamp: xy\n  set Tractions = pull: 1e-3*t, 0\n"
           " end\nend\n";
  }

  /**
   * Reads the scene and builds its bodies and contact pairs (no solve).
   * Returns "accepted", "refused" or, for a finding, the exception text.
   */
  std::string
  try_scene(const std::string &text, bool &finding)
  {
    finding = false;
    try
      {
        const SceneDescription scene =
          SceneReader::read_string(text, "mutant.prm");
        Simulation simulation(scene);
        return "accepted";
      }
    catch (const InputError &)
      {
        return "refused";
      }
    catch (const ConvergenceFailure &)
      {
        return "refused";
      }
    catch (const std::exception &e)
      {
        finding = true;
        return std::string("uncaught ") + typeid(e).name() + ": " + e.what();
      }
    catch (...)
      {
        finding = true;
        return "uncaught non-standard exception";
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  if (argc < 5 ||
      (std::string(argv[1]) != "prm" && std::string(argv[1]) != "msh"))
    {
      std::cerr << "usage: glissade_fuzz prm|msh <iterations> <seed> <files>\n";
      return 2;
    }
  const bool               mesh       = std::string(argv[1]) == "msh";
  const unsigned int       iterations = std::stoul(argv[2]);
  std::mt19937             random(std::stoul(argv[3]));
  std::vector<std::string> seeds;
  for (int i = 4; i < argc; ++i)
    seeds.push_back(read_text(argv[i]));

  const std::string mesh_file =
    (std::filesystem::temp_directory_path() /
     ("glissade_fuzz_" + std::to_string(::getpid()) + ".msh"))
      .string();
  unsigned int accepted = 0, refused = 0, findings = 0;
  for (unsigned int i = 0; i < iterations; ++i)
    {
      const std::string &seed =
        seeds[std::uniform_int_distribution<std::size_t>(0, seeds.size() - 1)(
          random)];
      const std::string mutant = mutate(seed, random, mesh);
      std::string       scene  = mutant;
      if (mesh)
        {
          std::ofstream(mesh_file) << mutant;
          scene = plate_scene(mesh_file);
        }
      // GLISSADE_FUZZ_TRACE=1: each mutant on stderr before it is read, to
      // find the one that hangs.
      if (std::getenv("GLISSADE_FUZZ_TRACE"))
        std::cerr << "--- mutant " << i << " ---\n" << mutant << std::flush;
      bool              finding = false;
      const std::string outcome = try_scene(scene, finding);
      if (finding)
        {
          ++findings;
          std::cout << "FINDING at iteration " << i << ": " << outcome
                    << "\n--- mutant ---\n"
                    << mutant << "--- end ---\n";
        }
      else if (outcome == "accepted")
        ++accepted;
      else
        ++refused;
    }
  std::filesystem::remove(mesh_file);
  std::cout << iterations << " mutants of " << seeds.size() << " " << argv[1]
            << " file(s): " << accepted << " accepted, " << refused
            << " refused with an input error, " << findings
            << " uncaught exceptions" << std::endl;
  return findings == 0 ? 0 : 1;
}

// The contact surface output (issue 20): read back from the files a run
// writes, as a user's script would. The pressure integrated along the
// slave boundary must be the support's reaction, each slave node must
// appear once, and a Hertz contact's pressure must be Hertz's profile
// within the discretisation error.

#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "body_resultant.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /** The columns of a CSV file by their header names (numbers; text as NaN). */
  std::map<std::string, std::vector<double>>
  read_csv(const std::string &file)
  {
    std::ifstream in(file);
    check(static_cast<bool>(in), "cannot open " + file);
    const auto split = [](const std::string &line) {
      std::vector<std::string> fields;
      std::string              field;
      std::istringstream       stream(line);
      while (std::getline(stream, field, ','))
        fields.push_back(field);
      return fields;
    };
    std::string line;
    std::getline(in, line);
    const auto                                 names = split(line);
    std::map<std::string, std::vector<double>> columns;
    while (std::getline(in, line))
      {
        const auto fields = split(line);
        for (unsigned int i = 0; i < names.size(); ++i)
          {
            double value = std::nan("");
            try
              {
                value = std::stod(fields.at(i));
              }
            catch (const std::exception &)
              {}
            columns[names[i]].push_back(value);
          }
      }
    return columns;
  }

  /**
   * The integral of the pressure along the slave boundary, times the
   * thickness: the trapezoidal rule between neighbouring nodes in the
   * given order (current positions).
   */
  double
  integrated_pressure(std::map<std::string, std::vector<double>> &table,
                      const std::vector<unsigned int>            &order,
                      const double                                thickness)
  {
    double sum = 0.;
    for (unsigned int i = 0; i + 1 < order.size(); ++i)
      {
        const unsigned int a = order[i], b = order[i + 1];
        const double       length = std::hypot(table["x"][a] - table["x"][b],
                                         table["y"][a] - table["y"][b]);
        sum += 0.5 * (table["pressure"][a] + table["pressure"][b]) * length;
      }
    return sum * thickness;
  }

  std::string
  contents(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
} // namespace

// A block of thickness 0.5 pressed onto a rigid line: the slave boundary's
// nine nodes appear once each in the table and the VTU, and the pressure
// integrated along it balances the top's reaction to round-off. The bulk
// VTU has no force field (it would count a node once per cell).
namespace
{
  std::string
  block_on_line(const std::string &slave_boundary, const std::string &directory)
  {
    return "subsection Scene\n set Bodies = block\n set Contact pairs = floor\nend\n"
           "subsection Body block\n subsection Mesh\n  set Type = rectangle\n"
           "  set Corner 1 = 0, 0\n  set Corner 2 = 1, 0.5\n"
           "  set Subdivisions = 8, 4\n end\n"
           " subsection Material\n  set Young modulus = 1000\n"
           "  set Thickness = 0.5\n end\n"
           " subsection Boundary conditions\n  set Fixed = left: x\n"
           "  set Prescribed displacement = top: y: -0.01*t\n end\nend\n"
           "subsection Contact floor\n set Slave body = block\n"
           " set Slave boundary = " +
           slave_boundary +
           "\n set Master body = rigid\n"
           " set Alert distance = 0.1\n"
           " subsection Obstacle\n  set Type = line\n  set Point = 0, 0\n"
           "  set Normal = 0, 1\n end\nend\n"
           "subsection Load program\n set Stage increments = 2\nend\n"
           "subsection Newton\n set Residual tolerance = 1e-12\nend\n"
           "subsection Output\n set Progress = false\n"
           " set Directory = " +
           directory + "\nend\n";
  }
} // namespace

GLISSADE_TEST(contact_surface_block_pressure_balances_support)
{
  Simulation simulation(
    SceneReader::read_string(block_on_line("bottom", "surface_block"),
                             "surface"));
  simulation.run();
  const double top = support_reaction(simulation.body("block"), "top")[1];

  auto               table = read_csv("surface_block/contact-floor-00002.csv");
  const unsigned int n     = table["X"].size();
  std::set<std::pair<double, double>> positions;
  std::vector<unsigned int>           order(n);
  for (unsigned int k = 0; k < n; ++k)
    {
      positions.emplace(table["X"][k], table["Y"][k]);
      order[k] = k;
    }
  std::sort(order.begin(), order.end(), [&](unsigned int a, unsigned int b) {
    return table["X"][a] < table["X"][b];
  });
  const double integral = integrated_pressure(table, order, 0.5);
  std::cout << "  " << n << " rows, " << positions.size()
            << " distinct nodes; pressure integrated " << integral
            << ", top reaction " << top << std::endl;
  check(n == 9 && positions.size() == 9, "each of the 9 slave nodes once");
  check_relative(integral,
                 -top,
                 1e-10,
                 "pressure integrated along the surface against the support");

  const std::string vtu = contents("surface_block/contact-floor-00002.vtu");
  check(vtu.find("NumberOfPoints=\"9\" NumberOfCells=\"8\"") !=
          std::string::npos,
        "the surface VTU is the 9 nodes and 8 faces of the boundary");
  check(contents("surface_block/contact-floor.pvd")
            .find("contact-floor-00002.vtu") != std::string::npos,
        "the PVD lists the surface VTU");
  check(contents("surface_block/block-00002.vtu").find("contact_force") ==
          std::string::npos,
        "no force field in the bulk VTU");
}



// Hertz: the lower half of a disk (R = 1, E = 200, nu = 0.3, plane strain,
// a hole of radius 0.2 driven down) on a rigid flat. At the load P that
// the contact carries, Hertz gives a = sqrt(4 P R / (pi E*)) and
// p(x) = p0 sqrt(1 - x^2 / a^2), p0 = 2 P / (pi a). The profile read from
// the table must approach it as the mesh is refined (a / R = 0.074).
GLISSADE_TEST(contact_surface_hertz_pressure_profile)
{
  std::vector<double> deviation;
  for (const std::string subdivisions : {"240, 12", "480, 24"})
    {
      const std::string prm =
        "subsection Scene\n set Bodies = disk\n set Contact pairs = flat\nend\n"
        "subsection Body disk\n subsection Mesh\n  set Type = half ring\n"
        "  set Center = 0, 1\n  set Inner radius = 0.2\n"
        "  set Outer radius = 1\n  set Start angle = 180\n"
        "  set End angle = 360\n  set Subdivisions = " +
        subdivisions +
        "\n end\n subsection Material\n  set Young modulus = 200\n"
        "  set Poisson ratio = 0.3\n end\n"
        " subsection Boundary conditions\n"
        "  set Prescribed displacement = inner: xy: 0, -0.01*t\n end\nend\n"
        "subsection Contact flat\n set Slave body = disk\n"
        " set Slave boundary = outer\n set Master body = rigid\n"
        " set Alert distance = 0.05\n"
        " subsection Obstacle\n  set Type = line\n  set Point = 0, 0\n"
        "  set Normal = 0, 1\n end\nend\n"
        "subsection Load program\n set Stage increments = 2\nend\n"
        "subsection Newton\n set Residual tolerance = 1e-12\nend\n"
        "subsection Output\n set Progress = false\n set VTU interval = 0\n"
        " set Directory = surface_hertz\nend\n";
      Simulation simulation(SceneReader::read_string(prm, "hertz"));
      simulation.run();
      const double support =
        support_reaction(simulation.body("disk"), "inner")[1];

      auto table = read_csv("surface_hertz/contact-flat-00002.csv");
      const unsigned int        n = table["X"].size();
      std::vector<unsigned int> order(n);
      for (unsigned int k = 0; k < n; ++k)
        order[k] = k;
      std::sort(order.begin(),
                order.end(),
                [&](unsigned int a, unsigned int b) {
                  return table["X"][a] < table["X"][b];
                });
      const double P = integrated_pressure(table, order, 1.);
      check_relative(P,
                     -support,
                     1e-10,
                     "pressure integrated against the hole's reaction");

      const double E_star = 200. / (1. - 0.3 * 0.3);
      const double a      = std::sqrt(4. * P / (M_PI * E_star));
      const double p0     = 2. * P / (M_PI * a);
      double       worst = 0., widest = 0.;
      for (unsigned int k = 0; k < n; ++k)
        if (table["r_n"][k] > 0.)
          {
            const double x = table["x"][k];
            const double hertz =
              p0 * std::sqrt(std::max(0., 1. - x * x / (a * a)));
            worst =
              std::max(worst, std::abs(table["pressure"][k] - hertz) / p0);
            widest = std::max(widest, std::abs(x));
          }
      deviation.push_back(worst);
      std::cout << "  " << subdivisions << ": P " << P << ", a " << a
                << " (last closed node at " << widest << "), p0 " << p0
                << "; largest deviation from Hertz " << worst << " p0"
                << std::endl;
      const double h = M_PI / std::stod(subdivisions);
      check(std::abs(widest - a) <= 2. * h,
            "the contact ends within two elements of Hertz's a");
    }
  check(deviation[1] <= 0.05,
        "Hertz's profile within 5 % of p0 on the fine mesh");
  check(deviation[1] < 0.5 * deviation[0],
        "the deviation from Hertz shrinks as the mesh is refined");
}



// A slave boundary given as several names: the corners where they meet
// are one node each (8 x 4 block: 9 + 4 + 4 = 17 nodes), and the contact
// still carries exactly what the top's support does.
GLISSADE_TEST(contact_pair_several_slave_boundaries)
{
  Simulation simulation(SceneReader::read_string(
    block_on_line("bottom, left, right", "surface_sides"), "surface"));
  simulation.run();
  const auto            &pair = *simulation.contact().contact_pairs()[0];
  std::set<unsigned int> vertices;
  for (const auto &node : pair.nodes())
    vertices.insert(node.vertex);
  const double top   = support_reaction(simulation.body("block"), "top")[1];
  const double total = pair.total_force()[1];
  std::cout << "  " << pair.nodes().size() << " slave nodes ("
            << vertices.size() << " distinct); contact force " << total
            << ", top reaction " << top << std::endl;
  check(pair.nodes().size() == 17 && vertices.size() == 17,
        "bottom, left and right give 17 nodes, corners once");
  check_relative(total, -top, 1e-10, "contact force against the support");
}



// Output/Initial state = false: the reference configuration's VTU files
// and contact table are left out, the final state's are written and the
// PVD index lists only them; with the default both are there.
GLISSADE_TEST(output_initial_state_left_out)
{
  for (const bool initial : {true, false})
    {
      const std::string directory =
        initial ? "initial_state_kept" : "initial_state_left_out";
      std::filesystem::remove_all(directory); // no file of an earlier run
      Simulation simulation(SceneReader::read_string(
        block_on_line("bottom", directory),
        "initial state",
        {"Output/VTU interval=0",
         std::string("Output/Initial state=") + (initial ? "true" : "false")}));
      simulation.run();
      const bool vtu_0 = !contents(directory + "/block-00000.vtu").empty();
      const bool table_0 =
        !contents(directory + "/contact-floor-00000.csv").empty();
      const bool vtu_2 = !contents(directory + "/block-00002.vtu").empty();
      const bool table_2 =
        !contents(directory + "/contact-floor-00002.csv").empty();
      const std::string pvd = contents(directory + "/block.pvd");
      std::cout << "  Initial state = " << initial << ": increment 0 VTU "
                << vtu_0 << ", table " << table_0 << "; final VTU " << vtu_2
                << ", table " << table_2 << std::endl;
      check(vtu_0 == initial && table_0 == initial,
            "increment 0 written if and only if asked for");
      check(vtu_2 && table_2, "the final state is always written");
      check((pvd.find("block-00000.vtu") != std::string::npos) == initial &&
              pvd.find("block-00002.vtu") != std::string::npos,
            "the PVD index lists the files written");
    }
}



// Output/VTU fields: each field is in the body's VTU if and only if it is
// asked for (the arrays' names in the file's header).
GLISSADE_TEST(output_vtu_fields_as_asked)
{
  for (const std::string fields :
       {"displacement, stress", "displacement", "stress"})
    {
      const std::string directory =
        "vtu_fields_" + std::to_string(fields.size());
      std::filesystem::remove_all(directory); // no file of an earlier run
      Simulation simulation(SceneReader::read_string(
        block_on_line("bottom", directory),
        "VTU fields",
        {"Output/VTU interval=0", "Output/VTU fields=" + fields}));
      simulation.run();
      const std::string vtu = contents(directory + "/block-00002.vtu");
      const bool        displacement =
        vtu.find("Name=\"displacement\"") != std::string::npos;
      const bool stress = vtu.find("Name=\"von_Mises\"") != std::string::npos &&
                          vtu.find("Name=\"sigma_xy\"") != std::string::npos;
      std::cout << "  VTU fields = " << fields << ": displacement "
                << displacement << ", stress " << stress << std::endl;
      check(!vtu.empty(), "the final VTU is written");
      check(displacement == (fields.find("displacement") != std::string::npos),
            "the displacement is written if and only if asked for");
      check(stress == (fields.find("stress") != std::string::npos),
            "the stress is written if and only if asked for");
    }
}



// Output/Plots: any scene draws its history, its pressure along the
// interface and its deformed mesh as PNG files (scripts/plot_scene.py,
// Debian's matplotlib; the body VTU read back from deal.II's compressed
// binary).
GLISSADE_TEST(scene_plots_written)
{
  Simulation simulation(SceneReader::read_string(
    block_on_line("bottom", "scene_plots"),
    "plots",
    {"Output/Plots=true",
     "Output/History=contact_force(floor); reaction(block, top)",
     "Output/Plot curves=time: floor_Fy; block_Ry_top: floor_Fy"}));
  simulation.run();
  for (const std::string file : {"history.png",
                                 "contact-floor-pressure.png",
                                 "deformed-mesh.png",
                                 "curves.png"})
    {
      const std::string png = contents("scene_plots/" + file);
      std::cout << "  " << file << ": " << png.size() << " bytes" << std::endl;
      check(png.size() > 1000 && png.compare(0, 4, "\x89PNG") == 0,
            file + " is a PNG picture");
    }
  // The rigid flat that deformed-mesh.png draws: points of the line y = 0
  // spanning the block (0 <= x <= 1), from obstacle-floor.csv.
  auto        line = read_csv("scene_plots/obstacle-floor.csv");
  const auto &x = line["x"], &y = line["y"];
  double      off_line = 0.;
  for (const double value : y)
    off_line = std::max(off_line, std::abs(value));
  check(x.size() == 2 && std::min(x[0], x[1]) <= 0. &&
          std::max(x[0], x[1]) >= 1. && off_line <= 1e-12,
        "obstacle-floor.csv holds the flat y = 0 under the block");
}



// The walkthrough's scene (prm/pad_on_roller.prm, doc/walkthrough.md): a
// rubber pad pressed on a rigid roller, then dragged 4 mm with mu = 0.3. At
// the end every active node obeys Coulomb's law as its table reports it:
// slipping nodes |r_t| = mu r_n, sticking ones |r_t| <= mu r_n; the nodal
// forces add up to minus the top's reaction (balance of the pad).
GLISSADE_TEST(walkthrough_pad_on_roller)
{
  Simulation simulation(
    SceneReader::read_file(source_path("prm/pad_on_roller.prm"),
                           {"Output/Directory=walkthrough_pad",
                            "Output/Plots=false",
                            "Output/Progress=false"}));
  simulation.run();
  const double mu       = 0.3;
  unsigned int slipping = 0, sticking = 0;
  double       worst_slip = 0., fx = 0., fy = 0.;
  // Increment 12: the drag has begun, part of the contact still sticks;
  // increment 20: the end (its forces are balanced below).
  for (const std::string increment : {"00012", "00020"})
    {
      const std::string file =
        "walkthrough_pad/contact-roller-" + increment + ".csv";
      auto               table = read_csv(file);
      std::istringstream lines(contents(file));
      std::string        line;
      std::getline(lines, line);
      fx = fy = 0.;
      for (unsigned int k = 0; std::getline(lines, line); ++k)
        {
          const double r_n = table["r_n"][k];
          const double r_t = std::abs(table["r_t"][k]);
          fx += table["fx"][k];
          fy += table["fy"][k];
          if (line.find(",slip,") != std::string::npos)
            {
              ++slipping;
              worst_slip = std::max(worst_slip, std::abs(r_t - mu * r_n) / r_n);
            }
          else if (line.find(",stick,") != std::string::npos)
            {
              ++sticking;
              check(r_t <= mu * r_n * (1. + 1e-10),
                    "a sticking node is outside the cone");
            }
        }
    }
  std::cout << "  " << slipping << " slipping and " << sticking
            << " sticking nodes; worst | |r_t| / r_n - mu | / mu of the "
               "slipping ones: "
            << worst_slip / mu << std::endl;
  check(slipping > 0 && sticking > 0, "the pad both sticks and slips");
  check(worst_slip / mu < 1e-8, "a slipping node is off the cone");
  const Tensor<1, 2> top = support_reaction(simulation.body("pad"), "top");
  check_relative(fx,
                 -top[0],
                 1e-8,
                 "contact force x against the top's reaction");
  check_relative(fy,
                 -top[1],
                 1e-8,
                 "contact force y against the top's reaction");
}

// Output/Contact tables = per body: three rings in a row (the middle one
// held at its inner edge, the outer two pushed onto it by 0.6 t, closing
// at t = 5/6), automatic contact in one pass with the middle ring listed
// first: it is the slave of two pairs, the outer rings masters only. Its
// table lists its 32 slave nodes once; the nodes of its left side are
// carried by its pair on the left ring, those of its right side by its
// pair on the right one; by the scene's mirror symmetry its forces sum to
// zero; and what its left-side nodes carry is the force on the left ring,
// with the opposite sign (action = reaction). The outer rings, slaves of
// no pair, have no table, and no table per pair is written.
GLISSADE_TEST(contact_tables_per_body)
{
  std::string prm = "subsection Scene\n set Bodies = left, middle, right\n"
                    " set Contact bodies = middle: outer, left: outer, right: "
                    "outer\nend\n"
                    "subsection Automatic contact\n set Passes = one\n"
                    " set Surface = bspline\n set Alert distance = 0.05\nend\n";
  for (const auto &[name, x, support] :
       {std::tuple<std::string, std::string, std::string>{
          "left", "-2.5", "Prescribed displacement = inner: xy: 0.6*t, 0"},
        {"middle", "0", "Fixed = inner: xy"},
        {"right", "2.5", "Prescribed displacement = inner: xy: -0.6*t, 0"}})
    prm += "subsection Body " + name +
           "\n subsection Mesh\n  set Type = ring\n  set Center = " + x +
           ", 0\n  set Inner radius = 0.5\n  set Outer radius = 1\n"
           "  set Subdivisions = 32, 3\n end\n"
           " subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n end\n"
           " subsection Boundary conditions\n  set " +
           support + "\n end\nend\n";
  prm += "subsection Load program\n set Stage increments = 4\nend\n"
         "subsection Contact solver\n set Tolerance = 1e-13\nend\n"
         "subsection Newton\n set Residual tolerance = 1e-10\n"
         " set Displacement tolerance = 1e-10\nend\n"
         "subsection Output\n set Progress = false\n"
         " set Contact tables = per body\n"
         " set Directory = tables_per_body\nend\n";
  // (files of an earlier run of this test must not pass for this one's)
  std::filesystem::remove_all("tables_per_body");
  Simulation simulation(SceneReader::read_string(prm, "tables per body"));
  simulation.run();

  const std::string file  = "tables_per_body/contact-of-middle-00004.csv";
  auto              table = read_csv(file);
  std::ifstream     in(file);
  std::string       line;
  std::getline(in, line);
  Tensor<1, 2> total, by_left;
  unsigned int k = 0, carried = 0;
  while (std::getline(in, line))
    {
      const Tensor<1, 2> f({table["fx"][k], table["fy"][k]});
      total += f;
      const std::string pair = line.substr(line.rfind(',') + 1);
      if (!pair.empty() && table["active"][k] == 1.)
        {
          ++carried;
          check(pair ==
                  (table["X"][k] < 0. ? "middle on left" : "middle on right"),
                "the node at X = " + std::to_string(table["X"][k]) +
                  " is carried by '" + pair + "'");
          if (pair == "middle on left")
            by_left += f;
        }
      ++k;
    }
  const Tensor<1, 2> on_left =
    resultant(simulation.body("left"),
              simulation.body("left").get_contact_forces());
  std::cout << "  middle: " << table["X"].size() << " slave nodes, " << carried
            << " active, forces summing to " << total << "; its left side's "
            << by_left << ", the force on the left "
            << "ring " << on_left << std::endl;
  check(table["X"].size() == 32, "not each of the 32 slave nodes once");
  check(carried >= 4, "the middle ring's nodes carry nothing");
  const double scale = by_left.norm();
  check(scale > 1., "the rings do not press on each other");
  check(total.norm() <= 1e-8 * scale,
        "the middle ring's slave forces do not sum to zero");
  check((by_left + on_left).norm() <= 1e-10 * scale,
        "the left side's forces are not the left ring's, reversed");
  for (const auto &entry :
       std::filesystem::directory_iterator("tables_per_body"))
    {
      const std::string name = entry.path().filename().string();
      check(name.find(" on ") == std::string::npos &&
              name.find("contact-of-left") == std::string::npos,
            "a table per pair, or of a body that is no slave: " + name);
    }
}

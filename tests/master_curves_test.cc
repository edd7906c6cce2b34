// A master boundary of several curves (a body with a hole, its outer
// boundary and its hole's wall under one name: CompositeSurface), and the
// elastic foundation that holds a body nothing else holds (Boundary
// conditions/Elastic foundation).

#include <glissade/base/input_error.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "body_resultant.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  std::vector<std::string>
  own_directory(const std::string &label)
  {
    return own_output_directory("master_curves_", label);
  }

  /**
   * An annulus r in [0.5, 1] about the origin, 48 cells around and 4
   * through, as a Gmsh 2.2 file: its two curves in one Physical Line
   * 'surface' (`one_name`) or as 'inner' and 'outer'.
   */
  std::string
  write_ring_mesh(const std::string &folder, const bool one_name)
  {
    const unsigned int n_around = 48, n_through = 4;
    const std::string  path =
      folder + (one_name ? "/ring_one_name.msh" : "/ring_two_names.msh");
    std::ofstream f(path);
    f.precision(17);
    f << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n"
      << (one_name ? "2\n1 2 \"surface\"\n" :
                     "3\n1 2 \"inner\"\n1 3 \"outer\"\n")
      << "2 1 \"ring\"\n$EndPhysicalNames\n";
    const auto node = [&](const unsigned int i, const unsigned int j) {
      return (i % n_around) * (n_through + 1) + j + 1;
    };
    f << "$Nodes\n" << n_around * (n_through + 1) << "\n";
    for (unsigned int i = 0; i < n_around; ++i)
      for (unsigned int j = 0; j <= n_through; ++j)
        {
          const double r   = 0.5 + 0.5 * j / n_through;
          const double phi = 2. * M_PI * i / n_around;
          f << node(i, j) << " " << r * std::cos(phi) << " "
            << r * std::sin(phi) << " 0\n";
        }
    f << "$EndNodes\n$Elements\n"
      << 2 * n_around + n_around * n_through << "\n";
    unsigned int k = 1;
    // (one name: both curves carry tag 2)
    for (unsigned int i = 0; i < n_around; ++i)
      f << k++ << " 1 2 2 2 " << node(i, 0) << " " << node(i + 1, 0) << "\n";
    const unsigned int outer_tag = one_name ? 2 : 3;
    for (unsigned int i = 0; i < n_around; ++i)
      f << k++ << " 1 2 " << outer_tag << " " << outer_tag << " "
        << node(i, n_through) << " " << node(i + 1, n_through) << "\n";
    for (unsigned int i = 0; i < n_around; ++i)
      for (unsigned int j = 0; j < n_through; ++j)
        f << k++ << " 3 2 1 1 " << node(i, j) << " " << node(i + 1, j) << " "
          << node(i + 1, j + 1) << " " << node(i, j + 1) << "\n";
    f << "$EndElements\n";
    return path;
  }

  /**
   * The ring of write_ring_mesh held by an elastic foundation (k = 10,
   * E = 1000), a disk (r 0.35 about (0, -0.1)) in its hole pushed down
   * onto the hole's wall and a block under it pushed up onto its outer
   * wall, by 0.1 each over t in [0, 1] (gaps 0.05 at the start). The two
   * pairs' masters are `disk_master` and `block_master` of the ring.
   */
  std::string
  ring_between_disk_and_block(const std::string &mesh,
                              const std::string &pairs,
                              const std::string &sections)
  {
    return "subsection Scene\n set Bodies = ring, disk, block\n" + pairs +
           "end\n"
           "subsection Body ring\n subsection Mesh\n  set Type = gmsh\n"
           "  set File = " +
           mesh +
           "\n end\n subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n end\n"
           " subsection Boundary conditions\n"
           "  set Elastic foundation = 10\n end\nend\n"
           "subsection Body disk\n subsection Mesh\n  set Type = ring\n"
           "  set Center = 0, -0.1\n  set Inner radius = 0.05\n"
           "  set Outer radius = 0.35\n  set Subdivisions = 40, 3\n end\n"
           " subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n end\n"
           " subsection Boundary conditions\n"
           "  set Prescribed displacement = inner: xy: 0, -0.1*t\n end\nend\n"
           "subsection Body block\n subsection Mesh\n  set Type = rectangle\n"
           "  set Corner 1 = -0.3, -1.35\n  set Corner 2 = 0.3, -1.05\n"
           "  set Subdivisions = 12, 6\n end\n"
           " subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n end\n"
           " subsection Boundary conditions\n"
           "  set Prescribed displacement = bottom: xy: 0, 0.1*t\n end\nend\n" +
           sections +
           "subsection Contact solver\n set Tolerance = 1e-13\nend\n"
           "subsection Newton\n set Residual tolerance = 1e-10\n"
           " set Displacement tolerance = 1e-10\nend\n"
           "subsection Output\n set Progress = false\nend\n";
  }

  std::string
  pair(const std::string &name,
       const std::string &slave,
       const std::string &slave_boundary,
       const std::string &master_boundary,
       const std::string &surface)
  {
    return "subsection Contact " + name + "\n set Slave body = " + slave +
           "\n set Slave boundary = " + slave_boundary +
           "\n set Master body = ring\n set Master boundary = " +
           master_boundary + "\n set Surface = " + surface +
           "\n set Alert distance = 0.1\nend\n";
  }

  std::unique_ptr<Simulation>
  solved(const std::string &prm, const std::string &label)
  {
    auto simulation = std::make_unique<Simulation>(
      SceneReader::read_string(prm, label, own_directory(label)));
    for (unsigned int k = 1; k <= 4; ++k)
      simulation->advance_to(k / 4., "increment " + std::to_string(k));
    return simulation;
  }
} // namespace

// A free body under its weight rho g on an elastic foundation k settles by
// the rigid translation u = rho g / k (no strain, so sigma = 0 and -k u +
// rho g = 0 at every point), at large strain and at small strain.
GLISSADE_TEST(elastic_foundation_translates_a_free_body)
{
  for (const std::string kinematics : {"large strain", "small strain"})
    {
      const std::string prm =
        "subsection Scene\n set Bodies = plate\nend\n"
        "subsection Body plate\n subsection Mesh\n  set Type = rectangle\n"
        "  set Corner 2 = 1, 0.5\n  set Subdivisions = 4, 2\n"
        "  set Distortion = 0.2\n end\n"
        " subsection Material\n  set Young modulus = 100\n"
        "  set Poisson ratio = 0.3\n  set Density = 2\n"
        "  set Kinematics = " +
        kinematics +
        "\n end\n subsection Boundary conditions\n"
        "  set Gravity = 0.3*t, -t\n  set Elastic foundation = 4\n end\nend\n"
        "subsection Newton\n set Residual tolerance = 1e-10\nend\n"
        "subsection Output\n set Progress = false\nend\n";
      Simulation simulation(
        SceneReader::read_string(prm, kinematics, own_directory(kinematics)));
      simulation.advance_to(1., "t = 1");
      const Vector<double> &u = simulation.body("plate").displacement();
      const Tensor<1, 2>    expected({2. * 0.3 / 4., -2. * 1. / 4.});
      double                deviation = 0.;
      for (unsigned int i = 0; i < u.size(); i += 2)
        deviation = std::max({deviation,
                              std::abs(u(i) - expected[0]),
                              std::abs(u(i + 1) - expected[1])});
      std::cout << "  " << kinematics
                << ": largest nodal deviation from rho g / k = (0.15, -0.5): "
                << deviation << std::endl;
      check(deviation <= 1e-10, kinematics + ": not the translation rho g / k");
    }
}

// A ring's whole boundary, its outer curve and its hole's wall under one
// name, is one master: a disk pressed on the hole's wall and a block
// pressed on the outer wall find each its curve, with the forces and
// displacements of pairs whose masters name the curves one by one (the
// same mesh, the same nodes, the same segments: equal to round-off), on a
// faceted and a B-spline master, with the two curves' names listed together
// ('inner, outer'), and by automatic contact ('ring: inner + outer'). The
// forces on the three bodies balance (action = reaction), and the slave nodes
// end on their masters.
GLISSADE_TEST(contact_on_a_master_of_two_curves)
{
  const std::string folder =
    std::filesystem::absolute("master_curves_meshes").string();
  std::filesystem::create_directories(folder);
  const std::string one_name  = write_ring_mesh(folder, true);
  const std::string two_names = write_ring_mesh(folder, false);

  for (const std::string surface : {"faceted", "bspline"})
    {
      const auto by_curve =
        solved(ring_between_disk_and_block(
                 two_names,
                 " set Contact pairs = disk on ring, block on ring\n",
                 pair("disk on ring", "disk", "outer", "inner", surface) +
                   pair("block on ring", "block", "top", "outer", surface)),
               surface + ", the curves named one by one");
      const auto whole =
        solved(ring_between_disk_and_block(
                 one_name,
                 " set Contact pairs = disk on ring, block on ring\n",
                 pair("disk on ring", "disk", "outer", "surface", surface) +
                   pair("block on ring", "block", "top", "surface", surface)),
               surface + ", the whole boundary");

      // The two curves' names listed together: the same master.
      const auto listed = solved(
        ring_between_disk_and_block(
          two_names,
          " set Contact pairs = disk on ring, block on ring\n",
          pair("disk on ring", "disk", "outer", "inner, outer", surface) +
            pair("block on ring", "block", "top", "outer, inner", surface)),
        surface + ", both names listed");

      double       force_scale = 0., largest = 0.;
      Tensor<1, 2> total;
      for (const std::string body : {"ring", "disk", "block"})
        {
          Vector<double> d = whole->body(body).get_contact_forces();
          force_scale      = std::max(force_scale, d.linfty_norm());
          total += resultant(whole->body(body), d);
          d -= by_curve->body(body).get_contact_forces();
          largest           = std::max(largest, d.linfty_norm());
          Vector<double> du = whole->body(body).displacement();
          du -= by_curve->body(body).displacement();
          largest           = std::max(largest, du.linfty_norm() * 1000.);
          Vector<double> dl = listed->body(body).get_contact_forces();
          dl -= by_curve->body(body).get_contact_forces();
          largest = std::max(largest, dl.linfty_norm());
        }
      const Tensor<1, 2> on_disk =
        resultant(whole->body("disk"),
                  whole->body("disk").get_contact_forces());
      const Tensor<1, 2> on_block =
        resultant(whole->body("block"),
                  whole->body("block").get_contact_forces());
      double deepest = 0.;
      for (const auto &p : whole->contact().contact_pairs())
        for (const auto &node : p->nodes())
          if (node.active)
            deepest = std::min(deepest, node.gap);
      std::cout << "  " << surface << ": force on the disk " << on_disk
                << ", on the block " << on_block
                << "; largest difference from the curves named one by one "
                << largest << " of " << force_scale
                << "; resultant of all three bodies' contact forces " << total
                << "; deepest slave gap " << deepest << std::endl;
      check(on_disk[1] > 1. && on_block[1] < -1.,
            surface + ": the disk and the block do not press on the ring");
      check(largest <= 1e-10 * force_scale,
            surface + ": not the forces of the curves named one by one");
      check(total.norm() <= 1e-10 * force_scale,
            surface + ": the contact forces do not balance");
      check(deepest >= -1e-8, surface + ": a slave node behind its master");

      // The same couples found by automatic contact (one pass, the ring
      // listed last: the master of both), its boundary as one name and as
      // two joined by '+'.
      for (const auto &[mesh, ring_side] :
           {std::pair<std::string, std::string>{one_name, "surface"},
            {two_names, "inner + outer"}})
        {
          const auto automatic =
            solved(ring_between_disk_and_block(
                     mesh,
                     " set Contact bodies = disk: outer, block: top, ring: " +
                       ring_side + "\n",
                     "subsection Automatic contact\n set Passes = one\n"
                     " set Surface = " +
                       surface + "\n set Alert distance = 0.1\nend\n"),
                   surface + ", automatic contact, ring: " + ring_side);
          double apart = 0.;
          for (const std::string body : {"ring", "disk", "block"})
            {
              Vector<double> d = automatic->body(body).get_contact_forces();
              d -= whole->body(body).get_contact_forces();
              apart = std::max(apart, d.linfty_norm());
            }
          std::cout << "  " << surface
                    << ", automatic contact, ring: " << ring_side << ": "
                    << automatic->contact().contact_pairs().size()
                    << " pairs, largest force difference " << apart
                    << std::endl;
          check(apart <= 1e-10 * force_scale,
                surface + ": automatic contact (ring: " + ring_side +
                  ") differs from the pairs written");
        }
    }

  // Mortar integrates over one curve: refused, with the reason.
  try
    {
      Simulation refused(SceneReader::read_string(
        ring_between_disk_and_block(
          one_name,
          " set Contact pairs = disk on ring\n",
          pair("disk on ring", "disk", "outer", "surface", "faceted") +
            "subsection Contact disk on ring\n set Discretisation = mortar\n"
            "end\n"),
        "mortar",
        own_directory("mortar")));
      check(false, "mortar on a master of two curves was not refused");
    }
  catch (const InputError &e)
    {
      std::cout << "  mortar: " << e.what() << std::endl;
      check(std::string(e.what()).find("has 2") != std::string::npos,
            "the refusal does not say the master has two curves");
    }
}

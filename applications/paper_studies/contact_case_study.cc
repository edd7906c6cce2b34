#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/body/body_measures.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/plotting.h>
#include <glissade/mesh/mesh_diameter.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <paper_studies/contact_case_study.h>
#include <paper_studies/study_progress.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    std::string
    stem_of(const std::string &file)
    {
      return std::filesystem::path(file).stem().string();
    }

    /** The overrides that turn a scene into one discretisation. */
    std::vector<std::string>
    variant_overrides(const SceneDescription &scene, const std::string &variant)
    {
      if (variant != "q4" && variant != "bspline" &&
          variant != "bspline-spline" && variant != "hermite" &&
          variant != "mortar")
        throw InputError("Contact case study/Variants",
                         "unknown variant '" + variant +
                           "' (known: q4, bspline, bspline-spline, hermite, "
                           "mortar)");
      std::vector<std::string> overrides;
      if (variant == "hermite")
        for (const auto &body : scene.bodies)
          overrides.push_back("Body " + body.name + "/Element/Space=hermite");
      // bspline-spline: the B-spline master with the spline's own force
      // transfer weights instead of the paper's segment hand-over.
      // mortar: the mortar discretisation, over the faceted master where
      // the master is a body.
      const std::string surface = variant == "q4" || variant == "mortar" ?
                                    "faceted" :
                                  variant == "hermite" ? "hermite" :
                                                         "bspline";
      for (const auto &contact : scene.contacts)
        {
          if (variant == "mortar")
            overrides.push_back("Contact " + contact.name +
                                "/Discretisation=mortar");
          if (contact.master == ContactDescription::MasterKind::obstacle)
            continue;
          overrides.push_back("Contact " + contact.name +
                              "/Surface=" + surface);
          if (variant == "bspline-spline")
            overrides.push_back("Contact " + contact.name +
                                "/Force transfer=spline");
        }
      return overrides;
    }

    const BodyDescription *
    find_body(const SceneDescription &scene, const std::string &name)
    {
      for (const auto &body : scene.bodies)
        if (body.name == name)
          return &body;
      return nullptr;
    }

    Tensor<1, 2>
    mirror(const Tensor<1, 2> &v)
    {
      return Tensor<1, 2>({-v[0], v[1]});
    }

    /** The vertex of a mesh at a point (looked up once, before the run). */
    unsigned int
    vertex_at(const Triangulation<2> &mesh,
              const Point<2>         &point,
              const std::string      &where)
    {
      const unsigned int v = GridTools::find_closest_vertex(mesh, point);
      if (mesh.get_vertices()[v].distance(point) > 1e-9 * mesh_diameter(mesh))
        throw InputError(where,
                         "no mesh vertex at the point the study measures");
      return v;
    }

    /**
     * The vertex that comes first by `before` (a strict order on points):
     * the ring's crown (the highest), the square's lower left corner.
     */
    template <typename Before>
    Point<2>
    extreme_vertex(const Triangulation<2> &mesh, const Before &before)
    {
      Point<2> best = mesh.get_vertices()[0];
      for (const auto &p : mesh.get_vertices())
        if (before(p, best))
          best = p;
      return best;
    }

    /** For every vertex of `a`, the vertex of `b` at its mirror image. */
    std::vector<unsigned int>
    mirror_vertices(const Triangulation<2> &a,
                    const Triangulation<2> &b,
                    const std::string      &where)
    {
      const double tolerance = 1e-9 * mesh_diameter(a);
      std::map<std::pair<long long, long long>, unsigned int> index;
      const auto key = [&](const Point<2> &p) {
        return std::make_pair(std::llround(p[0] / tolerance),
                              std::llround(p[1] / tolerance));
      };
      for (unsigned int v = 0; v < b.n_vertices(); ++v)
        index[key(b.get_vertices()[v])] = v;
      std::vector<unsigned int> result(a.n_vertices());
      for (unsigned int v = 0; v < a.n_vertices(); ++v)
        {
          const Point<2> &p     = a.get_vertices()[v];
          const auto      found = index.find(key(Point<2>(-p[0], p[1])));
          if (found == index.end())
            throw InputError(where,
                             "the meshes are not mirror images of each "
                             "other about x = 0 (no vertex at the "
                             "mirror of a vertex)");
          result[v] = found->second;
        }
      return result;
    }
  } // namespace



  ContactCaseResult
  ContactCaseStudy::run_variant(const std::string &scene_file,
                                const std::string &variant,
                                const unsigned int increments,
                                const double       load_fraction,
                                const std::string &output_directory,
                                const bool         progress,
                                const std::vector<std::string> &extra_overrides)
  {
    const SceneDescription base =
      SceneReader::read_file(scene_file, extra_overrides);
    std::vector<std::string> overrides = extra_overrides;
    for (const auto &o : variant_overrides(base, variant))
      overrides.push_back(o);
    overrides.push_back(std::string("Output/Progress=") +
                        (progress ? "true" : "false"));
    overrides.push_back("Output/Directory=" + output_directory + "/" +
                        stem_of(scene_file) + "/" + variant);
    if (increments > 0)
      {
        if (base.load_program.stage_end_times.size() != 1)
          throw InputError(scene_file,
                           "shortening a run needs a load program "
                           "of one stage");
        std::ostringstream end;
        end.precision(17);
        end << load_fraction * base.load_program.stage_end_times[0];
        overrides.push_back("Load program/Stage end times=" + end.str());
        overrides.push_back("Load program/Stage increments=" +
                            std::to_string(increments));
      }
    const SceneDescription scene =
      SceneReader::read_file(scene_file, overrides);
    Simulation simulation(scene);

    ContactCaseResult result;
    result.scene   = stem_of(scene_file);
    result.variant = variant;
    for (const auto &b : simulation.bodies())
      result.dofs += b->n_dofs();
    const auto &pairs = simulation.contact().contact_pairs();

    // Case 2: the two rings and the square, symmetric about x = 0.
    const BodyDescription *left_ring  = find_body(scene, "left ring");
    const BodyDescription *right_ring = find_body(scene, "right ring");
    const BodyDescription *square     = find_body(scene, "square");
    const ContactPair     *left_pair = nullptr, *right_pair = nullptr;
    for (const auto &pair : pairs)
      {
        if (pair->name() == "left")
          left_pair = pair.get();
        if (pair->name() == "right")
          right_pair = pair.get();
      }
    const bool symmetric_scene =
      left_ring && right_ring && square && left_pair && right_pair;
    std::vector<unsigned int>   ring_mirror, square_mirror;
    std::array<unsigned int, 2> crown_vertex;
    unsigned int                corner_vertex = 0;
    Point<2>                    square_corner;
    if (symmetric_scene)
      {
        // The crowns (top of each ring's outer edge, fig 19: its highest
        // vertex) and the square's lower left corner (figs 20-23).
        for (const unsigned int side : {0u, 1u})
          {
            const BodyDescription  &ring = side == 0 ? *left_ring : *right_ring;
            const Triangulation<2> &mesh =
              simulation.body(ring.name).triangulation();
            crown_vertex[side] =
              vertex_at(mesh,
                        extreme_vertex(mesh,
                                       [](const Point<2> &a,
                                          const Point<2> &b) {
                                         return a[1] > b[1];
                                       }),
                        scene_file + ": Body " + ring.name);
          }
        const Triangulation<2> &square_mesh =
          simulation.body("square").triangulation();
        square_corner =
          extreme_vertex(square_mesh, [](const Point<2> &a, const Point<2> &b) {
            return a[0] + a[1] < b[0] + b[1];
          });
        corner_vertex =
          vertex_at(square_mesh, square_corner, scene_file + ": Body square");
        ring_mirror =
          mirror_vertices(simulation.body("left ring").triangulation(),
                          simulation.body("right ring").triangulation(),
                          scene_file + ": Body right ring");
        square_mirror =
          mirror_vertices(simulation.body("square").triangulation(),
                          simulation.body("square").triangulation(),
                          scene_file + ": Body square");
      }

    simulation.on_increment = [&](const unsigned int, const double) {
      unsigned int active = 0;
      for (const auto &pair : pairs)
        for (const auto &node : pair->nodes())
          active += node.reaction[1] > 0. ? 1 : 0;
      result.active_nodes.push_back(active);

      // Rigid disk masters: the slave nodes against the exact circle.
      for (const auto &pair : pairs)
        {
          const ContactDescription &c = pair->settings();
          if (c.master != ContactDescription::MasterKind::obstacle ||
              c.obstacle != "disk")
            continue;
          const auto u        = vertex_displacements(pair->slave());
          double     smallest = std::numeric_limits<double>::max();
          for (const auto &node : pair->nodes())
            {
              const Point<2> x = node.reference_position + u[node.vertex];
              // (the disk's gap: the distance to its circle)
              const double distance = pair->surface().project(x).gap;
              smallest              = std::min(smallest, distance);
              if (node.reaction[1] > 0.)
                result.max_active_distance =
                  std::max(result.max_active_distance, std::abs(distance));
            }
          result.min_obstacle_distance.push_back(smallest);
        }

      if (symmetric_scene)
        {
          const auto u_left =
            vertex_displacements(simulation.body("left ring"));
          const auto u_right =
            vertex_displacements(simulation.body("right ring"));
          const auto u_square = vertex_displacements(simulation.body("square"));
          double     largest = 0., difference = 0.;
          for (unsigned int v = 0; v < u_left.size(); ++v)
            {
              largest =
                std::max({largest, u_left[v].norm(), u_right[v].norm()});
              difference =
                std::max(difference,
                         (u_left[v] - mirror(u_right[ring_mirror[v]])).norm());
            }
          for (unsigned int v = 0; v < u_square.size(); ++v)
            {
              largest    = std::max(largest, u_square[v].norm());
              difference = std::max(
                difference,
                (u_square[v] - mirror(u_square[square_mirror[v]])).norm());
            }
          result.symmetry_displacement.push_back(
            largest > 0. ? difference / largest : 0.);

          double largest_force = 0., force_difference = 0.;
          for (const auto &node : left_pair->nodes())
            {
              const Point<2>     image(-node.reference_position[0],
                                   node.reference_position[1]);
              const Tensor<1, 2> f = node.force(),
                                 g = mirror(right_pair->node_at(image).force());
              largest_force    = std::max({largest_force, f.norm(), g.norm()});
              force_difference = std::max(force_difference, (f - g).norm());
            }
          result.symmetry_force.push_back(
            largest_force > 0. ? force_difference / largest_force : 0.);

          result.crown_uy.push_back(
            {{u_left[crown_vertex[0]][1], u_right[crown_vertex[1]][1]}});
          result.corner_ux.push_back(u_square[corner_vertex][0]);
          result.corner_force.push_back(
            left_pair->node_at(square_corner).force().norm());
        }
    };

    Timer timer;
    simulation.run();
    result.wall_seconds      = timer.wall_time();
    result.increments        = simulation.statistics().increments;
    result.newton_iterations = simulation.statistics().newton_iterations;
    result.cut_backs         = simulation.statistics().cut_backs;

    for (const auto &b : simulation.bodies())
      {
        result.body_names.push_back(b->name());
        result.vertices.push_back(b->triangulation().get_vertices());
        result.final_displacement.push_back(vertex_displacements(*b));
        std::vector<std::array<unsigned int, 4>> cells;
        for (const auto &cell : b->triangulation().active_cell_iterators())
          cells.push_back({{cell->vertex_index(0),
                            cell->vertex_index(1),
                            cell->vertex_index(3),
                            cell->vertex_index(2)}});
        result.cells.push_back(std::move(cells));
      }
    for (const auto &pair : pairs)
      {
        const auto u = vertex_displacements(pair->slave());
        for (const auto &node : pair->nodes())
          if (node.reaction[1] > 0.)
            result.contact_forces.emplace_back(node.reference_position +
                                                 u[node.vertex],
                                               node.force());
      }
    return result;
  }



  double
  ContactCaseStudy::final_difference(const ContactCaseResult &a,
                                     const ContactCaseResult &b)
  {
    AssertThrow(a.final_displacement.size() == b.final_displacement.size(),
                ExcMessage("the two runs do not have the same bodies"));
    double largest = 0., difference = 0.;
    for (unsigned int i = 0; i < a.final_displacement.size(); ++i)
      {
        AssertThrow(a.final_displacement[i].size() ==
                      b.final_displacement[i].size(),
                    ExcMessage("the two runs do not share their meshes"));
        for (unsigned int v = 0; v < a.final_displacement[i].size(); ++v)
          {
            largest    = std::max(largest, a.final_displacement[i][v].norm());
            difference = std::max(
              difference,
              (a.final_displacement[i][v] - b.final_displacement[i][v]).norm());
          }
      }
    return largest > 0. ? difference / largest : 0.;
  }



  double
  ContactCaseStudy::roughness(const std::vector<double>       &f,
                              const unsigned int               first,
                              const unsigned int               last,
                              const std::vector<unsigned int> &loaded_nodes)
  {
    const auto quiet = [&](const unsigned int i) {
      if (loaded_nodes.empty())
        return true;
      for (int j = int(i) - 2; j <= int(i) + 2; ++j)
        if (j >= 0 && j < int(loaded_nodes.size()) &&
            loaded_nodes[j] != loaded_nodes[i])
          return false;
      return true;
    };
    double jump = 0., largest = 0.;
    for (unsigned int i = first; i < last && i < f.size(); ++i)
      {
        largest = std::max(largest, std::abs(f[i]));
        if (i > first && i + 1 < last && i + 1 < f.size() && quiet(i))
          jump = std::max(jump, std::abs(f[i + 1] - 2. * f[i] + f[i - 1]));
      }
    return largest > 0. ? jump / largest : 0.;
  }



  std::pair<unsigned int, unsigned int>
  ContactCaseStudy::contact_phase(const ContactCaseResult &r)
  {
    unsigned int first = 0;
    while (first < r.corner_force.size() && !(r.corner_force[first] > 0.))
      ++first;
    unsigned int last = first;
    while (last < r.corner_force.size() && r.corner_force[last] > 0.)
      ++last;
    return {first, last};
  }



  double
  ContactCaseStudy::kink_concentration(const std::vector<double> &f,
                                       const unsigned int         first,
                                       const unsigned int         last)
  {
    std::vector<double> second;
    for (unsigned int i = first + 1; i + 1 < last && i + 1 < f.size(); ++i)
      second.push_back(std::abs(f[i + 1] - 2. * f[i] + f[i - 1]));
    if (second.size() < 10)
      return 0.;
    std::sort(second.rbegin(), second.rend());
    double total = 0., top = 0.;
    for (std::size_t i = 0; i < second.size(); ++i)
      {
        total += second[i];
        if (i < second.size() / 10)
          top += second[i];
      }
    return total > 0. ? top / total : 0.;
  }



  namespace
  {
    std::string
    optional(const std::vector<double> &values, const unsigned int i)
    {
      if (i >= values.size())
        return "";
      std::ostringstream out;
      out.precision(12);
      out << values[i];
      return out.str();
    }

    void
    write_csv(const std::string                    &directory,
              const std::vector<ContactCaseResult> &runs)
    {
      const std::string scene = runs.front().scene;
      AtomicFile        history(directory + "/" + scene + "_history.csv");
      history.stream()
        << "variant,increment,active_nodes,min_obstacle_distance,"
           "symmetry_displacement,symmetry_force,crown_left_uy,"
           "crown_right_uy,corner_ux,corner_force\n";
      for (const auto &r : runs)
        {
          std::vector<double> left, right;
          for (const auto &c : r.crown_uy)
            {
              left.push_back(c[0]);
              right.push_back(c[1]);
            }
          for (unsigned int i = 0; i < r.active_nodes.size(); ++i)
            history.stream()
              << r.variant << ',' << i + 1 << ',' << r.active_nodes[i] << ','
              << optional(r.min_obstacle_distance, i) << ','
              << optional(r.symmetry_displacement, i) << ','
              << optional(r.symmetry_force, i) << ',' << optional(left, i)
              << ',' << optional(right, i) << ',' << optional(r.corner_ux, i)
              << ',' << optional(r.corner_force, i) << '\n';
        }
      history.commit();

      for (const auto &r : runs)
        {
          AtomicFile mesh(directory + "/" + scene + "_" + r.variant +
                          "_deformed.csv");
          mesh.stream() << "body,x0,y0,x1,y1,x2,y2,x3,y3\n";
          mesh.stream().precision(10);
          for (unsigned int b = 0; b < r.cells.size(); ++b)
            for (const auto &cell : r.cells[b])
              {
                mesh.stream() << r.body_names[b];
                for (const unsigned int v : cell)
                  {
                    const Point<2> x =
                      r.vertices[b][v] + r.final_displacement[b][v];
                    mesh.stream() << ',' << x[0] << ',' << x[1];
                  }
                mesh.stream() << '\n';
              }
          mesh.commit();
          AtomicFile forces(directory + "/" + scene + "_" + r.variant +
                            "_forces.csv");
          forces.stream() << "x,y,fx,fy\n";
          forces.stream().precision(12);
          for (const auto &[x, f] : r.contact_forces)
            forces.stream()
              << x[0] << ',' << x[1] << ',' << f[0] << ',' << f[1] << '\n';
          forces.commit();
        }
    }
  } // namespace



  void
  ContactCaseStudy::run(const std::string              &prm_file,
                        const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    prm.declare_entry("Study", "case1", Patterns::Selection("case1|case2"));
    prm.enter_subsection("Contact case study");
    prm.declare_entry("Scenes",
                      "",
                      Patterns::Anything(),
                      "Scene files, comma separated (relative to this file's "
                      "folder).");
    prm.declare_entry("Variants",
                      "q4, bspline, hermite",
                      Patterns::List(
                        Patterns::Selection("q4|bspline|hermite|mortar")),
                      "Discretisations: q4 (faceted masters), bspline (Q4 "
                      "bodies, B-spline masters), hermite (Hermite bodies and "
                      "masters), mortar (mortar, over the faceted masters of "
                      "bodies).");
    prm.declare_entry("Increments",
                      "0",
                      Patterns::Integer(0),
                      "0: each scene's own load program; otherwise this many "
                      "increments up to Load fraction of its end time.");
    prm.declare_entry("Load fraction",
                      "1",
                      Patterns::Double(0., 1.),
                      "With Increments > 0: where the shortened run stops.");
    prm.declare_entry("Output directory",
                      "output/contact_cases",
                      Patterns::Anything(),
                      "Where CSVs, PNGs and VTUs go.");
    prm.leave_subsection();
    SceneReader::parse_study(prm, prm_file, overrides);
    prm.enter_subsection("Contact case study");
    std::vector<std::string> scenes;
    for (const auto &name :
         Utilities::split_string_list(prm.get("Scenes"), ','))
      scenes.push_back(text::path_beside(prm_file, name));
    if (scenes.empty())
      throw InputError(prm_file + ": Contact case study/Scenes",
                       "no scene given");
    const auto variants =
      Utilities::split_string_list(prm.get("Variants"), ',');
    const unsigned int increments =
      SceneReader::get_integer(prm, "Increments", prm_file);
    const double fraction =
      SceneReader::get_double(prm, "Load fraction", prm_file);
    const std::string directory = prm.get("Output directory");
    prm.leave_subsection();
    std::filesystem::create_directories(directory);

    std::ostringstream table;
    table << std::setw(22) << "scene" << std::setw(9) << "variant"
          << std::setw(8) << "dofs" << std::setw(7) << "incr." << std::setw(8)
          << "Newton" << std::setw(10) << "wall (s)"
          << "  measure\n";
    StudyProgress progress(scenes.size() * variants.size());
    for (const auto &scene_file : scenes)
      {
        const SceneDescription scene = SceneReader::read_file(scene_file);
        bool                   rigid = true;
        for (const auto &c : scene.contacts)
          rigid = rigid && c.master == ContactDescription::MasterKind::obstacle;
        std::vector<ContactCaseResult> runs;
        for (const auto &variant : variants)
          {
            if (rigid && variant == "bspline")
              {
                std::cout << stem_of(scene_file) << ", bspline: skipped (the "
                          << "master is an exact rigid circle; the run would "
                          << "be the q4 run)" << std::endl;
                progress.skip();
                continue;
              }
            progress.next(stem_of(scene_file) + ", " + variant);
            runs.push_back(run_variant(
              scene_file, variant, increments, fraction, directory, true));
          }
        if (runs.empty())
          continue;
        write_csv(directory, runs);

        const ContactCaseResult *bspline = nullptr, *hermite = nullptr;
        for (const auto &r : runs)
          {
            if (r.variant == "bspline")
              bspline = &r;
            if (r.variant == "hermite")
              hermite = &r;
          }
        for (const auto &r : runs)
          {
            std::ostringstream measure;
            measure.precision(3);
            if (!r.min_obstacle_distance.empty())
              measure
                << "deepest penetration "
                << std::max(0.,
                            -*std::min_element(r.min_obstacle_distance.begin(),
                                               r.min_obstacle_distance.end()))
                << " m, loaded nodes off the circle by <= "
                << r.max_active_distance << " m";
            else if (!r.corner_force.empty())
              {
                const auto [first, last] = contact_phase(r);
                measure << "symmetry u "
                        << *std::max_element(r.symmetry_displacement.begin(),
                                             r.symmetry_displacement.end())
                        << ", f "
                        << *std::max_element(r.symmetry_force.begin(),
                                             r.symmetry_force.end())
                        << "; corner force roughness "
                        << roughness(r.corner_force,
                                     first + 2,
                                     last - 1,
                                     r.active_nodes)
                        << ", u_x kinks "
                        << kink_concentration(r.corner_ux, first + 2, last - 1);
              }
            else if (bspline && hermite && &r != hermite)
              measure << "final u differs from hermite by "
                      << final_difference(*hermite, r) * 100. << " %";
            table << std::setw(22) << r.scene << std::setw(9) << r.variant
                  << std::setw(8) << r.dofs << std::setw(7) << r.increments
                  << std::setw(8) << r.newton_iterations << std::setw(10)
                  << std::setprecision(3) << r.wall_seconds << "  "
                  << measure.str() << '\n';
          }
      }
    std::cout << '\n' << table.str() << std::flush;
    AtomicFile summary(directory + "/summary.txt");
    summary.stream() << table.str();
    summary.commit();
    plot_with_python("plot_contact_cases.py", directory);
  }
} // namespace glissade

// Reading a scene: the passes over the .prm file (the names first, then
// every entry strictly), the command line's overrides, and the scene's own
// entries (Study, Scene). Each section declares and reads its entries in
// the file of its subject: body_section.cc (with mesh_section.cc and
// material_section.cc), contact_section.cc, load_program_section.cc,
// output_section.cc.

#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/scene/parameter_file.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/scene/section_reader.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** The path an "A/B/Entry=value" override sets: {"A", "B", "Entry"}
     *  (each trimmed). */
    std::vector<std::string>
    override_path(const std::string &assignment)
    {
      return Utilities::split_string_list(
        assignment.substr(0, assignment.find('=')), '/');
    }

    /** Applies one "A/B/Entry=value" override. */
    void
    apply_override(ParameterHandler &prm, const std::string &assignment)
    {
      const auto equal = assignment.find('=');
      if (equal == std::string::npos)
        throw InputError("--set " + assignment,
                         "expected 'Subsection/Entry=value'");
      const auto        path  = override_path(assignment);
      const std::string value = text::trim(assignment.substr(equal + 1));
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.enter_subsection(path[i]);
      try
        {
          prm.set(path.back(), value);
        }
      catch (const std::exception &e)
        {
          throw InputError("--set " + assignment, text::essential_message(e));
        }
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.leave_subsection();
    }

    /**
     * Each name once. Body and contact pair names become parts of output
     * file names
     * ("<body>-00010.vtu", "contact-<pair>-00010.csv"): a name that is a
     * path ("up/../../x") would write outside the output directory.
     */
    void
    check_file_name_parts(const std::vector<std::string> &names,
                          const std::string              &entry,
                          const std::string              &what)
    {
      for (const auto &name : names)
        {
          bool printable = true;
          for (const unsigned char c : name)
            printable = printable && c >= 32 && c != 127;
          // '"', '<', '>' and '&' would break the PVD index (XML).
          if (name.empty() || name == "." || name == ".." ||
              name.find_first_of("/\\\"<>&") != std::string::npos ||
              !printable || name.size() > 100)
            throw InputError(entry,
                             what + " name '" + name.substr(0, 100) +
                               (name.size() > 100 ? "...'" : "'") +
                               " cannot be part of a file name: use at most "
                               "100 letters, digits, spaces, '-', '_' or "
                               "'.', without '/', '\\', '\"', '<', '>' "
                               "or '&'");
        }
      for (unsigned int i = 0; i < names.size(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          if (names[i] == names[j])
            throw InputError(entry,
                             what + " '" + names[i] + "' is named twice");
    }



    std::vector<std::string>
    read_body_names(const std::string &text_value, const std::string &source)
    {
      const auto names = Utilities::split_string_list(text_value, ',');
      if (names.empty())
        throw InputError(source + ": Scene/Bodies",
                         "the scene needs at least one body");
      check_file_name_parts(names, source + ": Scene/Bodies", "body");
      return names;
    }



    /**
     * A 64-bit FNV-1a hash of every value of the scene except the
     * sections Checkpoint (a run stopped half-way and its restart differ
     * there) and Linear solver: a restart refuses a checkpoint of another
     * scene.
     */
    std::string
    fingerprint(ParameterHandler &prm, const std::vector<std::string> &files)
    {
      prm.enter_subsection("Checkpoint");
      const std::string interval = prm.get("Interval");
      const std::string stop     = prm.get("Stop after increment");
      prm.set("Interval", "0");
      prm.set("Stop after increment", "0");
      prm.leave_subsection();
      std::ostringstream printed;
      prm.print_parameters(printed, ParameterHandler::ShortPRM);
      prm.enter_subsection("Checkpoint");
      prm.set("Interval", interval);
      prm.set("Stop after increment", stop);
      prm.leave_subsection();
      // Where a run keeps its factors does not change the problem (a
      // restart may choose otherwise): the section Linear solver left out,
      // so that checkpoints written before it existed are still read.
      std::string       kept    = printed.str();
      const std::string section = "subsection Linear solver\n";
      if (const auto begin = kept.find(section); begin != std::string::npos)
        kept.erase(begin, kept.find("\nend\n", begin) + 5 - begin);
      std::ostringstream text;
      text << kept;
      // The content of the files the scene reads (meshes): a restart after a
      // mesh file changed would otherwise continue a different problem.
      for (const auto &file : files)
        {
          // Only what the mesh reader will accept (it refuses the rest with
          // a message): a device such as /dev/zero never ends.
          if (!text::is_regular_file_of_at_most(file, 1ull << 31))
            continue;
          std::ifstream in(file, std::ios::binary);
          text << "\nfile " << file << '\n' << in.rdbuf();
        }

      std::uint64_t hash = 14695981039346656037ull;
      for (const char c : text.str())
        {
          hash ^= static_cast<unsigned char>(c);
          hash *= 1099511628211ull;
        }
      std::ostringstream hex;
      hex << std::hex << std::setw(16) << std::setfill('0') << hash;
      return hex.str();
    }



    /**
     * Parses the file's text into prm, then applies the overrides that
     * `applies` selects; deal.II's errors become an InputError naming the
     * file (ours pass as they are).
     */
    void
    parse_with_overrides(ParameterHandler               &prm,
                         const std::string              &text_value,
                         const std::string              &source,
                         const bool                      skip_undefined,
                         const std::vector<std::string> &overrides,
                         const std::function<bool(const std::string &)> applies)
    {
      try
        {
          prm.parse_input_from_string(text_value, "", skip_undefined);
          for (const auto &o : overrides)
            if (applies(o))
              apply_override(prm, o);
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const std::exception &e)
        {
          throw InputError(source, text::essential_message(e));
        }
    }



    /** Pass 1 over the file: the body and contact pair names only. */
    void
    read_scene_names(const std::string              &text_value,
                     const std::string              &source,
                     const std::vector<std::string> &overrides,
                     std::vector<std::string>       &body_names,
                     std::vector<std::string>       &contact_names)
    {
      ParameterHandler prm;
      prm.enter_subsection("Scene");
      prm.declare_entry("Bodies", "body", Patterns::Anything());
      prm.declare_entry("Contact pairs", "", Patterns::Anything());
      prm.leave_subsection();
      // (only the overrides of these two: the other entries of Scene, as
      // Contact bodies, are declared by the pass that reads everything)
      parse_with_overrides(
        prm, text_value, source, true, overrides, [](const std::string &o) {
          const auto path = override_path(o);
          return path.size() == 2 && path[0] == "Scene" &&
                 (path[1] == "Bodies" || path[1] == "Contact pairs");
        });
      prm.enter_subsection("Scene");
      body_names = read_body_names(prm.get("Bodies"), source);
      contact_names =
        Utilities::split_string_list(prm.get("Contact pairs"), ',');
      check_file_name_parts(contact_names,
                            source + ": Scene/Contact pairs",
                            "contact pair");
      prm.leave_subsection();
    }



    /**
     * Pass 1b: each body's material regions, whose subsections pass 2
     * declares by name.
     */
    std::map<std::string, std::vector<std::string>>
    read_material_regions(const std::string              &text_value,
                          const std::string              &source,
                          const std::vector<std::string> &overrides,
                          const std::vector<std::string> &body_names)
    {
      ParameterHandler prm;
      for (const auto &name : body_names)
        {
          prm.enter_subsection("Body " + name);
          prm.enter_subsection("Material");
          prm.declare_entry("Regions", "", Patterns::Anything());
          prm.leave_subsection();
          prm.leave_subsection();
        }
      parse_with_overrides(
        prm, text_value, source, true, overrides, [](const std::string &o) {
          const auto path = override_path(o);
          return path.size() == 3 && path[1] == "Material" &&
                 path[2] == "Regions";
        });
      std::map<std::string, std::vector<std::string>> regions;
      for (const auto &name : body_names)
        {
          prm.enter_subsection("Body " + name);
          prm.enter_subsection("Material");
          regions[name] = Utilities::split_string_list(prm.get("Regions"), ',');
          prm.leave_subsection();
          prm.leave_subsection();
          const std::string entry =
            source + ": Body " + name + "/Material/Regions";
          for (unsigned int i = 0; i < regions[name].size(); ++i)
            for (unsigned int j = 0; j < i; ++j)
              if (regions[name][i] == regions[name][j])
                throw InputError(entry,
                                 "region '" + regions[name][i] +
                                   "' is named twice");
        }
      return regions;
    }



    /**
     * ParameterHandler reports paths with special characters mangled as
     * "_XX" (hex): the path as the file wrote it.
     */
    std::string
    demangle_path(const std::string &mangled)
    {
      std::string plain;
      for (unsigned int i = 0; i < mangled.size(); ++i)
        if (mangled[i] == '_' && i + 2 < mangled.size() &&
            std::isxdigit(mangled[i + 1]) && std::isxdigit(mangled[i + 2]))
          {
            plain += static_cast<char>(
              std::stoi(mangled.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          plain += mangled[i];
      return plain;
    }



    /**
     * Mesh/Type must be set for every body: how a body of Scene/Bodies
     * without its subsection is caught.
     */
    void
    check_every_body_has_a_mesh(const ParameterHandler         &prm,
                                const std::vector<std::string> &body_names,
                                const std::string              &source)
    {
      for (const auto &name : body_names)
        for (const auto &missing : prm.get_entries_wrongly_not_set())
          if (demangle_path(missing).find("Body " + name) != std::string::npos)
            throw InputError(source + ": Body " + name + "/Mesh/Type",
                             "is not set: every body of Scene/Bodies needs a "
                             "'subsection Body " +
                               name + "' with at least its Mesh/Type");
    }
  } // namespace



  namespace
  {
    std::vector<std::pair<std::string, std::string>> &
    registered_studies()
    {
      static std::vector<std::pair<std::string, std::string>> studies;
      return studies;
    }
  } // namespace



  void
  SceneReader::register_studies(
    const std::vector<std::pair<std::string, std::string>> &studies)
  {
    registered_studies() = studies;
  }



  void
  SceneReader::declare_parameters(
    ParameterHandler                                      &prm,
    const std::vector<std::string>                        &body_names,
    const std::vector<std::string>                        &contact_names,
    const std::map<std::string, std::vector<std::string>> &regions)
  {
    std::string pattern = "simulation",
                help    = "simulation: run the scene below.";
    for (const auto &[name, sentence] : registered_studies())
      {
        pattern += "|" + name;
        help += " " + name + ": " + sentence + ".";
      }
    if (!registered_studies().empty())
      help += " A study's own entries replace these.";
    prm.declare_entry("Study",
                      "simulation",
                      Patterns::Selection(pattern),
                      help);
    prm.enter_subsection("Scene");
    prm.declare_entry("Bodies",
                      "body",
                      Patterns::Anything(),
                      "Comma-separated names of the bodies; each has a "
                      "subsection 'Body <name>'.");
    prm.declare_entry("Contact pairs",
                      "",
                      Patterns::Anything(),
                      "Comma-separated names of the contact pairs; each has a "
                      "subsection 'Contact <name>'.");
    prm.leave_subsection();

    for (const auto &name : contact_names)
      {
        prm.enter_subsection("Contact " + name);
        ContactDescription::declare_parameters(prm);
        prm.leave_subsection();
      }
    AutomaticContact::declare_parameters(prm);

    for (const auto &name : body_names)
      {
        prm.enter_subsection("Body " + name);
        const auto body_regions = regions.find(name);
        BodyDescription::declare_parameters(prm,
                                            body_regions == regions.end() ?
                                              std::vector<std::string>() :
                                              body_regions->second);
        prm.leave_subsection();
      }

    LoadProgram::declare_parameters(prm);
    TimeIntegrationSettings::declare_parameters(prm);
    NewtonSettings::declare_parameters(prm);
    ContactSolverSettings::declare_parameters(prm);
    OutputSettings::declare_parameters(prm);
    CheckpointSettings::declare_parameters(prm);
    LinearSolverSettings::declare_parameters(prm);
  }



  namespace
  {
    /**
     * A pair whose Slave body lists several bodies ("a, b") or is '*'
     * (every body of Scene/Contact bodies), against a rigid obstacle: a
     * pair of each body, "<body> on <pair>", the written pair's name their
     * group (history's contact_force(<pair>) sums them). Any other pair
     * as it is.
     */
    std::vector<ContactDescription>
    pairs_of_each_slave_body(const ContactDescription       &contact,
                             const AutomaticContact         &automatic,
                             const std::vector<std::string> &declared)
    {
      std::vector<std::string> bodies;
      if (contact.slave_body == "*")
        for (const auto &side : automatic.sides)
          bodies.push_back(side.body);
      else
        for (const auto &body : text::split_top_level(contact.slave_body, ','))
          bodies.push_back(text::trim(body));
      if (contact.slave_body != "*" && bodies.size() == 1)
        return {contact};
      const std::string where = contact.entry + "/Slave body";
      if (contact.master != ContactDescription::MasterKind::obstacle)
        throw InputError(where,
                         "lists several bodies: that is for a rigid "
                         "obstacle (Master body = rigid); between bodies, "
                         "use Scene/Contact bodies");
      if (bodies.empty())
        throw InputError(where,
                         "is '*', every body of Scene/Contact bodies, "
                         "which lists none");
      std::vector<ContactDescription> pairs;
      for (const auto &body : bodies)
        {
          for (const auto &earlier : pairs)
            if (earlier.slave_body == body)
              throw InputError(where, "lists '" + body + "' twice");
          ContactDescription pair = contact;
          pair.group              = contact.name;
          pair.slave_body         = body;
          pair.name               = body + " on " + contact.name;
          pair.entry              = contact.entry + " (body '" + body + "')";
          if (std::find(declared.begin(), declared.end(), pair.name) !=
              declared.end())
            throw InputError(where,
                             "makes the pair '" + pair.name +
                               "', which Scene/Contact pairs names too");
          pairs.push_back(pair);
        }
      return pairs;
    }
  } // namespace



  SceneDescription
  SceneReader::parse_parameters(ParameterHandler               &handler,
                                const std::vector<std::string> &body_names,
                                const std::vector<std::string> &contact_names,
                                const std::string              &source)
  {
    SceneDescription scene;
    SectionReader    prm(handler, source);
    scene.source = source;

    // Each part is checked even when an earlier one has a mistake: the user
    // reads every mistake of the file in one message.
    prm.check([&]() { scene.contact_solver.parse_parameters(prm); });
    prm.check([&]() { scene.time_integration.parse_parameters(prm); });
    prm.check([&]() { scene.linear_solver.parse_parameters(prm); });
    std::vector<ContactDescription> made_by_automatic_contact;
    prm.check([&]() {
      made_by_automatic_contact = AutomaticContact::parse_parameters(
        prm, body_names, contact_names, scene.automatic_contact);
    });
    for (const auto &name : contact_names)
      prm.check([&]() {
        ContactDescription contact;
        contact.name = name;
        prm.enter_subsection("Contact " + name);
        contact.parse_parameters(prm, body_names);
        scene.contact_solver.take_pair_entries(prm, contact.entry);
        prm.leave_subsection();
        for (auto &pair : pairs_of_each_slave_body(contact,
                                                   scene.automatic_contact,
                                                   contact_names))
          scene.contacts.push_back(std::move(pair));
      });
    for (auto &contact : made_by_automatic_contact)
      scene.contacts.push_back(std::move(contact));
    // Under a dynamic scheme a B-spline master takes the reaction by the
    // spline's weights, the gap's gradient: the paper's segment transfer
    // hands it to forces that are not, whose work on a node sliding over a
    // step is first order in its motion and of either sign (measured: a
    // disk glancing off another gained 2.5 times its energy), and which
    // the forces over the step (discrete_gradient.h) could only correct
    // by as much, at the cost of Newton's quadratic convergence.
    if (scene.time_integration.dynamic())
      {
        for (auto &contact : scene.contacts)
          contact.force_transfer = ContactDescription::ForceTransfer::spline;
        scene.automatic_contact.settings.force_transfer =
          ContactDescription::ForceTransfer::spline;
      }
    for (const auto &name : body_names)
      {
        BodyDescription body;
        body.name = name;
        prm.enter_subsection("Body " + name);
        body.parse_parameters(prm);
        prm.leave_subsection();
        // A body that nothing holds (no Dirichlet datum, no contact pair,
        // no elastic foundation) has a singular tangent: its rigid-body motions
        // are free. The factorisation would not always say so (round-off
        // pivots), and the run would end on an inverted element far from the
        // cause.
        bool in_contact = false;
        for (const auto &c : scene.contacts)
          in_contact =
            in_contact || c.slave_body == name || c.master_body == name;
        for (const auto &side : scene.automatic_contact.sides)
          in_contact = in_contact || side.body == name;
        if (body.dirichlet.empty() && !in_contact &&
            !(body.elastic_foundation > 0.) &&
            !scene.time_integration.dynamic())
          prm.check([&]() {
            throw InputError(source + ": Body " + name + "/Boundary conditions",
                             "body '" + name +
                               "' has no support: no Fixed, Prescribed "
                               "displacement or rotation, no contact pair "
                               "and no Elastic foundation, so its "
                               "rigid-body motions (two "
                               "translations and a rotation) are free");
          });
        scene.bodies.push_back(body);
      }
    scene.load_program.parse_parameters(prm);
    // A dynamic scheme integrates every body's inertia: a body without
    // mass would have none, and its equations no time derivative.
    if (scene.time_integration.dynamic())
      for (const auto &body : scene.bodies)
        prm.check([&]() {
          if (!(body.material.density > 0.))
            throw InputError(source + ": Body " + body.name +
                               "/Material/Density",
                             "must be > 0 for the dynamic scheme of Time "
                             "integration/Scheme (body '" +
                               body.name + "' would have no inertia)");
        });
    for (const auto &body : scene.bodies)
      prm.check([&]() {
        if (!body.gravity.empty() && !(body.material.density > 0.))
          throw InputError(source + ": Body " + body.name +
                             "/Boundary conditions/Gravity",
                           "acts on the mass, and Material/Density is 0");
      });
    scene.newton.parse_parameters(prm);
    scene.output.parse_parameters(prm);
    scene.checkpoint.parse_parameters(prm, scene.load_program);

    prm.throw_if_any();
    std::vector<std::string> files_read;
    for (const auto &body : scene.bodies)
      if (!body.mesh.file.empty())
        files_read.push_back(body.mesh.file);
    scene.fingerprint = fingerprint(handler, files_read);
    return scene;
  }



  SceneDescription
  SceneReader::read_string(const std::string              &text_value,
                           const std::string              &source,
                           const std::vector<std::string> &overrides)
  {
    std::vector<std::string> body_names, contact_names;
    read_scene_names(text_value, source, overrides, body_names, contact_names);
    const std::map<std::string, std::vector<std::string>> regions =
      read_material_regions(text_value, source, overrides, body_names);

    // Pass 2: everything, strictly: an undeclared entry is an error.
    ParameterHandler prm;
    declare_parameters(prm, body_names, contact_names, regions);
    parse_with_overrides(prm,
                         text_value,
                         source,
                         false,
                         overrides,
                         [](const std::string &) { return true; });
    check_every_body_has_a_mesh(prm, body_names, source);
    try
      {
        return parse_parameters(prm, body_names, contact_names, source);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        // A value that matches its pattern but does not convert (a
        // denormal like 1e-320 for a double): deal.II's message names the
        // entry. Found by the fuzzer.
        throw InputError(source, text::essential_message(e));
      }
  }



  SceneDescription
  SceneReader::read_file(const std::string              &filename,
                         const std::vector<std::string> &overrides)
  {
    return read_string(read_parameter_file(filename), filename, overrides);
  }



  void
  SceneReader::parse_study(ParameterHandler               &prm,
                           const std::string              &filename,
                           const std::vector<std::string> &overrides)
  {
    const std::string text_value = read_parameter_file(filename);
    try
      {
        prm.parse_input_from_string(text_value, "", false);
        for (const auto &o : overrides)
          apply_override(prm, o);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        throw InputError(filename, text::essential_message(e));
      }
  }



  namespace
  {
    /** A value read from prm, with a failed conversion as an InputError. */
    template <typename Read>
    auto
    converted(const Read &read, const std::string &filename)
    {
      try
        {
          return read();
        }
      catch (const std::exception &e)
        {
          throw InputError(filename, text::essential_message(e));
        }
    }
  } // namespace



  double
  SceneReader::get_double(const ParameterHandler &prm,
                          const std::string      &entry,
                          const std::string      &filename)
  {
    return converted([&]() { return prm.get_double(entry); }, filename);
  }



  long int
  SceneReader::get_integer(const ParameterHandler &prm,
                           const std::string      &entry,
                           const std::string      &filename)
  {
    return converted([&]() { return prm.get_integer(entry); }, filename);
  }



  std::string
  SceneReader::study_type(const std::string &filename)
  {
    const std::string text_value = read_parameter_file(filename);
    ParameterHandler  prm;
    prm.declare_entry("Study", "simulation", Patterns::Anything());
    try
      {
        prm.parse_input_from_string(text_value, "", true);
      }
    catch (const std::exception &e)
      {
        throw InputError(filename, text::essential_message(e));
      }
    return prm.get("Study");
  }



  void
  SceneReader::print_parameters(std::ostream &out)
  {
    ParameterHandler prm;
    declare_parameters(prm, {"body"}, {"pair"});
    prm.print_parameters(out,
                         ParameterHandler::PRM |
                           ParameterHandler::KeepDeclarationOrder);
  }
} // namespace glissade

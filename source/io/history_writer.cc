#include <glissade/base/input_error.h>
#include <glissade/base/processes.h>
#include <glissade/base/text.h>
#include <glissade/body/body_measures.h>
#include <glissade/contact/surfaces/abradable_coating.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/history_writer.h>

#include <cctype>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * A plain identifier from a name or a location, for a column header
     * that pandas, gnuplot and R read as it is: letters, digits and '_';
     * '-' becomes 'm' and '.' 'p' in numbers, anything else one '_'
     * ("point(-0.025, 0.5)" -> "m0p025_0p5", "beam on ring" ->
     * "beam_on_ring").
     */
    std::string
    identifier(const std::string &text)
    {
      std::string result;
      for (const char c : text)
        {
          if (std::isalnum(static_cast<unsigned char>(c)) || c == '_')
            result += c;
          else if (c == '-')
            result += 'm';
          else if (c == '.')
            result += 'p';
          else if (!result.empty() && result.back() != '_')
            result += '_';
        }
      while (!result.empty() && result.back() == '_')
        result.pop_back();
      return result;
    }

    /** "point(x, y)" -> "x_y" as an identifier, a boundary name as itself. */
    std::string
    location_identifier(const std::string &location)
    {
      const std::string trimmed = text::trim(location);
      if (trimmed.rfind("point(", 0) == 0 && trimmed.back() == ')')
        return identifier(trimmed.substr(6, trimmed.size() - 7));
      return identifier(trimmed);
    }

    /** The reference position of an item's "point(x, y)". */
    Point<2>
    point_of(const std::string &location,
             const std::string &item,
             const std::string &entry)
    {
      double x, y;
      if (!text::parse_point_location(location, x, y))
        throw InputError(entry, "'" + item + "': expected point(x, y)");
      return Point<2>(x, y);
    }
  } // namespace


  HistoryWriter::HistoryWriter(const std::vector<std::string>           &items,
                               const std::vector<std::unique_ptr<Body>> &bodies,
                               ContactProblem      &contact,
                               const std::string   &filename,
                               const std::string   &source,
                               const EnergyAccount *energies)
    : filename(filename)
  {
    columns                 = {"increment", "time", "newton_iterations"};
    const std::string entry = source + ": Output/History";
    for (const auto &item : items)
      add_item(item, bodies, contact, energies, entry);

    // Names that differ only in what an identifier cannot hold ("a b" and
    // "a_b") would give two columns one header.
    for (unsigned int i = 0; i < columns.size(); ++i)
      for (unsigned int j = 0; j < i; ++j)
        if (columns[i] == columns[j])
          throw InputError(entry,
                           "two items give the column '" + columns[i] +
                             "' (body, pair or location names that differ "
                             "only in spaces, signs or punctuation): rename "
                             "one, or remove the repeated item");
  }



  void
  HistoryWriter::add_item(const std::string                        &item,
                          const std::vector<std::unique_ptr<Body>> &bodies,
                          ContactProblem                           &contact,
                          const EnergyAccount                      *energies,
                          const std::string                        &entry)
  {
    // "kind(arguments)": the energies take none, a pair's items name the
    // pair first, a body's items the body.
    const auto open = item.find('(');
    if (open == std::string::npos || item.back() != ')')
      throw InputError(entry, "cannot read '" + item + "'");
    const std::string kind = text::trim(item.substr(0, open));
    const auto        args =
      text::split_top_level(item.substr(open + 1, item.size() - open - 2), ',');
    if (kind == "energies" &&
        (args.empty() || (args.size() == 1 && text::trim(args[0]).empty())))
      {
        add_energies(energies, item, entry);
        return;
      }
    if (args.empty())
      throw InputError(entry, "'" + item + "' names no body");

    // (an automatic couple's pair is made if it is not yet)
    const ContactPair *pair = contact.pair_named(args[0]);
    if (kind == "contact_force" && pair != nullptr && args.size() == 1)
      {
        add_contact_force(*pair, args[0]);
        return;
      }
    // A pair written with several slave bodies: the sum of the pairs made
    // of it (ContactDescription::group).
    bool group = false;
    for (const auto &p : contact.contact_pairs())
      group = group || p->settings().group == args[0];
    if (kind == "contact_force" && group && args.size() == 1)
      {
        for (const std::string q : {"Fx", "Fy", "active_nodes"})
          columns.push_back(identifier(args[0]) + "_" + q);
        evaluators.emplace_back(
          [name = args[0], &contact](std::vector<double> &row) {
            Tensor<1, 2> f;
            unsigned int active = 0;
            for (const auto &p : contact.contact_pairs())
              if (p->settings().group == name)
                {
                  f += p->total_force();
                  active += p->n_active();
                }
            row.push_back(f[0]);
            row.push_back(f[1]);
            row.push_back(active);
          });
        return;
      }
    if (kind == "contact_node" && pair != nullptr && args.size() == 2)
      {
        add_contact_node(*pair, args[0], args[1], item, entry);
        return;
      }
    if (kind == "wear" && pair != nullptr && args.size() == 1)
      {
        if (pair->coating() == nullptr)
          throw InputError(entry,
                           "'" + item + "': pair '" + args[0] +
                             "' has no abradable coating (Obstacle/Coating "
                             "thickness)");
        columns.push_back(identifier(args[0]) + "_removed_area");
        columns.push_back(identifier(args[0]) + "_worn_depth");
        evaluators.emplace_back([pair](std::vector<double> &row) {
          const auto &profile = pair->coating()->profile();
          row.push_back(pair->removed_area());
          row.push_back(*std::max_element(profile.begin(), profile.end()));
        });
        return;
      }

    const Body *body = nullptr;
    for (const auto &b : bodies)
      if (b->name() == args[0])
        body = b.get();
    if (body == nullptr)
      throw InputError(entry,
                       "'" + item + "': there is no body '" + args[0] + "'");
    if (kind == "momentum" && args.size() == 1)
      add_momentum(*body, args[0], item, entry);
    else if (kind == "max_displacement" && args.size() == 1)
      {
        columns.push_back(identifier(args[0]) + "_max_u");
        evaluators.emplace_back([body](std::vector<double> &row) {
          row.push_back(max_displacement(*body));
        });
      }
    else if (kind == "displacement" && args.size() == 2)
      add_displacement(*body, args[0], args[1], item, entry);
    else if (kind == "reaction" && args.size() == 2)
      add_reaction(*body, args[0], args[1], entry);
    else if (kind == "contact_force_on" && args.size() == 1)
      {
        // Every pair's force on the body, the pairs made later too (a
        // couple of automatic contact): on its slave nodes as reported,
        // and the opposite of a pair's total where the body is the master
        // (the master's nodal forces are the slave's spread by the shape
        // functions, whose weights sum to one).
        for (const std::string q : {"Fx", "Fy", "active_nodes"})
          columns.push_back(identifier(args[0]) + "_contact_" + q);
        evaluators.emplace_back([body, &contact](std::vector<double> &row) {
          Tensor<1, 2> f;
          unsigned int active = 0;
          for (const auto &pair : contact.contact_pairs())
            {
              if (&pair->slave() == body)
                {
                  f += pair->total_force();
                  active += pair->n_active();
                }
              if (pair->master() == body)
                f -= pair->total_force();
            }
          row.push_back(f[0]);
          row.push_back(f[1]);
          row.push_back(active);
        });
      }
    else
      throw InputError(entry,
                       "cannot read '" + item +
                         "' (known: displacement(body, point(x, y)), "
                         "max_displacement(body), reaction(body, "
                         "boundary), contact_force_on(body), "
                         "contact_force(pair), "
                         "contact_node(pair, point(x, y)), wear(pair); dynamic "
                         "schemes: momentum(body), energies())");
  }



  void
  HistoryWriter::add_energies(const EnergyAccount *energies,
                              const std::string   &item,
                              const std::string   &entry)
  {
    if (energies == nullptr)
      throw InputError(entry,
                       "'" + item +
                         "': the energies are those of a dynamic "
                         "scheme (Time integration/Scheme)");
    for (const std::string q : {"kinetic_energy",
                                "strain_energy",
                                "work_of_loads",
                                "contact_dissipation",
                                "friction_dissipation",
                                "damping_dissipation",
                                "scheme_dissipation",
                                "energy_balance"})
      columns.push_back(q);
    evaluators.emplace_back([energies](std::vector<double> &row) {
      row.push_back(energies->kinetic);
      row.push_back(energies->strain);
      row.push_back(energies->work_of_loads);
      row.push_back(energies->contact_dissipation());
      row.push_back(energies->friction_dissipation);
      row.push_back(energies->damping_dissipation);
      row.push_back(energies->scheme_dissipation);
      row.push_back(energies->balance());
    });
  }



  void
  HistoryWriter::add_contact_force(const ContactPair &pair,
                                   const std::string &name)
  {
    for (const std::string q : {"Fx", "Fy", "active_nodes"})
      columns.push_back(identifier(name) + "_" + q);
    evaluators.emplace_back([pair = &pair](std::vector<double> &row) {
      const Tensor<1, 2> f = pair->total_force();
      row.push_back(f[0]);
      row.push_back(f[1]);
      row.push_back(pair->n_active());
    });
  }



  void
  HistoryWriter::add_contact_node(const ContactPair &pair,
                                  const std::string &name,
                                  const std::string &location,
                                  const std::string &item,
                                  const std::string &entry)
  {
    const Point<2> X = point_of(location, item, entry);
    if (pair.node_at(X).reference_position.distance(X) > 1e-8 * (1. + X.norm()))
      throw InputError(entry,
                       "'" + item + "': no slave node of pair '" + name +
                         "' at that reference position");
    for (const std::string q : {"r_n", "r_t", "f", "gap"})
      columns.push_back(identifier(name) + "_" + q + "_" +
                        location_identifier(location));
    evaluators.emplace_back([pair = &pair, X](std::vector<double> &row) {
      const ContactNode          &node = pair->node_at(X);
      const std::array<double, 2> r    = pair->reported_reaction(node);
      row.push_back(r[1]);
      row.push_back(r[0]);
      row.push_back(pair->reported_force(node).norm());
      row.push_back(node.gap);
    });
  }



  void
  HistoryWriter::add_momentum(const Body        &body,
                              const std::string &name,
                              const std::string &item,
                              const std::string &entry)
  {
    if (body.inertia() == nullptr)
      throw InputError(entry,
                       "'" + item +
                         "': a body's momentum is that of a dynamic "
                         "scheme (Time integration/Scheme)");
    for (const std::string q : {"px", "py"})
      columns.push_back(identifier(name) + "_" + q);
    evaluators.emplace_back([body = &body](std::vector<double> &row) {
      const auto p = body->inertia()->momentum();
      row.push_back(p[0]);
      row.push_back(p[1]);
    });
  }



  void
  HistoryWriter::add_displacement(const Body        &body,
                                  const std::string &name,
                                  const std::string &location,
                                  const std::string &item,
                                  const std::string &entry)
  {
    const Point<2> X = point_of(location, item, entry);
    // The vertex and its dofs are found once: searching them at every
    // increment made 320 columns cost 6 times the solve.
    std::array<types::global_dof_index, 2> vertex_dofs;
    try
      {
        vertex_dofs = vertex_value_dofs(body, X);
      }
    catch (const InputError &e)
      {
        throw InputError(entry, e.what());
      }
    for (const std::string q : {"ux", "uy"})
      columns.push_back(identifier(name) + "_" + q + "_" +
                        location_identifier(location));
    evaluators.emplace_back(
      [body = &body, vertex_dofs](std::vector<double> &row) {
        row.push_back(body->nodal_displacement()(vertex_dofs[0]));
        row.push_back(body->nodal_displacement()(vertex_dofs[1]));
      });
  }



  void
  HistoryWriter::add_reaction(const Body        &body,
                              const std::string &name,
                              const std::string &where,
                              const std::string &entry)
  {
    // (a boundary that the body does not have is refused now)
    try
      {
        support_reaction(body, where);
      }
    catch (const InputError &e)
      {
        throw InputError(entry, e.what());
      }
    for (const std::string q : {"Rx", "Ry"})
      columns.push_back(identifier(name) + "_" + q + "_" +
                        location_identifier(where));
    evaluators.emplace_back([body = &body, where](std::vector<double> &row) {
      const Tensor<1, 2> r = support_reaction(*body, where);
      row.push_back(r[0]);
      row.push_back(r[1]);
    });
  }



  void
  HistoryWriter::record(const unsigned int increment,
                        const double       time,
                        const unsigned int newton_iterations)
  {
    std::vector<double> row = {double(increment),
                               time,
                               double(newton_iterations)};
    for (const auto &evaluate : evaluators)
      evaluate(row);
    rows.push_back(row);
    if (std::chrono::steady_clock::now() - last_write >=
        std::chrono::seconds(1))
      write();
  }



  void
  HistoryWriter::write()
  {
    // (in a run on several processes, process 0 writes the file)
    if (!processes::writes_files())
      return;
    if (rows_written == rows.size() && rows_written > 0)
      return;
    AtomicFile file(filename);
    auto      &out = file.stream();
    for (unsigned int c = 0; c < columns.size(); ++c)
      out << (c ? "," : "") << columns[c];
    out << '\n';
    for (const auto &r : rows)
      {
        for (unsigned int c = 0; c < r.size(); ++c)
          out << (c ? "," : "") << r[c];
        out << '\n';
      }
    file.commit();
    rows_written = rows.size();
    last_write   = std::chrono::steady_clock::now();
  }
} // namespace glissade

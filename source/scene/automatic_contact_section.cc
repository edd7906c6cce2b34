// Scene/Contact bodies and the subsection Automatic contact: contact among
// several bodies without a pair written for every couple of them.
//
// Each couple of listed bodies gets the pairs a user would write by hand
// (ContactDescription, "<slave> on <master>"), with the section's settings,
// so that everything downstream (detection, the condensed problem, output,
// history) is the pairs' as they are: a scene with automatic contact gives
// the figures of the same pairs written out.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/description/scene_description.h>
#include <glissade/scene/section_reader.h>

#include <algorithm>
#include <string>
#include <vector>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * "left: outer, right: outer" as sides, each body once, known, with one
     * boundary. `where` names the entry.
     */
    std::vector<AutomaticContact::Side>
    read_sides(const std::string              &value,
               const std::vector<std::string> &body_names,
               const std::string              &where)
    {
      std::vector<AutomaticContact::Side> sides;
      for (const std::string &item : Utilities::split_string_list(value, ','))
        {
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            throw InputError(where,
                             "'" + item +
                               "' is not 'body: boundary' (the boundary of "
                               "the body that may touch the others, as "
                               "'left: outer')");
          AutomaticContact::Side side{text::trim(item.substr(0, colon)),
                                      text::trim(item.substr(colon + 1))};
          if (std::find(body_names.begin(), body_names.end(), side.body) ==
              body_names.end())
            throw InputError(where,
                             "there is no body '" + side.body +
                               "' (Scene/Bodies)");
          if (side.boundary.empty() ||
              side.boundary.find_first_of(", \t") != std::string::npos)
            throw InputError(where,
                             "body '" + side.body +
                               "': give one boundary name after ':' (a "
                               "master surface is one chain of faces)");
          for (const auto &earlier : sides)
            if (earlier.body == side.body)
              throw InputError(where,
                               "body '" + side.body + "' is listed twice");
          sides.push_back(side);
        }
      return sides;
    }
  } // namespace



  void
  AutomaticContact::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.declare_entry(
      "Contact bodies",
      "",
      Patterns::Anything(),
      "Contact found among these bodies without a pair written for each "
      "couple: 'body: boundary, body: boundary, ...', the boundary of each "
      "that may touch the others. Every couple gets the pairs a user would "
      "write, named '<slave> on <master>' (their history items and files "
      "take that name), with the settings of the subsection Automatic "
      "contact.");
    prm.leave_subsection();
    prm.enter_subsection("Automatic contact");
    prm.declare_entry("Passes",
                      "two",
                      Patterns::Selection("one|two"),
                      "two: each body of a couple is the slave on the other "
                      "in turn (two pairs, no body's side privileged); one: "
                      "the body listed first in Scene/Contact bodies is the "
                      "slave.");
    prm.declare_entry("Self-contact",
                      "false",
                      Patterns::Bool(),
                      "Each listed body's boundary against itself too: a "
                      "pair '<body> on itself' (node-to-segment), as a pair "
                      "whose Master body is its Slave body.");
    ContactDescription::declare_settings(prm);
    prm.leave_subsection();
  }



  std::vector<ContactDescription>
  AutomaticContact::parse_parameters(SectionReader                  &prm,
                                     const std::vector<std::string> &body_names,
                                     const std::vector<std::string> &declared)
  {
    const std::string where = prm.file() + ": Scene/Contact bodies";
    prm.enter_subsection("Scene");
    const std::string listed = prm.get("Contact bodies");
    prm.leave_subsection();
    if (text::trim(listed).empty())
      return {};
    AutomaticContact automatic;
    automatic.sides = read_sides(listed, body_names, where);

    prm.enter_subsection("Automatic contact");
    automatic.passes       = prm.get("Passes") == "one" ? 1 : 2;
    automatic.self_contact = prm.get_bool("Self-contact");
    if (automatic.sides.size() == 1 && !automatic.self_contact)
      throw InputError(where,
                       "lists one body ('" + automatic.sides[0].body +
                         "'): contact among bodies needs two or more, or "
                         "Automatic contact/Self-contact = true");
    ContactDescription settings;
    settings.entry  = prm.file() + ": Automatic contact";
    settings.master = ContactDescription::MasterKind::body;
    settings.parse_settings(prm);
    prm.leave_subsection();

    std::vector<ContactDescription> pairs;
    const auto add = [&](const Side &slave, const Side &master) {
      ContactDescription pair = settings;
      pair.name               = slave.body + " on " +
                  (master.body == slave.body ? "itself" : master.body);
      pair.entry =
        prm.file() + ": Automatic contact (pair '" + pair.name + "')";
      pair.slave_body      = slave.body;
      pair.slave_boundary  = slave.boundary;
      pair.master_body     = master.body;
      pair.master_boundary = master.boundary;
      if (std::find(declared.begin(), declared.end(), pair.name) !=
          declared.end())
        throw InputError(where,
                         "makes the pair '" + pair.name +
                           "', which Scene/Contact pairs names too: rename "
                           "that pair, or leave its bodies out of one list");
      pair.check_sides(body_names);
      pairs.push_back(pair);
    };
    const auto &sides = automatic.sides;
    for (std::size_t i = 0; i < sides.size(); ++i)
      for (std::size_t j = i + 1; j < sides.size(); ++j)
        {
          add(sides[i], sides[j]);
          if (automatic.passes == 2)
            add(sides[j], sides[i]);
        }
    if (automatic.self_contact)
      for (const Side &side : sides)
        add(side, side);
    return pairs;
  }
} // namespace glissade

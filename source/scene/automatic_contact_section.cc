// Scene/Contact bodies and the subsection Automatic contact: contact among
// several bodies without a pair written for every couple of them.
//
// Each couple of listed bodies gets the pairs a user would write by hand
// (ContactDescription, "<slave> on <master>"), with the section's settings,
// so that everything downstream (detection, the condensed problem, output,
// history) is the pairs' as they are: a scene with automatic contact gives
// the figures of the same pairs written out. The pairs of a couple are made
// by ContactProblem when its bodies come within reach (AutomaticContact::
// pair()); the ones of a body on itself, here.

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
          // Several boundaries of one body: 'ring: inner + outer', which
          // its pairs take as 'inner, outer'.
          std::string joined;
          for (const std::string &name :
               Utilities::split_string_list(side.boundary, '+'))
            {
              if (name.empty() ||
                  name.find_first_of(" \t") != std::string::npos)
                throw InputError(where,
                                 "body '" + side.body +
                                   "': give its boundary after ':', or "
                                   "several joined by '+' ('ring: inner + "
                                   "outer'), not '" +
                                   side.boundary + "'");
              joined += (joined.empty() ? "" : ", ") + name;
            }
          if (joined.empty())
            throw InputError(where,
                             "body '" + side.body +
                               "': give its boundary after ':'");
          side.boundary = joined;
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
      "that may touch the others (several of one body joined by '+': "
      "'ring: inner + outer'). Every couple gets the pairs a user would "
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
                      "pair '<body> on itself' (node-to-segment or mortar, "
                      "as Discretisation says), as a pair whose Master body "
                      "is its Slave body.");
    ContactDescription::declare_settings(prm);
    prm.leave_subsection();
  }



  ContactDescription
  AutomaticContact::pair(const unsigned int slave,
                         const unsigned int master) const
  {
    ContactDescription pair = settings;
    pair.name               = sides[slave].body + " on " +
                (master == slave ? "itself" : sides[master].body);
    pair.entry      = file + ": Automatic contact (pair '" + pair.name + "')";
    pair.slave_body = sides[slave].body;
    pair.slave_boundary  = sides[slave].boundary;
    pair.master_body     = sides[master].body;
    pair.master_boundary = sides[master].boundary;
    return pair;
  }



  std::vector<ContactDescription>
  AutomaticContact::parse_parameters(SectionReader                  &prm,
                                     const std::vector<std::string> &body_names,
                                     const std::vector<std::string> &declared,
                                     AutomaticContact               &automatic)
  {
    const std::string where = prm.file() + ": Scene/Contact bodies";
    prm.enter_subsection("Scene");
    const std::string listed = prm.get("Contact bodies");
    prm.leave_subsection();
    automatic = AutomaticContact();
    if (text::trim(listed).empty())
      return {};
    std::vector<Side> sides = read_sides(listed, body_names, where);

    prm.enter_subsection("Automatic contact");
    const unsigned int passes       = prm.get("Passes") == "one" ? 1 : 2;
    const bool         self_contact = prm.get_bool("Self-contact");
    if (sides.size() == 1 && !self_contact)
      throw InputError(where,
                       "lists one body ('" + sides[0].body +
                         "'): contact among bodies needs two or more, or "
                         "Automatic contact/Self-contact = true");
    ContactDescription settings;
    settings.entry  = prm.file() + ": Automatic contact";
    settings.master = ContactDescription::MasterKind::body;
    settings.parse_settings(prm);
    prm.leave_subsection();

    // A pair written by hand must not take a name a couple's pair will
    // have: "a on b" with a and b listed (read_sides checked the sides'
    // bodies, so the couples' pairs need no check of their own).
    for (const std::string &name : declared)
      for (const Side &slave : sides)
        if (name.rfind(slave.body + " on ", 0) == 0)
          {
            const std::string master = name.substr(slave.body.size() + 4);
            for (const Side &other : sides)
              if (other.body == master || (master == "itself" && self_contact))
                throw InputError(where,
                                 "makes the pair '" + name +
                                   "', which Scene/Contact pairs names too: "
                                   "rename that pair, or leave its bodies "
                                   "out of one list");
          }

    automatic.sides        = std::move(sides);
    automatic.passes       = passes;
    automatic.self_contact = self_contact;
    automatic.settings     = settings;
    automatic.file         = prm.file();
    std::vector<ContactDescription> made_now;
    if (self_contact)
      for (unsigned int s = 0; s < automatic.sides.size(); ++s)
        {
          made_now.push_back(automatic.pair(s, s));
          made_now.back().check_sides(body_names);
        }
    // One body listed with Self-contact has no couple.
    if (automatic.sides.size() < 2)
      automatic.sides.clear();
    return made_now;
  }
} // namespace glissade

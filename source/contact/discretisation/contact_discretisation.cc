#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/contact/discretisation/contact_discretisation.h>

#include <functional>

namespace glissade
{
  // Each discretisation's factory, defined in its own file.
  std::unique_ptr<ContactDiscretisation>
  create_node_to_segment(const ContactDiscretisation::Context &);
  std::unique_ptr<ContactDiscretisation>
  create_mortar(const ContactDiscretisation::Context &);

  namespace
  {
    struct DiscretisationEntry
    {
      std::string name;
      std::string sentence;
      std::function<std::unique_ptr<ContactDiscretisation>(
        const ContactDiscretisation::Context &)>
        create;
    };

    const std::vector<DiscretisationEntry> &
    discretisations()
    {
      // One line per discretisation.
      static const std::vector<DiscretisationEntry> list = {
        {"node-to-segment",
         "each slave node against its closest point on the master surface "
         "(the paper's method; every master surface and obstacle)",
         create_node_to_segment},
        {"mortar",
         "segment-to-segment mortar: each slave node's gap is the integral "
         "of the gap against its dual shape function (a Q1 slave) or its "
         "control point's rational function (a NURBS slave), segment by "
         "segment (passes the contact patch test on non-matching meshes; "
         "a faceted, B-spline, Hermite or NURBS master, or a rigid "
         "obstacle)",
         create_mortar}};
      return list;
    }
  } // namespace



  std::unique_ptr<ContactDiscretisation>
  ContactDiscretisation::create(const std::string &name, const Context &context)
  {
    for (const auto &entry : discretisations())
      if (entry.name == name)
        return entry.create(context);
    throw InputError("Discretisation",
                     "unknown contact discretisation '" + name + "'");
  }



  std::string
  ContactDiscretisation::names_as_pattern()
  {
    std::vector<std::string> names;
    for (const auto &entry : discretisations())
      names.push_back(entry.name);
    return text::joined(names, "|");
  }



  std::string
  ContactDiscretisation::documentation()
  {
    std::vector<std::string> sentences;
    for (const auto &entry : discretisations())
      sentences.push_back(entry.name + ": " + entry.sentence);
    return text::joined(sentences, "; ") + ".";
  }
} // namespace glissade

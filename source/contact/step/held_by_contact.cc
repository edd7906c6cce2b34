#include <glissade/base/input_error.h>
#include <glissade/contact/step/held_by_contact.h>

#include <sstream>

namespace glissade
{
  using namespace dealii;

  void
  check_free_motions_are_held(
    const std::vector<std::unique_ptr<Body>>        &bodies,
    const std::vector<std::unique_ptr<ContactPair>> &pairs,
    const std::string                               &source)
  {
    // The unknowns: the amplitudes of every body's free motions.
    std::vector<unsigned int> first(bodies.size() + 1, 0);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      first[b + 1] = first[b] + bodies[b]->system().free_rigid_motions().size();
    const unsigned int n = first.back();
    if (n == 0)
      return;
    const auto index = [&](const Body *body) {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (bodies[b].get() == body)
          return b;
      return numbers::invalid_unsigned_int;
    };

    // One row per direction a contact holds: d . (v_slave - v_master) at
    // the slave node, for d the normal, and the tangent with friction
    // (ContactPair::initial_contacts: the slave boundary's frame).
    std::vector<std::vector<double>> rows;
    for (const auto &pair : pairs)
      for (const auto &contact : pair->initial_contacts())
        {
          std::vector<Tensor<1, 2>> directions = {contact.normal};
          if (pair->settings().friction > 0.)
            directions.push_back(contact.tangent);
          for (const auto &d : directions)
            {
              std::vector<double> row(n, 0.);
              for (const auto &[body, sign] :
                   {std::make_pair<const Body *, double>(&pair->slave(), 1.),
                    std::make_pair<const Body *, double>(pair->master(), -1.)})
                if (body != nullptr)
                  {
                    const unsigned int b = index(body);
                    const auto &motions  = body->system().free_rigid_motions();
                    for (unsigned int j = 0; j < motions.size(); ++j)
                      row[first[b] + j] +=
                        sign * (d * motions[j].at(contact.position));
                  }
              rows.push_back(row);
            }
        }

    const auto free = null_space(rows, n);
    if (free.empty())
      return;

    // The first free motion, body by body.
    const std::vector<double> &x = free[0];
    std::ostringstream         motion;
    std::string                first_body;
    unsigned int               n_bodies = 0;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        double size = 0.;
        for (unsigned int j = first[b]; j < first[b + 1]; ++j)
          size += x[j] * x[j];
        if (!(size > 1e-16))
          continue;
        const auto &motions = bodies[b]->system().free_rigid_motions();
        const std::vector<double> local(x.begin() + first[b],
                                        x.begin() + first[b + 1]);
        motion << (n_bodies > 0 ? "; with it, body '" : "body '")
               << bodies[b]->name()
               << "': " << combine(motions, local).describe(bodies[b]->size());
        if (n_bodies++ == 0)
          first_body = bodies[b]->name();
      }
    std::vector<std::string> names;
    for (const auto &pair : pairs)
      names.push_back(
        "'" + pair->name() + "'" +
        (pair->settings().friction > 0. ? "" : " (frictionless)"));
    std::ostringstream message;
    message << "a rigid-body motion is free (" << motion.str()
            << "). Its supports do not hold it, and ";
    if (names.empty())
      message << "there is no contact pair. ";
    else
      {
        message << "neither do the contact pairs ";
        for (unsigned int p = 0; p < names.size(); ++p)
          message << (p > 0 ? ", " : "") << names[p];
        message << " with their slave nodes within the alert distance at "
                   "t = 0 (a frictionless contact holds only the normal "
                   "direction). ";
      }
    message << "Add a support that holds it (Fixed = point(x, y): x, say), "
               "friction, or a larger Alert distance if the contact is "
               "farther";
    if (free.size() > 1)
      message << " (" << free.size() << " independent motions are free)";
    throw InputError(source + ": Body " + first_body + "/Boundary conditions",
                     message.str());
  }
} // namespace glissade

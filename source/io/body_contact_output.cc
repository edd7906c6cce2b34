// A body's contact state over all its pairs as a slave
// (include/glissade/io/body_contact_output.h).

#include <glissade/io/atomic_file.h>
#include <glissade/io/body_contact_output.h>
#include <glissade/io/contact_line_vtu.h>
#include <glissade/io/contact_surface_output.h>
#include <glissade/io/pvd_index.h>

#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  BodyContactOutput::BodyContactOutput(const Body &body)
    : body(body)
  {}



  void
  BodyContactOutput::write(
    const std::string                               &directory,
    const unsigned int                               increment,
    const double                                     t,
    const std::vector<std::unique_ptr<ContactPair>> &pairs,
    std::vector<std::pair<double, std::string>>     &records) const
  {
    // Each slave vertex of the body once, over all its pairs.
    struct Node
    {
      Point<2>     reference, current;
      bool         active = false, projected = false;
      double       gap = std::numeric_limits<double>::infinity();
      double       r_n = 0., r_t = 0., slip = 0., area = 0.;
      Tensor<1, 2> force;
      int          status = 0;
      std::string  carried_by;
      double       largest_r_n = 0.;
    };
    std::vector<Node>                             nodes;
    std::map<std::array<double, 2>, unsigned int> of_place;
    std::vector<std::array<unsigned int, 2>>      faces;
    std::set<std::array<unsigned int, 2>>         face_seen;
    for (const auto &pair : pairs)
      {
        if (&pair->slave() != &body)
          continue;
        const auto               &pair_nodes = pair->nodes();
        const std::vector<double> area       = pair->tributary_areas();
        std::vector<unsigned int> index(pair_nodes.size());
        for (unsigned int k = 0; k < pair_nodes.size(); ++k)
          {
            const ContactNode &p = pair_nodes[k];
            // (a node shared by two pairs is one; a NURBS body's slave
            // points, between its nodes, are keyed by their place)
            const auto [at, added] = of_place.emplace(
              p.vertex != ContactNode::no_vertex ?
                std::array<double, 2>{{-1., double(p.vertex)}} :
                std::array<double, 2>{
                  {p.reference_position[0], p.reference_position[1]}},
              nodes.size());
            if (added)
              {
                Node node;
                node.reference = p.reference_position;
                node.current =
                  p.reference_position + p.displacement(body.displacement());
                nodes.push_back(node);
              }
            index[k]   = at->second;
            Node &node = nodes[at->second];
            node.area  = std::max(node.area, area[k]);
            if (p.projected)
              {
                node.projected = true;
                node.gap       = std::min(node.gap, p.gap);
              }
            if (!p.active)
              continue;
            const std::array<double, 2> r = pair->reported_reaction(p);
            node.active                   = true;
            node.r_n += r[1];
            node.r_t += r[0];
            node.force += pair->reported_force(p);
            if (node.carried_by.empty() || r[1] > node.largest_r_n)
              {
                node.largest_r_n = r[1];
                node.carried_by  = pair->name();
                node.status      = ContactSurfaceOutput::status_of(p).second;
                node.slip        = p.linearization.slip;
              }
          }
        for (const auto &[a, b] : pair->slave_faces())
          {
            std::array<unsigned int, 2> face = {{index[a], index[b]}};
            std::array<unsigned int, 2> key  = face;
            if (key[0] > key[1])
              std::swap(key[0], key[1]);
            if (face_seen.insert(key).second)
              faces.push_back(face);
          }
      }
    if (nodes.empty())
      return;

    std::ostringstream stem;
    stem << "contact-of-" << body.name() << "-" << std::setw(5)
         << std::setfill('0') << increment;
    const char *names[]  = {"inactive", "open", "stick", "slip"};
    const auto  per_area = [](const Node &node, const double force) {
      return node.area > 0. ? force / node.area : 0.;
    };

    AtomicFile table(directory + "/" + stem.str() + ".csv");
    table.stream() << std::setprecision(16)
                   << "X,Y,x,y,active,gap,r_t,r_n,fx,fy,status,pressure,"
                      "shear,slip,pair\n";
    for (const Node &node : nodes)
      {
        table.stream() << node.reference[0] << ',' << node.reference[1] << ','
                       << node.current[0] << ',' << node.current[1] << ','
                       << node.active << ',';
        // (no gap where no pair projects the node)
        if (node.projected)
          table.stream() << node.gap;
        table.stream() << ',' << node.r_t << ',' << node.r_n << ','
                       << node.force[0] << ',' << node.force[1] << ','
                       << names[node.status] << ',' << per_area(node, node.r_n)
                       << ',' << per_area(node, node.r_t) << ',' << node.slip
                       << ',' << node.carried_by << '\n';
      }
    table.commit();

    ContactLineFields fields;
    fields.faces = faces;
    for (const Node &node : nodes)
      {
        fields.x.push_back(node.current);
        fields.pressure.push_back(per_area(node, node.r_n));
        fields.shear.push_back(per_area(node, node.r_t));
        fields.r_n.push_back(node.r_n);
        fields.r_t.push_back(node.r_t);
        fields.gap.push_back(node.projected ? node.gap : 0.);
        fields.slip.push_back(node.slip);
        fields.status.push_back(node.status);
        fields.force.push_back(node.force);
      }
    write_contact_line_vtu(directory + "/" + stem.str() + ".vtu", fields);
    records.emplace_back(t, stem.str() + ".vtu");
    write_pvd_index(directory + "/contact-of-" + body.name() + ".pvd", records);
  }
} // namespace glissade

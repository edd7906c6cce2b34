#include <glissade/io/atomic_file.h>
#include <glissade/io/contact_line_vtu.h>
#include <glissade/io/contact_surface_output.h>
#include <glissade/io/pvd_index.h>

#include <iomanip>
#include <map>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  std::pair<const char *, int>
  ContactSurfaceOutput::status_of(const ContactNode &node)
  {
    if (!node.active)
      return {"inactive", 0};
    switch (node.status)
      {
        case BiPotentialSolver::NodeStatus::open:
          return {"open", 1};
        case BiPotentialSolver::NodeStatus::stick:
          return {"stick", 2};
        default:
          return {"slip", 3};
      }
  }



  ContactSurfaceOutput::ContactSurfaceOutput(const ContactPair &pair)
    : pair(pair)
    , faces(pair.slave_faces())
  {}



  void
  ContactSurfaceOutput::write(
    const std::string                           &directory,
    const unsigned int                           increment,
    const double                                 t,
    std::vector<std::pair<double, std::string>> &records) const
  {
    const auto        &nodes = pair.nodes();
    const Body        &slave = pair.slave();
    const unsigned int n     = nodes.size();

    // Current positions, and the tributary length: half of each adjacent
    // slave face; the tributary area (ContactPair::tributary_areas()).
    std::vector<Point<2>> x(n);
    for (unsigned int k = 0; k < n; ++k)
      x[k] = nodes[k].reference_position +
             nodes[k].displacement(slave.displacement());
    std::vector<double> length(n, 0.);
    for (const auto &[a, b] : faces)
      {
        const double face = x[a].distance(x[b]);
        length[a] += 0.5 * face;
        length[b] += 0.5 * face;
      }
    const std::vector<double> area = pair.tributary_areas();
    const auto per_area = [&](const unsigned int k, const double force) {
      return area[k] > 0. ? force / area[k] : 0.;
    };

    std::ostringstream stem;
    stem << "contact-" << pair.name() << "-" << std::setw(5)
         << std::setfill('0') << increment;

    // The table.
    AtomicFile table(directory + "/" + stem.str() + ".csv");
    table.stream() << std::setprecision(16)
                   << "X,Y,x,y,active,gap,r_t,r_n,fx,fy,status,pressure,"
                      "shear,slip,tributary_length\n";
    for (unsigned int k = 0; k < n; ++k)
      {
        const ContactNode &node = nodes[k];
        const Tensor<1, 2> f =
          node.active ? pair.reported_force(node) : Tensor<1, 2>();
        const std::array<double, 2> r = pair.reported_reaction(node);
        table.stream() << node.reference_position[0] << ','
                       << node.reference_position[1] << ',' << x[k][0] << ','
                       << x[k][1] << ',' << node.active << ',';
        // A node with no counterpart on the master has no gap: the field
        // stays empty rather than repeating its last projection's.
        if (node.projected)
          table.stream() << node.gap;
        table.stream() << ',' << r[0] << ',' << r[1] << ',' << f[0] << ','
                       << f[1] << ',' << status_of(node).first << ','
                       << per_area(k, r[1]) << ',' << per_area(k, r[0]) << ','
                       << (node.active ? node.linearization.slip : 0.) << ','
                       << length[k] << '\n';
      }
    table.commit();

    // The line mesh.
    ContactLineFields fields;
    fields.x     = x;
    fields.faces = faces;
    for (unsigned int k = 0; k < n; ++k)
      {
        const ContactNode          &node = nodes[k];
        const std::array<double, 2> r    = pair.reported_reaction(node);
        fields.pressure.push_back(per_area(k, r[1]));
        fields.shear.push_back(per_area(k, r[0]));
        fields.r_n.push_back(r[1]);
        fields.r_t.push_back(r[0]);
        // No gap without a counterpart: 0 there, and status says why.
        fields.gap.push_back(node.projected ? node.gap : 0.);
        fields.slip.push_back(node.active ? node.linearization.slip : 0.);
        fields.status.push_back(status_of(node).second);
        fields.force.push_back(node.active ? pair.reported_force(node) :
                                             Tensor<1, 2>());
      }
    write_contact_line_vtu(directory + "/" + stem.str() + ".vtu", fields);

    // The PVD of every VTU written so far.
    records.emplace_back(t, stem.str() + ".vtu");
    write_pvd_index(directory + "/contact-" + pair.name() + ".pvd", records);
  }
} // namespace glissade

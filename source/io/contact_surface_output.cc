#include <glissade/io/atomic_file.h>
#include <glissade/io/contact_surface_output.h>
#include <glissade/io/pvd_index.h>

#include <iomanip>
#include <map>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** What each node's status is called in the table and coded in the VTU. */
    std::pair<const char *, int>
    status_of(const ContactNode &node)
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
  } // namespace



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
             Tensor<1, 2>({slave.displacement()(nodes[k].dofs[0]),
                           slave.displacement()(nodes[k].dofs[1])});
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

    // The line mesh (ASCII VTU: a boundary is small).
    AtomicFile vtu(directory + "/" + stem.str() + ".vtu");
    auto      &out = vtu.stream();
    out << std::setprecision(16)
        << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\""
        << faces.size() << "\">\n<Points>\n<DataArray type=\"Float64\" "
        << "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int k = 0; k < n; ++k)
      out << x[k][0] << ' ' << x[k][1] << " 0\n";
    out
      << "</DataArray>\n</Points>\n<Cells>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto &[a, b] : faces)
      out << a << ' ' << b << '\n';
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
           "format=\"ascii\">\n";
    for (unsigned int i = 1; i <= faces.size(); ++i)
      out << 2 * i << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">\n";
    for (unsigned int i = 0; i < faces.size(); ++i)
      out << "3\n";
    out << "</DataArray>\n</Cells>\n<PointData Scalars=\"pressure\" "
           "Vectors=\"force\">\n";
    const auto scalar = [&](const char *name, const auto &value) {
      out << "<DataArray type=\"Float64\" Name=\"" << name
          << "\" format=\"ascii\">\n";
      for (unsigned int k = 0; k < n; ++k)
        out << value(k) << '\n';
      out << "</DataArray>\n";
    };
    const auto r = [&](const unsigned int k, const unsigned int c) {
      return pair.reported_reaction(nodes[k])[c];
    };
    scalar("pressure", [&](unsigned int k) { return per_area(k, r(k, 1)); });
    scalar("shear", [&](unsigned int k) { return per_area(k, r(k, 0)); });
    scalar("r_n", [&](unsigned int k) { return r(k, 1); });
    scalar("r_t", [&](unsigned int k) { return r(k, 0); });
    // No gap without a counterpart: 0 there, and status says why.
    scalar("gap", [&](unsigned int k) {
      return nodes[k].projected ? nodes[k].gap : 0.;
    });
    scalar("slip", [&](unsigned int k) {
      return nodes[k].active ? nodes[k].linearization.slip : 0.;
    });
    scalar("status",
           [&](unsigned int k) { return status_of(nodes[k]).second; });
    out
      << "<DataArray type=\"Float64\" Name=\"force\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
    for (unsigned int k = 0; k < n; ++k)
      {
        const Tensor<1, 2> f =
          nodes[k].active ? pair.reported_force(nodes[k]) : Tensor<1, 2>();
        out << f[0] << ' ' << f[1] << " 0\n";
      }
    out << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n"
           "</VTKFile>\n";
    vtu.commit();

    // The PVD of every VTU written so far.
    records.emplace_back(t, stem.str() + ".vtu");
    write_pvd_index(directory + "/contact-" + pair.name() + ".pvd", records);
  }
} // namespace glissade

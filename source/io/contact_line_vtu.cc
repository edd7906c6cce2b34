// The contact fields of a slave boundary as a VTU line mesh
// (include/glissade/io/contact_line_vtu.h).

#include <glissade/io/atomic_file.h>
#include <glissade/io/contact_line_vtu.h>

#include <iomanip>

namespace glissade
{
  using namespace dealii;

  void
  write_contact_line_vtu(const std::string       &path,
                         const ContactLineFields &fields)
  {
    const std::size_t n = fields.x.size();
    AtomicFile        vtu(path);
    auto             &out = vtu.stream();
    out << std::setprecision(16)
        << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\""
        << fields.faces.size() << "\">\n<Points>\n<DataArray type=\"Float64\" "
        << "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const Point<2> &p : fields.x)
      out << p[0] << ' ' << p[1] << " 0\n";
    out
      << "</DataArray>\n</Points>\n<Cells>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto &[a, b] : fields.faces)
      out << a << ' ' << b << '\n';
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
           "format=\"ascii\">\n";
    for (std::size_t i = 1; i <= fields.faces.size(); ++i)
      out << 2 * i << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">\n";
    for (std::size_t i = 0; i < fields.faces.size(); ++i)
      out << "3\n";
    out << "</DataArray>\n</Cells>\n<PointData Scalars=\"pressure\" "
           "Vectors=\"force\">\n";
    const auto scalar = [&](const char *name, const std::vector<double> &v) {
      out << "<DataArray type=\"Float64\" Name=\"" << name
          << "\" format=\"ascii\">\n";
      for (const double value : v)
        out << value << '\n';
      out << "</DataArray>\n";
    };
    scalar("pressure", fields.pressure);
    scalar("shear", fields.shear);
    scalar("r_n", fields.r_n);
    scalar("r_t", fields.r_t);
    scalar("gap", fields.gap);
    scalar("slip", fields.slip);
    scalar("status", fields.status);
    out
      << "<DataArray type=\"Float64\" Name=\"force\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
    for (const Tensor<1, 2> &f : fields.force)
      out << f[0] << ' ' << f[1] << " 0\n";
    out << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n"
           "</VTKFile>\n";
    vtu.commit();
  }
} // namespace glissade

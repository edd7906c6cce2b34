#include <glissade/io/atomic_file.h>
#include <glissade/io/pvd_index.h>

#include <iomanip>

namespace glissade
{
  void
  write_pvd_index(const std::string                                 &file,
                  const std::vector<std::pair<double, std::string>> &records)
  {
    AtomicFile pvd(file);
    pvd.stream() << "<?xml version=\"1.0\"?>\n"
                 << "<VTKFile type=\"Collection\" version=\"0.1\" "
                    "ByteOrder=\"LittleEndian\">\n  <Collection>\n"
                 << std::setprecision(17);
    for (const auto &[time, vtu] : records)
      pvd.stream() << "    <DataSet timestep=\"" << time
                   << "\" group=\"\" part=\"0\" file=\"" << vtu << "\"/>\n";
    pvd.stream() << "  </Collection>\n</VTKFile>\n";
    pvd.commit();
  }
} // namespace glissade

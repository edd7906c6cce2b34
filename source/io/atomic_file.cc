#include <glissade/io/atomic_file.h>

#include <cstdio>
#include <stdexcept>

namespace glissade
{
  AtomicFile::AtomicFile(const std::string &filename)
    : filename(filename)
    , temporary(filename + ".tmp")
    , out(temporary)
  {
    if (!out)
      throw std::runtime_error("cannot write '" + temporary +
                               "' (does the output directory exist and is it "
                               "writable?)");
    out.precision(16);
  }



  AtomicFile::~AtomicFile()
  {
    if (!committed)
      {
        out.close();
        std::remove(temporary.c_str());
      }
  }



  std::string
  AtomicFile::failure_message() const
  {
    return "writing '" + temporary +
           "' failed (is the disk full, or the output directory gone?); the "
           "files written before are complete";
  }



  void
  AtomicFile::commit()
  {
    out.flush();
    if (!out)
      throw std::runtime_error(failure_message());
    out.close();
    if (std::rename(temporary.c_str(), filename.c_str()) != 0)
      throw std::runtime_error("cannot rename '" + temporary + "' to '" +
                               filename + "'");
    committed = true;
  }
} // namespace glissade

#pragma once

#include <fstream>
#include <stdexcept>
#include <string>

namespace glissade
{
  /**
   * An output file that appears complete or not at all: it is written to
   * "<name>.tmp" and renamed on commit(), so an interrupted run never leaves
   * a half-written VTU, PVD or CSV behind.
   */
  class AtomicFile
  {
  public:
    explicit AtomicFile(const std::string &filename);
    ~AtomicFile();

    std::ofstream &
    stream()
    {
      return out;
    }

    /** Flushes, checks the stream and renames into place; throws on error. */
    void
    commit();

    /**
     * Runs `write(stream())` and commits. Whatever the writer throws when
     * the stream fails (deal.II's ExcIO with its stack trace, boost's
     * archive exceptions, std::bad_cast) becomes one plain message naming
     * the file: a full disk must read as a full disk.
     */
    template <typename Writer>
    void
    write_and_commit(const Writer &write)
    {
      try
        {
          write(out);
        }
      catch (...)
        {
          throw std::runtime_error(failure_message());
        }
      commit();
    }

  private:
    std::string
    failure_message() const;

    std::string   filename;
    std::string   temporary;
    std::ofstream out;
    bool          committed = false;
  };
} // namespace glissade

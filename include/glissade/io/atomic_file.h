#pragma once

#include <fstream>
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

  private:
    std::string   filename;
    std::string   temporary;
    std::ofstream out;
    bool          committed = false;
  };
} // namespace glissade

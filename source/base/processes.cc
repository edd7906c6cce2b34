// The processes of a run (include/glissade/base/processes.h).

#include <deal.II/base/mpi.h>

#include <glissade/base/processes.h>

#include <algorithm>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace glissade
{
  namespace processes
  {
    unsigned int
    count()
    {
      return dealii::Utilities::MPI::job_supports_mpi() ?
               dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) :
               1;
    }



    unsigned int
    rank()
    {
      return dealii::Utilities::MPI::job_supports_mpi() ?
               dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) :
               0;
    }



    MPI_Comm
    communicator()
    {
      return dealii::Utilities::MPI::job_supports_mpi() ? MPI_COMM_WORLD :
                                                          MPI_COMM_SELF;
    }



    std::string
    mesh_held_here(const bool mesh_is_distributed, const unsigned int n_cells)
    {
      if (!shared_out())
        return "";
      return mesh_is_distributed ?
               ", mesh shared out (" + std::to_string(n_cells) +
                 " cells held here)" :
               ", whole mesh on every process";
    }



    VtuFiles
    vtu_files(const std::string &stem)
    {
      VtuFiles files;
      if (!shared_out())
        {
          files.own_piece = stem + ".vtu";
          return files;
        }
      for (unsigned int p = 0; p < count(); ++p)
        {
          std::ostringstream name;
          name << stem << "." << std::setw(4) << std::setfill('0') << p
               << ".vtu";
          files.pieces.push_back(name.str());
        }
      files.own_piece = files.pieces[rank()];
      files.record    = stem + ".pvtu";
      return files;
    }



    void
    sum(double *values, const std::size_t n)
    {
      if (count() == 1 || n == 0)
        return;
      // (in chunks: MPI counts are int)
      constexpr std::size_t chunk = std::size_t(1) << 28;
      for (std::size_t start = 0; start < n; start += chunk)
        {
          const int size = std::min(chunk, n - start);
          if (rank() == 0)
            MPI_Reduce(MPI_IN_PLACE,
                       values + start,
                       size,
                       MPI_DOUBLE,
                       MPI_SUM,
                       0,
                       communicator());
          else
            MPI_Reduce(values + start,
                       nullptr,
                       size,
                       MPI_DOUBLE,
                       MPI_SUM,
                       0,
                       communicator());
          MPI_Bcast(values + start, size, MPI_DOUBLE, 0, communicator());
        }
    }



    std::pair<std::size_t, std::size_t>
    share(const std::size_t n)
    {
      const std::size_t p = rank(), P = count();
      return {n * p / P, n * (p + 1) / P};
    }



    void
    gather_columns(double           *matrix,
                   const std::size_t rows,
                   const std::size_t columns)
    {
      if (count() == 1 || rows == 0 || columns == 0)
        return;
      // Counted in columns (an MPI type of one column): a count of doubles
      // would overflow MPI's int at some 2^31 entries.
      MPI_Datatype column;
      MPI_Type_contiguous(int(rows), MPI_DOUBLE, &column);
      MPI_Type_commit(&column);
      std::vector<int> counts(count()), offsets(count());
      for (unsigned int p = 0; p < count(); ++p)
        {
          offsets[p] = columns * p / count();
          counts[p]  = columns * (p + 1) / count() - offsets[p];
        }
      MPI_Allgatherv(MPI_IN_PLACE,
                     0,
                     MPI_DATATYPE_NULL,
                     matrix,
                     counts.data(),
                     offsets.data(),
                     column,
                     communicator());
      MPI_Type_free(&column);
    }



    std::string
    first_message(const std::string &message)
    {
      if (count() == 1)
        return message;
      int first = message.empty() ? int(count()) : int(rank());
      MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, communicator());
      if (first == int(count()))
        return std::string();
      int length = message.size();
      MPI_Bcast(&length, 1, MPI_INT, first, communicator());
      std::string text = message;
      text.resize(length);
      MPI_Bcast(text.data(), length, MPI_CHAR, first, communicator());
      return text;
    }



    int
    maximum(const int value)
    {
      if (count() == 1)
        return value;
      int result = value;
      MPI_Allreduce(MPI_IN_PLACE, &result, 1, MPI_INT, MPI_MAX, communicator());
      return result;
    }



    std::vector<unsigned long>
    union_of(const std::vector<unsigned long> &items)
    {
      std::vector<unsigned long> all = items;
      if (count() > 1)
        {
          std::vector<int> counts(count()), offsets(count(), 0);
          const int        here = items.size();
          MPI_Allgather(
            &here, 1, MPI_INT, counts.data(), 1, MPI_INT, communicator());
          for (unsigned int p = 1; p < count(); ++p)
            offsets[p] = offsets[p - 1] + counts[p - 1];
          all.resize(offsets.back() + counts.back());
          MPI_Allgatherv(items.data(),
                         here,
                         MPI_UNSIGNED_LONG,
                         all.data(),
                         counts.data(),
                         offsets.data(),
                         MPI_UNSIGNED_LONG,
                         communicator());
        }
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
      return all;
    }



    void
    check_identical(const double value, const char *what)
    {
      if (count() == 1)
        return;
      // Process 0's bits, compared everywhere; the verdict gathered, so
      // that every process throws (or none does).
      double reference = value;
      MPI_Bcast(&reference, 1, MPI_DOUBLE, 0, communicator());
      int differs = std::memcmp(&reference, &value, sizeof(double)) != 0;
      MPI_Allreduce(
        MPI_IN_PLACE, &differs, 1, MPI_INT, MPI_MAX, communicator());
      if (differs != 0)
        throw std::runtime_error(
          std::string("the processes of this run no longer agree on ") + what +
          " (a computation that gives other bits on another process: "
          "please report it, with the scene)");
    }
  } // namespace processes
} // namespace glissade

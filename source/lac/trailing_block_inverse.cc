// The block of A^-1 on the unknowns eliminated last
// (include/glissade/lac/trailing_block_inverse.h).

#include <glissade/base/timing_sections.h>
#include <glissade/lac/lapack.h>
#include <glissade/lac/trailing_block_inverse.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

namespace glissade
{
  void
  TrailingBlockInverse::ask_for_inverse_columns(
    const std::vector<long> &positions)
  {
    if (n_last == 0)
      return;
    const auto start = std::chrono::steady_clock::now();
    // The columns wanted: those asked for and those already formed.
    std::vector<long> wanted;
    if (column_of.size() != std::size_t(n_last))
      column_of.assign(n_last, -1);
    for (long j = 0; j < n_last; ++j)
      if (column_of[j] >= 0)
        wanted.push_back(j);
    const std::size_t formed = wanted.size();
    for (const long j : positions)
      if (j >= 0 && column_of[j] < 0)
        {
          column_of[j] = -2; // marked, so that a repeated j is added once
          wanted.push_back(j);
        }
    const bool needed = wanted.size() != formed;
    request_pending   = on_any_process(needed);
    if (!request_pending)
      return; // every column is there already
    // (a process that needs no new column asks for none and keeps those
    // it has; one that does lets go of the old ones, formed again with
    // the new: both at once would double the room they take)
    if (needed)
      {
        std::sort(wanted.begin(), wanted.end());
        std::vector<double>().swap(inverse_block);
        std::fill(column_of.begin(), column_of.end(), -1);
      }
    else
      wanted.clear();
    requested = wanted;
    take_request(requested);
    inverse_seconds += timing::seconds_since(start);
  }



  void
  TrailingBlockInverse::form_asked_inverse_columns()
  {
    if (!request_pending)
      return;
    const auto start = std::chrono::steady_clock::now();
    form_requested_columns();
    inverse_seconds += timing::seconds_since(start);
  }



  void
  TrailingBlockInverse::receive_inverse_columns()
  {
    if (!request_pending)
      return;
    const auto start           = std::chrono::steady_clock::now();
    request_pending            = false;
    const bool          needed = !requested.empty();
    std::vector<double> columns;
    hand_over_columns(requested, columns);
    if (needed)
      {
        inverse_block.swap(columns);
        for (std::size_t c = 0; c < requested.size(); ++c)
          column_of[requested[c]] = c;
      }
    std::vector<long>().swap(requested);
    inverse_seconds += timing::seconds_since(start);
  }



  void
  TrailingBlockInverse::columns_of_inverse(std::vector<double> &factor,
                                           const long           m,
                                           std::vector<long>   &wanted,
                                           std::vector<double> &columns)
  {
    const int size = m;
    int       info = 0;
    if (wanted.empty())
      columns.clear();
    else if (3 * long(wanted.size()) >= m)
      {
        // (L_S L_S^T)^-1 in the lower triangle, then mirrored, in place:
        // every column is then there.
        dpotri_("L", &size, factor.data(), &size, &info);
        for (long j = 0; j < m && info == 0; ++j)
          for (long i = j + 1; i < m; ++i)
            factor[j + i * m] = factor[i + j * m];
        columns.swap(factor);
        wanted.resize(m);
        for (long j = 0; j < m; ++j)
          wanted[j] = j;
      }
    else
      {
        // C e_j = (L_S L_S^T)^-1 e_j for each wanted column j.
        const int k = wanted.size();
        columns.assign(std::size_t(m) * k, 0.);
        for (int c = 0; c < k; ++c)
          columns[wanted[c] + std::size_t(c) * m] = 1.;
        dpotrs_(
          "L", &size, &k, factor.data(), &size, columns.data(), &size, &info);
      }
    if (info != 0)
      throw std::runtime_error("LAPACK dpotri/dpotrs failed with info " +
                               std::to_string(info));
  }
} // namespace glissade

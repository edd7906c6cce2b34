// The block of A^-1 on the unknowns eliminated last
// (include/glissade/lac/trailing_block_inverse.h).

#include <glissade/lac/lapack.h>
#include <glissade/lac/trailing_block_inverse.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

namespace glissade
{
  void
  TrailingBlockInverse::compute_inverse_columns(
    const std::vector<long> &positions)
  {
    if (n_last == 0)
      return;
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
    if (!on_any_process(needed))
      return; // every column is there already
    share_trailing_factor();
    if (!needed)
      return;
    std::sort(wanted.begin(), wanted.end());
    const bool              whole_block = 3 * long(wanted.size()) >= n_last;
    const std::vector<long> asked       = wanted;
    if (whole_block)
      {
        wanted.resize(n_last);
        for (long j = 0; j < n_last; ++j)
          wanted[j] = j;
      }

    const auto          start = std::chrono::steady_clock::now();
    std::vector<double> factor;
    trailing_factor(factor, whole_block);
    const int m    = n_last;
    int       info = 0;
    if (whole_block)
      {
        // (L_S L_S^T)^-1 in the lower triangle, then mirrored.
        dpotri_("L", &m, factor.data(), &m, &info);
        for (long j = 0; j < n_last && info == 0; ++j)
          for (long i = j + 1; i < n_last; ++i)
            factor[j + i * n_last] = factor[i + j * n_last];
        inverse_block.swap(factor);
        if (keep_only_asked_columns && info == 0 &&
            asked.size() < std::size_t(n_last))
          {
            // (the columns asked for, copied out of the whole block)
            std::vector<double> kept(std::size_t(n_last) * asked.size());
            for (std::size_t c = 0; c < asked.size(); ++c)
              std::copy_n(&inverse_block[std::size_t(asked[c]) * n_last],
                          n_last,
                          &kept[c * n_last]);
            inverse_block.swap(kept);
            wanted = asked;
          }
      }
    else
      {
        // C e_j = (L_S L_S^T)^-1 e_j for each wanted column j.
        const int k = wanted.size();
        inverse_block.assign(std::size_t(n_last) * k, 0.);
        for (int c = 0; c < k; ++c)
          inverse_block[wanted[c] + std::size_t(c) * n_last] = 1.;
        dpotrs_(
          "L", &m, &k, factor.data(), &m, inverse_block.data(), &m, &info);
      }
    if (info != 0)
      throw std::runtime_error("LAPACK dpotri/dpotrs failed with info " +
                               std::to_string(info));
    std::fill(column_of.begin(), column_of.end(), -1);
    for (std::size_t c = 0; c < wanted.size(); ++c)
      column_of[wanted[c]] = c;
    inverse_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
  }
} // namespace glissade

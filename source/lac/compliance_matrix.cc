#include <glissade/lac/compliance_matrix.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

namespace glissade
{
  ComplianceMatrix::ComplianceMatrix(const unsigned int n_nodes,
                                     const Storage      storage)
  {
    reinit(n_nodes, storage);
  }

  void
  ComplianceMatrix::reinit(const unsigned int n_nodes, const Storage storage)
  {
    n_contact_nodes = n_nodes;
    storage_type    = storage;

    dense_values.clear();
    column_rows.clear();
    column_blocks.clear();
    // Release the memory, not only the contents: a 2000-node dense matrix
    // is 128 MB and should not survive a switch to block-sparse storage.
    dense_values.shrink_to_fit();
    column_rows.shrink_to_fit();
    column_blocks.shrink_to_fit();

    if (storage == Storage::dense)
      dense_values.assign(4 * std::size_t(n_nodes) * n_nodes, 0.);
    else
      {
        column_rows.resize(n_nodes);
        column_blocks.resize(n_nodes);
      }
  }

  void
  ComplianceMatrix::reinit(const unsigned int    n_nodes,
                           std::vector<double> &&column_major)
  {
    if (column_major.size() != 4 * std::size_t(n_nodes) * n_nodes)
      throw std::logic_error("ComplianceMatrix::reinit: a dense array of " +
                             std::to_string(column_major.size()) +
                             " entries for " + std::to_string(n_nodes) +
                             " nodes");
    reinit(0, Storage::dense);
    n_contact_nodes = n_nodes;
    dense_values    = std::move(column_major);
  }



  unsigned int
  ComplianceMatrix::n_nodes() const
  {
    return n_contact_nodes;
  }

  unsigned int
  ComplianceMatrix::size() const
  {
    return 2 * n_contact_nodes;
  }

  ComplianceMatrix::Storage
  ComplianceMatrix::storage() const
  {
    return storage_type;
  }

  void
  ComplianceMatrix::add_block(const unsigned int k,
                              const unsigned int l,
                              const Block       &block)
  {
    assert(k < n_contact_nodes && l < n_contact_nodes);
    if (storage_type == Storage::dense)
      {
        const std::size_t n_rows = size();
        for (unsigned int b = 0; b < 2; ++b)
          {
            double *column = &dense_values[(2 * std::size_t(l) + b) * n_rows];
            column[2 * k] += block[0][b];
            column[2 * k + 1] += block[1][b];
          }
        return;
      }

    // Keep each column sorted by row node. Assembly usually visits the rows
    // in increasing order, so the insertion is then an append.
    std::vector<unsigned int> &rows   = column_rows[l];
    std::vector<Block>        &blocks = column_blocks[l];
    const auto        position = std::lower_bound(rows.begin(), rows.end(), k);
    const std::size_t index    = position - rows.begin();
    if (position != rows.end() && *position == k)
      {
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = 0; b < 2; ++b)
            blocks[index][a][b] += block[a][b];
      }
    else
      {
        rows.insert(position, k);
        blocks.insert(blocks.begin() + index, block);
      }
  }

  void
  ComplianceMatrix::set_block(const unsigned int k,
                              const unsigned int l,
                              const Block       &block)
  {
    assert(k < n_contact_nodes && l < n_contact_nodes);
    if (storage_type == Storage::dense)
      {
        const std::size_t n_rows = size();
        for (unsigned int b = 0; b < 2; ++b)
          for (unsigned int a = 0; a < 2; ++a)
            dense_values[(2 * std::size_t(l) + b) * n_rows + 2 * k + a] =
              block[a][b];
      }
    else if (const Block *stored = find_sparse_block(k, l))
      *const_cast<Block *>(stored) = block;
    else
      add_block(k, l, block);
  }

  const ComplianceMatrix::Block *
  ComplianceMatrix::find_sparse_block(const unsigned int k,
                                      const unsigned int l) const
  {
    const std::vector<unsigned int> &rows = column_rows[l];
    const auto position = std::lower_bound(rows.begin(), rows.end(), k);
    if (position == rows.end() || *position != k)
      return nullptr;
    return &column_blocks[l][position - rows.begin()];
  }

  ComplianceMatrix::Block
  ComplianceMatrix::block(const unsigned int k, const unsigned int l) const
  {
    assert(k < n_contact_nodes && l < n_contact_nodes);
    Block result = {{{{0., 0.}}, {{0., 0.}}}};
    if (storage_type == Storage::dense)
      {
        const std::size_t n_rows = size();
        for (unsigned int b = 0; b < 2; ++b)
          for (unsigned int a = 0; a < 2; ++a)
            result[a][b] =
              dense_values[(2 * std::size_t(l) + b) * n_rows + 2 * k + a];
      }
    else if (const Block *stored = find_sparse_block(k, l))
      result = *stored;
    return result;
  }

  ComplianceMatrix::Block
  ComplianceMatrix::diagonal_block(const unsigned int k) const
  {
    return block(k, k);
  }

  double
  ComplianceMatrix::normal_compliance(const unsigned int k) const
  {
    return block(k, k)[normal][normal];
  }

  bool
  ComplianceMatrix::block_is_stored(const unsigned int k,
                                    const unsigned int l) const
  {
    if (storage_type == Storage::dense)
      return true;
    return find_sparse_block(k, l) != nullptr;
  }

  void
  ComplianceMatrix::add_product(const std::vector<Vector2> &r,
                                std::vector<Vector2>       &u) const
  {
    assert(r.size() == n_contact_nodes && u.size() == n_contact_nodes);
    for (unsigned int l = 0; l < n_contact_nodes; ++l)
      add_column_product(l, r[l], u);
  }

  void
  ComplianceMatrix::add_column_product(const unsigned int    l,
                                       const Vector2        &r_l,
                                       std::vector<Vector2> &u) const
  {
    assert(l < n_contact_nodes && u.size() == n_contact_nodes);
    if (storage_type == Storage::dense)
      {
        const std::size_t n_rows = size();
        for (unsigned int b = 0; b < 2; ++b)
          {
            const double factor = r_l[b];
            if (factor == 0.)
              continue;
            const double *column =
              &dense_values[(2 * std::size_t(l) + b) * n_rows];
            for (unsigned int k = 0; k < n_contact_nodes; ++k)
              {
                u[k][0] += column[2 * k] * factor;
                u[k][1] += column[2 * k + 1] * factor;
              }
          }
        return;
      }

    const std::vector<unsigned int> &rows   = column_rows[l];
    const std::vector<Block>        &blocks = column_blocks[l];
    for (std::size_t i = 0; i < rows.size(); ++i)
      {
        const Block &w = blocks[i];
        u[rows[i]][0] += w[0][0] * r_l[0] + w[0][1] * r_l[1];
        u[rows[i]][1] += w[1][0] * r_l[0] + w[1][1] * r_l[1];
      }
  }

  std::size_t
  ComplianceMatrix::n_stored_blocks() const
  {
    if (storage_type == Storage::dense)
      return std::size_t(n_contact_nodes) * n_contact_nodes;
    std::size_t n = 0;
    for (const auto &rows : column_rows)
      n += rows.size();
    return n;
  }

  std::size_t
  ComplianceMatrix::memory_consumption() const
  {
    std::size_t bytes =
      sizeof(*this) + dense_values.capacity() * sizeof(double);
    for (const auto &rows : column_rows)
      bytes += sizeof(rows) + rows.capacity() * sizeof(unsigned int);
    for (const auto &blocks : column_blocks)
      bytes += sizeof(blocks) + blocks.capacity() * sizeof(Block);
    return bytes;
  }

  bool
  ComplianceMatrix::all_entries_finite() const
  {
    for (const double value : dense_values)
      if (!std::isfinite(value))
        return false;
    for (const auto &blocks : column_blocks)
      for (const Block &w : blocks)
        for (const auto &row : w)
          for (const double value : row)
            if (!std::isfinite(value))
              return false;
    return true;
  }

  double
  ComplianceMatrix::max_asymmetry() const
  {
    double result = 0.;
    for (unsigned int l = 0; l < n_contact_nodes; ++l)
      for (unsigned int k = 0; k < n_contact_nodes; ++k)
        {
          if (storage_type == Storage::block_sparse && !block_is_stored(k, l) &&
              !block_is_stored(l, k))
            continue;
          const Block w_kl = block(k, l);
          const Block w_lk = block(l, k);
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int b = 0; b < 2; ++b)
              result = std::max(result, std::abs(w_kl[a][b] - w_lk[b][a]));
        }
    return result;
  }
} // namespace glissade

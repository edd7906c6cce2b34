#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace glissade
{
  /**
   * The compliance (Delassus) matrix W of the condensed contact problem
   * (CONTACT_ALGORITHM.md, step 3): for n active contact nodes, the relative
   * displacement of node k in its local frame (t, n) is
   *
   *   u_k = u_k^free + sum_l W_kl r_l,
   *
   * where r_l = (r_t, r_n) is the reaction on slave node l and W_kl is a 2x2
   * block. Inside a block, index 0 is the tangential and index 1 the normal
   * component: W_kl[1][0] is the normal displacement of node k caused by a
   * unit tangential reaction on node l.
   *
   * <h3>Storage</h3>
   * Two layouts share this interface, chosen when the matrix is sized:
   *
   * - Storage::dense: one column-major 2n x 2n array, 32 n^2 bytes (128 MB
   *   for n = 2000). This is the right choice for one contact pair, where
   *   every node sees every other through the deformable body, so W is full.
   * - Storage::block_sparse: per block column l, the sorted list of nodes k
   *   with a stored block W_kl. W_kl is structurally zero when nodes k and l
   *   share no deformable body, so a scene with several independent contact
   *   pairs stores only the diagonal blocks of the pair structure.
   *
   * Both layouts are organised by columns because the Gauss-Seidel solver
   * (BiPotentialSolver) needs, after changing r_l, the update
   * u += W_{.l} delta_r_l, i.e. one block column. Column access also works
   * when W is not symmetric, which happens when the reaction is handed to
   * other master nodes than those used to measure the displacement (the
   * paper's "underlying Q4 segment" variant).
   *
   * W is not checked for symmetry or positive semi-definiteness: it is
   * whatever H K^-1 H^T the caller assembled. max_asymmetry() is offered for
   * diagnostics.
   */
  class ComplianceMatrix
  {
  public:
    /** A 2x2 block: block[row][column], 0 = tangential, 1 = normal. */
    using Block = std::array<std::array<double, 2>, 2>;

    /** A pair (tangential, normal) attached to one node. */
    using Vector2 = std::array<double, 2>;

    static constexpr unsigned int tangential = 0;
    static constexpr unsigned int normal     = 1;

    enum class Storage
    {
      dense,
      block_sparse
    };

    /** An empty matrix (no nodes). */
    ComplianceMatrix() = default;

    /** A zero matrix for n_nodes contact nodes. */
    explicit ComplianceMatrix(unsigned int n_nodes,
                              Storage      storage = Storage::dense);

    /** Resize to n_nodes nodes, set to zero, and choose the storage. */
    void
    reinit(unsigned int n_nodes, Storage storage = Storage::dense);

    /**
     * Dense storage for n_nodes nodes, taking over `column_major` (the
     * 2n x 2n matrix in the layout of the dense storage) rather than
     * copying it: 82 MB fewer at 1,600 contact nodes.
     */
    void
    reinit(unsigned int n_nodes, std::vector<double> &&column_major);

    unsigned int
    n_nodes() const;

    /** Number of scalar rows (= columns): 2 n_nodes. */
    unsigned int
    size() const;

    Storage
    storage() const;

    /** W_kl += block. Creates the block if the storage is block-sparse. */
    void
    add_block(unsigned int k, unsigned int l, const Block &block);

    /** W_kl = block. */
    void
    set_block(unsigned int k, unsigned int l, const Block &block);

    /** W_kl, zero if the block is not stored. */
    Block
    block(unsigned int k, unsigned int l) const;

    /** W_kk. */
    Block
    diagonal_block(unsigned int k) const;

    /**
     * W_kk[normal][normal]: the normal displacement of node k per unit normal
     * reaction on itself. Zero when both bodies touching at k are rigid.
     */
    double
    normal_compliance(unsigned int k) const;

    /** Whether the block W_kl is stored (always true for dense storage). */
    bool
    block_is_stored(unsigned int k, unsigned int l) const;

    /** u += W r, for whole node vectors of length n_nodes(). */
    void
    add_product(const std::vector<Vector2> &r, std::vector<Vector2> &u) const;

    /**
     * u += W_{.l} r_l: the change of every node's relative displacement when
     * the reaction of node l changes by r_l. Components of r_l that are zero
     * are skipped, so a frictionless update reads only the normal column.
     */
    void
    add_column_product(unsigned int          l,
                       const Vector2        &r_l,
                       std::vector<Vector2> &u) const;

    /** Number of stored 2x2 blocks (n^2 for dense storage). */
    std::size_t
    n_stored_blocks() const;

    /** Bytes used by the stored values and indices. */
    std::size_t
    memory_consumption() const;

    /** True if no stored value is NaN or infinite. */
    bool
    all_entries_finite() const;

    /** max |W_ij - W_ji| over the stored entries. */
    double
    max_asymmetry() const;

  private:
    unsigned int n_contact_nodes = 0;
    Storage      storage_type    = Storage::dense;

    // Dense storage: entry (i, j) of the 2n x 2n matrix, scalar index
    // i = 2 k + component, is dense_values[j * 2n + i].
    std::vector<double> dense_values;

    // Block-sparse storage: for block column l, the nodes k of the stored
    // blocks W_kl in increasing order, and the blocks in the same order.
    std::vector<std::vector<unsigned int>> column_rows;
    std::vector<std::vector<Block>>        column_blocks;

    // The stored block W_kl, or nullptr (block-sparse storage only).
    const Block *
    find_sparse_block(unsigned int k, unsigned int l) const;
  };
} // namespace glissade

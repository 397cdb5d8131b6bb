#pragma once
// The network distributed by rows: each rank holds one contiguous block of rows (a RowBlock,
// cut by balanced_row_starts so that ranks hold about equal stored entries) and nothing else of
// size nnz. The rows are kept once, as a CSR whose columns index the rank's *column space* (its
// own rows and the ghost nodes its rows reference, in ascending global order); a Tpetra::Map
// describes the row blocks and a Tpetra::Import fills the ghost values. The force kernel reads
// that CSR directly, and A v products (the eigensolver's Tpetra operator, apply) run on it too:
// one copy of the structure, 4 bytes per stored entry (+ 8 when weighted) + 8 per row. A run
// that needs nothing else may hand the column indices to the sparse force, which holds them
// in its own layout (release_columns).
// Trilinos types stay behind the pimpl: only distributed_network_impl.hpp names them.
//
// The complete graph is held implicitly: only the row blocks (the Map), no rows; what needs
// stored rows (apply, local_adjacency, import_columns, the eigensolver) refuses it, and its
// callers use the closed forms of network/complete_graph.hpp and the rank-one force instead;
// what needs the column indices refuses a network that released them, likewise.
#include <memory>
#include <vector>

#include "network/complete_graph.hpp"
#include "network/network.hpp"
#include "network/row_block.hpp"

namespace hmfnet {

class DistributedNetwork {
 public:
  /// Needs a live ParallelSession. Collective: every rank calls it with the same network and
  /// keeps a copy of its own balanced block only.
  explicit DistributedNetwork(const Network& network);
  /// Takes over this rank's block. Collective: the blocks must be those of
  /// balanced_row_starts-style cuts, contiguous and in rank order (a block out of place is
  /// refused on every rank). Symmetry across blocks is the caller's to check
  /// (require_symmetric, parallel/distributed_read.hpp).
  explicit DistributedNetwork(RowBlock block);
  /// The row blocks of K_N over the ranks, and no stored rows. Collective.
  explicit DistributedNetwork(const CompleteGraph& graph);
  ~DistributedNetwork();
  DistributedNetwork(const DistributedNetwork&) = delete;
  DistributedNetwork& operator=(const DistributedNetwork&) = delete;

  NodeIndex global_size() const;
  /// Rows owned here: global indices [first_row(), first_row() + local_size()).
  NodeIndex local_size() const;
  NodeIndex first_row() const;
  /// Stored entries over all ranks (for the complete graph, those it stands for).
  EdgeOffset global_nnz() const;
  /// False for a structure held implicitly (the complete graph): no matrix behind it.
  bool stores_rows() const;
  /// True when some stored entry has a weight (the same answer on every rank).
  bool weighted() const;
  /// Diagonal entries over all ranks (for the complete graph, n or 0).
  EdgeOffset global_self_loops() const;
  /// d_i = sum_j A_ij of the rows owned here.
  std::vector<double> local_degrees() const;
  /// Columns referenced by this rank's rows that other ranks own: the values one product
  /// imports (0 on one rank, and for K_N held without rows).
  NodeIndex ghost_count() const;

  /// y = A x on the rows owned here; x and y hold this rank's entries (local_size() each).
  /// Collective (ghost values of x travel through the matrix's Import).
  void apply(const std::vector<double>& x_local, std::vector<double>& y_local) const;

  /// The full vector on every rank from each rank's block. Collective.
  std::vector<double> gather(const std::vector<double>& x_local) const;

  /// This rank's rows as a plain CSR whose column indices point into the *column space*: the
  /// owned rows' values and the ghost values of remote neighbours, laid out as import_columns
  /// fills them. Rows in the same order as the owned block; the column space is in ascending
  /// global order, so columns within a row are too (the same summation order on every rank
  /// count). `weights` empty: 0/1 network.
  struct LocalAdjacency {
    std::vector<EdgeOffset> row_ptr;
    std::vector<NodeIndex> cols;
    std::vector<double> weights;
    NodeIndex columns = 0;  ///< size of the column space
  };
  /// The stored rows themselves (no copy): valid while this object lives. Throws once the
  /// column indices were released.
  const LocalAdjacency& local_adjacency() const;
  /// Gives this rank's column indices away, for a run that reads the network only through its
  /// sparse force, which then holds them in its own layout and frees them
  /// (NetworkForce::take_columns): 4 bytes per stored entry less at the peak. A reference that
  /// local_adjacency() returned before keeps row_ptr, weights and columns, its cols empty; what
  /// reads the column indices afterwards (local_adjacency, apply, the eigensolver's operator,
  /// the content hash) throws ParameterError. Not collective.
  std::vector<NodeIndex> release_columns();
  /// Global index of column-space entry c (0 <= c < LocalAdjacency::columns).
  NodeIndex global_column(NodeIndex c) const;
  /// Every column-space entry's global index, ascending.
  std::vector<NodeIndex> column_globals() const;

  /// Fills the column space from the owned block: `owned` is local_size() x width row-major,
  /// `columns` is LocalAdjacency::columns x width row-major. Collective (one Tpetra Import).
  void import_columns(const double* owned, int width, double* columns) const;

  /// True when the column space is the owned block itself, in the same order (one rank, every
  /// node a column): then import_columns is the identity and callers may skip it.
  bool columns_are_owned_rows() const;

  /// The Tpetra types, defined in distributed_network_impl.hpp (an internal header).
  struct Impl;

 private:
  // The Tpetra matrix reaches only the .cpp files that include the internal header (the
  // eigensolver hands it to Anasazi), through this accessor defined there.
  friend const Impl& tpetra_impl(const DistributedNetwork& network);

  std::unique_ptr<Impl> m_impl;
};

}  // namespace hmfnet

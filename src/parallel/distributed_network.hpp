#pragma once
// The network as a Tpetra::CrsMatrix over a Tpetra::Map, rows in contiguous blocks over the ranks
// of the default communicator. Trilinos types stay behind the pimpl: only
// distributed_network_impl.hpp (included by a few .cpp files) names them.
//
// Every rank holds the same replicated Network (generators are deterministic, readers read the
// same file) and inserts only the rows it owns; the matrix stores values as double.
// The complete graph is held implicitly: only the row blocks (the Map), no matrix; what needs
// stored rows (apply, local_adjacency, import_columns, the eigensolver) refuses it, and its
// callers use the closed forms of network/complete_graph.hpp and the rank-one force instead.
#include <memory>
#include <vector>

#include "network/complete_graph.hpp"
#include "network/network.hpp"

namespace hmfnet {

class DistributedNetwork {
 public:
  /// Needs a live ParallelSession. Collective: every rank calls it with the same network.
  explicit DistributedNetwork(const Network& network);
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

  /// y = A x on the rows owned here; x and y hold this rank's entries (local_size() each).
  /// Collective (ghost values of x travel through the matrix's Import).
  void apply(const std::vector<double>& x_local, std::vector<double>& y_local) const;

  /// The full vector on every rank from each rank's block. Collective.
  std::vector<double> gather(const std::vector<double>& x_local) const;

  /// This rank's rows as a plain CSR whose column indices point into the *column space*: the
  /// owned rows' values and the ghost values of remote neighbours, laid out as import_columns
  /// fills them. Rows in the same order as the owned block; columns sorted within a row by
  /// global index (the same summation order on every rank count). `weights` empty: 0/1 network.
  struct LocalAdjacency {
    std::vector<EdgeOffset> row_ptr;
    std::vector<NodeIndex> cols;
    std::vector<double> weights;
    NodeIndex columns = 0;  ///< size of the column space
  };
  LocalAdjacency local_adjacency() const;

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

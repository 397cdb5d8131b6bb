#pragma once
// The network as a Tpetra::CrsMatrix over a Tpetra::Map, rows in contiguous blocks over the ranks
// of the default communicator. Trilinos types stay behind the pimpl: only
// distributed_network_impl.hpp (included by a few .cpp files) names them.
//
// Every rank holds the same replicated Network (generators are deterministic, readers read the
// same file) and inserts only the rows it owns; the matrix stores values as double.
#include <memory>
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

class DistributedNetwork {
 public:
  /// Needs a live ParallelSession. Collective: every rank calls it with the same network.
  explicit DistributedNetwork(const Network& network);
  ~DistributedNetwork();
  DistributedNetwork(const DistributedNetwork&) = delete;
  DistributedNetwork& operator=(const DistributedNetwork&) = delete;

  NodeIndex global_size() const;
  /// Rows owned here: global indices [first_row(), first_row() + local_size()).
  NodeIndex local_size() const;
  NodeIndex first_row() const;
  /// Stored entries owned here and over all ranks.
  EdgeOffset local_nnz() const;
  EdgeOffset global_nnz() const;

  /// y = A x on the rows owned here; x and y hold this rank's entries (local_size() each).
  /// Collective (ghost values of x travel through the matrix's Import).
  void apply(const std::vector<double>& x_local, std::vector<double>& y_local) const;

  /// The full vector on every rank from each rank's block. Collective.
  std::vector<double> gather(const std::vector<double>& x_local) const;

  struct Impl;
  const Impl& impl() const { return *m_impl; }

 private:
  std::unique_ptr<Impl> m_impl;
};

}  // namespace hmfnet

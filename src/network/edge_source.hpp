#pragma once
// A random network generated in independent work units: unit k (a row of ER or of the two-block
// SBM, a position in the decreasing-target order of Chung-Lu) emits its undirected edges from
// random stream k of the seed only, so any split of the units over threads or ranks, in any
// order, gives the same network. The serial generators build a Network from all units
// (network_from_source); parallel/distributed_generation.hpp gives each rank only its rows.
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

using Edge = std::pair<NodeIndex, NodeIndex>;

class EdgeSource {
 public:
  virtual ~EdgeSource() = default;
  EdgeSource() = default;
  EdgeSource(const EdgeSource&) = delete;
  EdgeSource& operator=(const EdgeSource&) = delete;

  /// Nodes of the network.
  virtual NodeIndex nodes() const = 0;
  /// Work units, numbered 0 .. units() - 1.
  virtual std::int64_t units() const = 0;
  /// Expected work (candidate pairs or expected edges) of units [0, k): non-decreasing in k,
  /// used only to split the units evenly, never to decide an edge.
  virtual double work_before(std::int64_t k) const = 0;
  /// Appends unit k's edges {u, v}, u != v; each unordered pair comes from one unit, once.
  virtual void emit(std::int64_t k, std::vector<Edge>& out) const = 0;
};

/// The whole network of a source, every unit emitted in order (one thread).
Network network_from_source(const EdgeSource& source);

/// Starts of `parts` contiguous unit ranges of about equal work_before (parts + 1 entries,
/// starts[0] = 0, starts[parts] = units()).
std::vector<std::int64_t> balanced_unit_starts(const EdgeSource& source, int parts);

}  // namespace hmfnet

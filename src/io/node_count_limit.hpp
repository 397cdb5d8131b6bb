#pragma once
// The largest node count a network file may give for the entries it stores. The readers allocate
// n + 1 row pointers (8 bytes each) whatever the file holds, and nodes that no entry touches are
// isolated, so an unchecked count lets a 20-byte file ("0 2000000000", or a Matrix Market size
// line "2000000000 2000000000 1") make a read allocate 16 GB (found by tests/fuzz). Bounding n by
// the entries keeps what a read allocates proportional to the file: any network with at most
// k_nodes_without_entries nodes is accepted, and a larger one needs mean degree 2/64 or more
// (a network whose nodes are almost all isolated is not one the HMF theory describes).
// A node count the user gives explicitly (ReadOptions::edge_list_nodes) is not bounded.
#include <algorithm>
#include <cstdint>
#include <limits>

#include "network/network.hpp"

namespace hmfnet {

/// Nodes allowed whatever the entry count: 2^20 (8 MiB of row pointers).
inline constexpr std::int64_t k_nodes_without_entries = std::int64_t{1} << 20;
/// Further nodes allowed per stored entry (an undirected edge counts once).
inline constexpr std::int64_t k_nodes_per_entry = 64;

/// Largest node count accepted from a file storing `entries` entries (never above NodeIndex).
inline std::int64_t max_nodes_for_entries(std::int64_t entries) {
  const std::int64_t index_limit = std::numeric_limits<NodeIndex>::max();
  const std::int64_t per_entry = std::min(entries, index_limit / k_nodes_per_entry);
  return std::min(index_limit, k_nodes_without_entries + k_nodes_per_entry * per_entry);
}

}  // namespace hmfnet

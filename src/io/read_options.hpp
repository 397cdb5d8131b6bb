#pragma once
// Options shared by the network readers, and what a read returns.
#include <string>
#include <vector>

#include "network/network.hpp"
#include "network/network_builder.hpp"

namespace hmfnet {

struct ReadOptions {
  AsymmetryPolicy asymmetry = AsymmetryPolicy::reject;  ///< for Matrix Market `general`
  int edge_list_base = 0;         ///< first node index in an edge list: 0 or 1
  NodeIndex edge_list_nodes = 0;  ///< node count for an edge list; 0: largest index + 1
};

struct ReadResult {
  Network network;
  std::vector<std::string> warnings;  ///< one line each, "FILE: warning: ..."
};

}  // namespace hmfnet

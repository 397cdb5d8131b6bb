#pragma once
// Assembles a Network from entries read from a file, with the checks every reader needs:
// duplicates, symmetry of a `general` matrix, weights, empty network. Errors are InputError
// naming the source file and the line of the offending entry.
#include <cstdint>
#include <string>
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

/// One matrix entry as read: 0-based indices, the weight (1 for pattern files) and its line.
struct MatrixEntry {
  NodeIndex row;
  NodeIndex col;
  double weight;
  std::int64_t line;
};

enum class EntrySymmetry {
  symmetric,  ///< each entry (i,j) stands for both A_ij and A_ji (MM `symmetric`, edge lists)
  general     ///< entries are the matrix as written; it must be symmetric or be symmetrised
};

/// What to do with a `general` matrix that is not symmetric. The paper (eq:hamiltonianNetworkCase)
/// notes that the antisymmetric part of A does not act on the dynamics, so (A + A^T)/2 is the
/// network that matters; doing so is never silent.
enum class AsymmetryPolicy { reject, symmetrize };

struct BuildResult {
  Network network;
  std::vector<std::string> warnings;
};

struct BuildOptions {
  EntrySymmetry symmetry = EntrySymmetry::symmetric;
  AsymmetryPolicy asymmetry = AsymmetryPolicy::reject;
  int index_base = 0;  ///< only to print indices as the file wrote them
};

/// Checks and assembles. Entries with weight exactly 0 are dropped (with a warning): they are not
/// edges. Weights must be finite and >= 0 (readers check as they parse, this checks again).
/// A network whose stored weights are all 1 is stored as a 0/1 network (no values).
BuildResult build_network(const std::string& source, NodeIndex n, std::vector<MatrixEntry> entries,
                          const BuildOptions& options);

}  // namespace hmfnet

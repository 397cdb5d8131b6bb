#pragma once
// Assembles a Network from entries read from a file, with the checks every reader needs:
// duplicates, symmetry of a `general` matrix, weights, empty network. Errors are InputError
// naming the source file and the line of the offending entry.
#include <cstdint>
#include <string>
#include <vector>

#include "network/network.hpp"
#include "network/row_block.hpp"

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

/// The rows [first, last) of the network that `entries` describe, checked, and what the caller
/// must add up over the parts of a network built in parts before it warns or refuses. `entries`
/// must hold every entry, as written, that touches these rows (row or column in [first, last)):
/// the whole file, or what a parallel reader sent to the rank owning the rows.
struct RowsBuild {
  RowBlock block;              ///< weights always kept; drop them when all_ones holds everywhere
  bool all_ones = true;        ///< every stored weight in these rows is 1
  std::int64_t zeros = 0;      ///< explicit zeros written in these rows (dropped)
  std::int64_t unmatched = 0;  ///< `general`: entries of these rows without an equal transpose
  std::int64_t first_unmatched_line = 0;
  std::string first_unmatched;  ///< that entry, "(i,j)" as the file writes indices
};

/// Throws InputError for what is wrong within the entries (weights, duplicates); an asymmetric
/// `general` matrix is only counted (RowsBuild::unmatched) and, when the policy says so,
/// symmetrised (always: exact where it is symmetric). Emptiness is the caller's to check.
RowsBuild build_rows(const std::string& source, NodeIndex n, NodeIndex first, NodeIndex last,
                     std::vector<MatrixEntry> entries, const BuildOptions& options);

/// The messages of the checks that need the whole network's counts.
std::string asymmetry_message(const RowsBuild& first_part, std::int64_t unmatched);
std::string asymmetry_warning(const std::string& source, std::int64_t unmatched);
std::string zeros_warning(const std::string& source, std::int64_t zeros);

/// Checks and assembles (build_rows over all rows). Entries with weight exactly 0 are dropped (with
/// a warning): they are not edges. Weights must be finite and >= 0 (readers check as they parse,
/// this checks again). A network whose stored weights are all 1 is stored as a 0/1 network (no
/// values).
BuildResult build_network(const std::string& source, NodeIndex n, std::vector<MatrixEntry> entries,
                          const BuildOptions& options);

}  // namespace hmfnet

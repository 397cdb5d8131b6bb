#pragma once
// Sending matrix entries to the ranks that own their rows: what a parallel reader (each rank
// parses part of a file) and a renumbering (each rank renames its own rows) both need. Entries
// travel as their bytes through a Tpetra::Distributor (grouped by destination, received in
// place), in rounds of at most `round_entries` entries per rank, so a rank holds its entries
// (24 B each), what it has received (24 B each) and one round's packets (up to 2 x 28 B per
// entry of the round).
#include <cstddef>
#include <vector>

#include "network/network.hpp"
#include "network/network_builder.hpp"

namespace hmfnet {

enum class Destinations {
  row_owner,            ///< each entry to the rank owning its row
  row_and_column_owner  ///< and to the one owning its column (once when the same)
};

/// Collective. Rows are owned by contiguous blocks: rank p owns [row_starts[p],
/// row_starts[p + 1]). Returns the entries this rank received, round by round, in rank order
/// of their senders within a round.
std::vector<MatrixEntry> send_to_owners(const std::vector<MatrixEntry>& entries,
                                        const std::vector<NodeIndex>& row_starts,
                                        Destinations destinations,
                                        std::size_t round_entries = std::size_t{1} << 22);

}  // namespace hmfnet

#pragma once
// Generating a random network by rows over the ranks (docs/scaling.md): no rank ever holds
// more than its own rows. The units of an EdgeSource (network/edge_source.hpp) are split by
// expected work; every rank emits its units twice: once to count the degrees (an N-vector
// summed over the ranks, from which the rows are cut by stored entries exactly as a reader cuts
// them, balanced_row_starts; O(N) transient on every rank, ~24 B per node at its peak: the
// counts, the reduction's copy, then the global row pointers), once to send each edge's two
// entries (u, v) and (v, u) to the ranks that own rows u and v, through a Tpetra::Distributor,
// in rounds of at most `chunk_edges` edges per rank (~40 B per edge sent; what a rank receives
// in a round is up to P times that in the worst case, 2 chunk_edges entries from each rank). Each
// row is then sorted, so the block equals the rows network_from_source(source) would give, for any
// rank count.
#include <cstdint>

#include "network/edge_source.hpp"
#include "network/row_block.hpp"

namespace hmfnet {

/// Collective: this rank's rows of the source's network.
RowBlock generate_distributed(const EdgeSource& source, std::int64_t chunk_edges = 1 << 21);

}  // namespace hmfnet

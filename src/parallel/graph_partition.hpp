#pragma once
// Graph partitioning through Zoltan2 (docs/scaling.md): for a network with structure (blocks,
// communities, geometry) whose node labels do not follow it, parts that cut few edges make the
// ghost set of each rank small, so each step imports fewer values. Zoltan2 runs Zoltan's
// parallel hypergraph partitioner PHG (algorithm "phg"; the graph's rows as hyperedges, so the
// cut it minimises is the ghost count itself) on the rows held by the ranks, each node weighted
// by its stored entries so that the parts hold equal work. Debian's Zoltan2 has no ParMETIS; its
// Scotch path was tried and dropped: on a shuffled two-block SBM (N = 1200, degree 31 inside and
// 1.2 across) it cut 0.07-0.20 of the entries depending on its threads and seed, where PHG finds
// the planted partition's 0.038 (tests/parallel/test_node_renumbering.cpp).
// The parts are then made contiguous by renumbering (parallel/node_renumbering.hpp): every
// reader here cuts rows into contiguous blocks. For ER no partition can help (every part of
// N / P nodes has ~d (1 - 1/P) of each node's neighbours outside it): bench/partition_ghosts.sh.
#include <cstdint>
#include <vector>

#include "network/row_block.hpp"

namespace hmfnet {

/// Collective. The part in [0, parts) of each row held here. PHG's random choices (matchings,
/// initial partitions) are seeded by `seed`, so the parts are reproducible for a given input,
/// seed and rank count; they may differ between rank counts (PHG coarsens in parallel): a
/// renumbered file records them.
std::vector<int> partition_rows(const RowBlock& block, int parts, std::uint64_t seed);

}  // namespace hmfnet

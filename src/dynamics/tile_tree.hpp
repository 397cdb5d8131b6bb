#pragma once
// Z's fixed pairwise tree over a replica's tile sums, and where a tile's rotors sit in a block's
// shared memory, for the complete graph's device stepper (cuda/complete_graph_ensembles.hpp).
// Host-and-device, so that the CPU tests (tests/dynamics/test_tile_tree.cpp) check what the
// device's stepper with its state in shared memory relies on: that summing the tree chunk by
// chunk and then over the chunks' heads adds the same pairs in the same order as the whole tree
// (the same bits as the stepper whose state stays in global memory), and that the layout gives
// every rotor of a replica one slot of exactly one block.
#include <cstddef>
#include <cstdint>

#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet {

/// The tree's levels run stride = 1, 2, 4, ...; at each, entry i (a multiple of 2 stride) takes
/// entry i + stride where that is below count. After every level below count, entry 0 holds the
/// total. The additions of one level are independent, so threads may take them in any order.
HMFNET_HD_INLINE bool tree_adds_into(int i, int stride, int count) {
  return i % (2 * stride) == 0 && i + stride < count;
}

/// The levels stride < stride_end of the tree over sums[0, count), one after the other.
template <typename Real>
HMFNET_HD_INLINE void tree_levels(Real* sums, int count, int stride_end) {
  for (int stride = 1; stride < stride_end && stride < count; stride *= 2) {
    for (int i = 0; i + stride < count; i += 2 * stride) sums[i] += sums[i + stride];
  }
}

/// The same tree in two parts, as blocks that each hold some chunks of `chunk` entries (a power of
/// two) run it: the levels below `chunk` inside each chunk (a pair i, i + stride with
/// stride < chunk never crosses a chunk's edge, since i is a multiple of 2 stride), then the
/// levels from `chunk` on, whose pairs are chunk heads: the tree over the heads, stride / chunk
/// apart. heads: room for ceil(count / chunk) values. Returns the total; sums is overwritten.
template <typename Real>
Real chunked_tree_sum(Real* sums, int count, int chunk, Real* heads) {
  const int chunks = (count + chunk - 1) / chunk;
  for (int q = 0; q < chunks; ++q) {
    const int base = q * chunk;
    const int inside = count - base < chunk ? count - base : chunk;
    tree_levels(sums + base, inside, chunk);
    heads[q] = sums[base];
  }
  tree_levels(heads, chunks, chunks);
  return heads[0];
}

/// Where a replica's rotors sit in the shared memory of its cluster's blocks. Tile t holds the
/// rotors m = t, t + tiles, ..., (m mod tiles = t); thread `thread` of block `rank` owns the tiles
/// t = rank threads + thread + j stride (stride = blocks threads), so that block `rank` owns the
/// chunks q = t / threads with q mod blocks = rank. Its j-th tile is local tile
/// j threads + thread, and the k-th rotor of a local tile L sits at slot k local_tiles() + L:
/// neighbouring threads, neighbouring slots.
struct TileLayout {
  std::int64_t n;  ///< rotors of the replica
  int tiles;       ///< min(n, the stepper's tile cap)
  int blocks;      ///< of the replica's cluster
  int threads;     ///< per block

  HMFNET_HD_INLINE int stride() const { return blocks * threads; }
  /// Local tiles of a block: the slots of one rotor row (some may hold no tile).
  HMFNET_HD_INLINE int local_tiles() const { return (tiles + stride() - 1) / stride() * threads; }
  /// The most rotors of a tile: ceil(n / tiles).
  HMFNET_HD_INLINE int rotors_per_tile() const { return static_cast<int>((n + tiles - 1) / tiles); }
  HMFNET_HD_INLINE int tile(int rank, int thread, int j) const {
    return rank * threads + thread + j * stride();
  }
  HMFNET_HD_INLINE int local_tile(int thread, int j) const { return j * threads + thread; }
  HMFNET_HD_INLINE std::int64_t slot(int local, int k) const {
    return static_cast<std::int64_t>(k) * local_tiles() + local;
  }
  /// Slots of a block, each holding one value of a rotor.
  HMFNET_HD_INLINE std::int64_t slots() const {
    return static_cast<std::int64_t>(local_tiles()) * rotors_per_tile();
  }
  /// Chunks of `threads` tiles, and so tree heads, of the replica.
  HMFNET_HD_INLINE int chunks() const { return (tiles + threads - 1) / threads; }
};

}  // namespace hmfnet

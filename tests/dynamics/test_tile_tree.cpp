// The complete graph's tile tree and shared-memory layout (dynamics/tile_tree.hpp): the tree summed
// chunk by chunk and then over the heads gives the whole tree's bits for every tile count and
// chunk the device stepper may meet; the tree is not the left-to-right sum (so the check above
// could fail); the layout gives every rotor of a replica exactly one slot of one block, inside
// that block's slots, and each tile to the block that owns its chunk.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "dynamics/tile_tree.hpp"
#include "support/bit_difference.hpp"

using namespace hmfnet;
using test::bit_difference;

namespace {

// Terms of mixed sign and magnitude (as [cos, sin] tile sums of ~1 to ~50 rotors), so that
// another order of additions rounds differently.
std::vector<double> tile_sums(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> sums(static_cast<std::size_t>(count));
  for (double& s : sums) s = u(rng) * std::pow(10.0, 3.0 * u(rng));
  return sums;
}

double whole_tree(std::vector<double> sums) {
  const int count = static_cast<int>(sums.size());
  tree_levels(sums.data(), count, count);
  return sums[0];
}

}  // namespace

TEST_CASE("the tile tree by chunks and then heads gives the whole tree's bits", "[tile_tree]") {
  // Tile counts: min(N, 2048) for N below, at and above the cap, powers of two and not; chunks:
  // the threads per block a power of two allows (32 to 1024).
  for (const int count : {1, 2, 3, 31, 64, 100, 700, 1000, 1696, 2047, 2048}) {
    for (const int chunk : {32, 64, 128, 256, 512, 1024}) {
      INFO(count << " tiles in chunks of " << chunk);
      const std::vector<double> sums = tile_sums(count, 7U + static_cast<unsigned>(count));
      std::vector<double> work = sums;
      std::vector<double> heads(static_cast<std::size_t>((count + chunk - 1) / chunk));
      const double by_chunks = chunked_tree_sum(work.data(), count, chunk, heads.data());
      CHECK(bit_difference(std::vector<double>{by_chunks}, {whole_tree(sums)}) == "");
    }
  }
}

TEST_CASE("the tile tree is not the left-to-right sum, so an order change shows in its bits",
          "[tile_tree]") {
  int differ = 0;
  for (unsigned seed = 0; seed < 20; ++seed) {
    const std::vector<double> sums = tile_sums(2048, seed);
    double serial = 0.0;
    for (const double s : sums) serial += s;
    if (serial != whole_tree(sums)) ++differ;
  }
  INFO(differ << " of 20 draws of 2048 tile sums differ between the tree and the serial sum");
  CHECK(differ > 10);
}

TEST_CASE("the tile layout gives each rotor one slot of the block owning its tile's chunk",
          "[tile_tree]") {
  struct Shape {
    std::int64_t n;
    int blocks, threads;
  };
  // The benchmark's N = 10^5 on 8 blocks of 256 threads (49 and 48 rotors a tile), the campaign's
  // 2 10^4 on 4 of 512, N below the tile cap, more tiles than threads, idle threads.
  for (const Shape s : {Shape{100000, 8, 256}, Shape{20000, 4, 512}, Shape{3000, 1, 128},
                        Shape{3000, 2, 128}, Shape{700, 8, 64}, Shape{64, 2, 128}}) {
    const int tiles = static_cast<int>(s.n < 2048 ? s.n : 2048);
    const TileLayout layout{s.n, tiles, s.blocks, s.threads};
    INFO("N = " << s.n << ", " << s.blocks << " blocks of " << s.threads << " threads");
    std::vector<int> owner(static_cast<std::size_t>(s.n), -1);
    bool slots_inside = true, chunks_owned = true, slots_distinct = true, rotors_once = true;
    for (int rank = 0; rank < s.blocks; ++rank) {
      std::set<std::int64_t> used;
      for (int thread = 0; thread < s.threads; ++thread) {
        for (int j = 0; layout.tile(rank, thread, j) < tiles; ++j) {
          const int t = layout.tile(rank, thread, j);
          chunks_owned = chunks_owned && (t / s.threads) % s.blocks == rank;
          int k = 0;
          for (std::int64_t m = t; m < s.n; m += tiles, ++k) {
            const std::int64_t slot = layout.slot(layout.local_tile(thread, j), k);
            slots_inside = slots_inside && slot >= 0 && slot < layout.slots();
            slots_distinct = slots_distinct && used.insert(slot).second;
            rotors_once = rotors_once && owner[static_cast<std::size_t>(m)] == -1;
            owner[static_cast<std::size_t>(m)] = rank;
          }
        }
      }
    }
    CHECK(slots_inside);
    CHECK(slots_distinct);
    CHECK(rotors_once);
    CHECK(chunks_owned);
    CHECK(std::count(owner.begin(), owner.end(), -1) == 0);
    CHECK(layout.chunks() == (tiles + s.threads - 1) / s.threads);
  }
}

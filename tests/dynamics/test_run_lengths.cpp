// Run lengths in one byte (dynamics/run_lengths.hpp): a walk made from any row gives every later
// row's run start and length as the prefix sums of the lengths do, for lengths on both sides of
// the one-byte limit (254, 255, 256 and runs of thousands), row counts that are and are not
// multiples of the block, and segments with no long run or nothing but long runs.
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <vector>

#include "dynamics/run_lengths.hpp"

using namespace hmfnet;

namespace {

// Segment 0: short runs with every fourth row long; 1: lengths 250-260 in turn; 2: all long;
// 3: all short; 4: all empty.
std::vector<std::uint32_t> lengths(std::size_t rows, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint32_t> counts(5 * rows);
  for (std::size_t r = 0; r < rows; ++r) {
    counts[r] = r % 4 == 3 ? 255 + static_cast<std::uint32_t>(rng() % 3000)
                           : static_cast<std::uint32_t>(rng() % 20);
    counts[rows + r] = 250 + static_cast<std::uint32_t>(r % 11);
    counts[2 * rows + r] = 255 + static_cast<std::uint32_t>(rng() % 2);
    counts[3 * rows + r] = static_cast<std::uint32_t>(rng() % 255);
    counts[4 * rows + r] = 0;
  }
  return counts;
}

}  // namespace

TEST_CASE("run lengths: a walk from any row gives the prefix sums' starts and lengths",
          "[run_lengths]") {
  for (const std::size_t rows :
       {std::size_t{0}, std::size_t{1}, std::size_t{64}, std::size_t{200}, std::size_t{640}}) {
    const std::vector<std::uint32_t> counts = lengths(rows, 5 + rows);
    const RunLengths runs(counts, 5, rows);
    for (int s = 0; s < 5; ++s) {
      std::vector<std::uint32_t> start(rows + 1, 0);
      for (std::size_t r = 0; r < rows; ++r)
        start[r + 1] = start[r] + counts[static_cast<std::size_t>(s) * rows + r];
      for (std::size_t from = 0; from <= rows; ++from) {
        RunWalk walk = runs.walk(s, static_cast<NodeIndex>(from));
        bool same = walk.start == start[from];
        for (std::size_t r = from; r < rows && same; ++r) {
          const RunSpan span = walk.next(static_cast<NodeIndex>(r));
          same = span.begin == start[r] && span.n == start[r + 1] - start[r];
        }
        INFO("rows " << rows << ", segment " << s << ", walk from row " << from);
        REQUIRE(same);
      }
    }
  }
}

TEST_CASE("run lengths: one byte a run and a start every 64 rows, 8 bytes a long run",
          "[run_lengths]") {
  const std::size_t rows = 640;
  const std::vector<std::uint32_t> counts = lengths(rows, 3);
  std::size_t long_runs = 0;
  for (const std::uint32_t n : counts) long_runs += n >= 255 ? 1 : 0;
  REQUIRE(long_runs > rows);  // segments 0, 1 and 2 hold some
  const RunLengths runs(counts, 5, rows);
  CHECK(RunLengths::bytes_without_long_runs(5, rows) ==
        5 * rows + 5 * (rows / 64 + 1) * sizeof(std::uint32_t) + 6 * sizeof(std::size_t));
  CHECK(runs.bytes() == RunLengths::bytes_without_long_runs(5, rows) + long_runs * sizeof(LongRun));
}

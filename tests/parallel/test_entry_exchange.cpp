// Entries sent to the owners of their rows (parallel/entry_exchange.hpp): every entry arrives
// once at the owner of its row (and once more at the owner of its column when asked), intact,
// whatever the round size. Run at 1, 2 and 3 ranks (label mpi).
#include <catch2/catch.hpp>
#include <random>
#include <tuple>

#include "parallel/entry_exchange.hpp"
#include "parallel/parallel_session.hpp"

using namespace hmfnet;

namespace {

bool before(const MatrixEntry& a, const MatrixEntry& b) {
  return std::tie(a.row, a.col, a.line, a.weight) < std::tie(b.row, b.col, b.line, b.weight);
}

// Rank p's entries: rows and columns of 0..n-1 drawn from its own stream, lines numbering them
// uniquely over the ranks, weights from the line.
std::vector<MatrixEntry> entries_of(int rank, NodeIndex n, std::size_t count) {
  std::mt19937_64 rng(1000 + static_cast<std::uint64_t>(rank));
  std::uniform_int_distribution<NodeIndex> node(0, n - 1);
  std::vector<MatrixEntry> out;
  for (std::size_t k = 0; k < count; ++k) {
    const auto line = static_cast<std::int64_t>(rank) * 1000000 + static_cast<std::int64_t>(k);
    out.push_back({node(rng), node(rng), 0.5 + static_cast<double>(line), line});
  }
  return out;
}

}  // namespace

TEST_CASE("Entries reach the owners of their rows (and columns) intact, in any round size",
          "[distributed][exchange]") {
  const NodeIndex n = 500;
  const int ranks = ParallelSession::ranks();
  std::vector<NodeIndex> starts;
  for (int p = 0; p <= ranks; ++p) starts.push_back(static_cast<NodeIndex>(n * p / ranks));
  const NodeIndex first = starts[static_cast<std::size_t>(ParallelSession::rank())];
  const NodeIndex last = starts[static_cast<std::size_t>(ParallelSession::rank()) + 1];
  const auto both = GENERATE(Destinations::row_owner, Destinations::row_and_column_owner);

  // What this rank should receive, from every rank's entries.
  std::vector<MatrixEntry> expected;
  for (int p = 0; p < ranks; ++p) {
    for (const auto& e : entries_of(p, n, 2000 + 37 * static_cast<std::size_t>(p))) {
      const bool row_here = e.row >= first && e.row < last;
      const bool col_here = e.col >= first && e.col < last;
      if (row_here || (both == Destinations::row_and_column_owner && col_here))
        expected.push_back(e);
    }
  }
  std::sort(expected.begin(), expected.end(), before);
  const auto mine = entries_of(ParallelSession::rank(), n,
                               2000 + 37 * static_cast<std::size_t>(ParallelSession::rank()));
  for (const std::size_t round : {std::size_t{97}, std::size_t{1} << 22}) {
    std::vector<MatrixEntry> got = send_to_owners(mine, starts, both, round);
    std::sort(got.begin(), got.end(), before);
    INFO("rank " << ParallelSession::rank() << " of " << ranks << ", rounds of " << round);
    CHECK(got.size() == expected.size());
    bool same = got.size() == expected.size();
    for (std::size_t k = 0; same && k < got.size(); ++k)
      same = !before(got[k], expected[k]) && !before(expected[k], got[k]);
    CHECK(same);
  }
}

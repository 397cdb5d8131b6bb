#pragma once
// Sorted random CSR rows for the row-loop tests (tests/dynamics/test_segment_runs.cpp,
// test_wide_rows.cpp): degrees 0 to 40, so every length of a row's last d mod 4 occurs.
#include <cstdint>
#include <random>
#include <vector>

#include "network/network.hpp"

namespace hmfnet::test {

struct RandomRows {
  std::vector<EdgeOffset> row_ptr{0};
  std::vector<NodeIndex> cols;
};

/// `rows` rows over `columns` columns, degrees 0 to 40 (fewer where draws coincide); row 0
/// empty where `first_empty`.
inline RandomRows random_rows(NodeIndex rows, NodeIndex columns, std::uint64_t seed,
                              bool first_empty = false) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> degree(0, 40);
  RandomRows out;
  for (NodeIndex r = 0; r < rows; ++r) {
    std::vector<char> taken(static_cast<std::size_t>(columns), 0);
    const int d = first_empty && r == 0 ? 0 : degree(rng);
    for (int k = 0; k < d; ++k) taken[rng() % static_cast<std::size_t>(columns)] = 1;
    for (NodeIndex c = 0; c < columns; ++c)
      if (taken[static_cast<std::size_t>(c)] != 0) out.cols.push_back(c);
    out.row_ptr.push_back(static_cast<EdgeOffset>(out.cols.size()));
  }
  return out;
}

}  // namespace hmfnet::test

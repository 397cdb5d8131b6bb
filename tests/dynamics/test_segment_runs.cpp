// A segment's runs (dynamics/segment_runs.hpp): the AVX2 version adds every run to the carried
// partials with the same bits as the scalar loop, segment after segment, for runs of every
// length and first place mod 4 (rows of degree 0 to 40, one to six segments, tails of d mod 4),
// row ranges that start and stop anywhere, and tables holding -0.0, subnormals, inf and NaN.
// Where this CPU has no AVX2 (or HMFNET_SINCOS_ISA=baseline) both sides are the scalar loop and
// the test says so.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "dynamics/column_segments.hpp"
#include "dynamics/segment_runs.hpp"
#include "support/bit_difference.hpp"
#include "support/random_rows.hpp"

using namespace hmfnet;

namespace {

using Rows = test::RandomRows;

// A [cos, sin] table of 2B values a column, with the values that IEEE addition treats apart.
template <typename T>
std::vector<T> table(NodeIndex columns, int replicas, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<T> t(2 * static_cast<std::size_t>(columns) * static_cast<std::size_t>(replicas));
  for (T& x : t) x = static_cast<T>(value(rng));
  const T special[] = {T(-0.0), std::numeric_limits<T>::denorm_min(),
                       -std::numeric_limits<T>::denorm_min(), std::numeric_limits<T>::infinity(),
                       std::numeric_limits<T>::quiet_NaN()};
  for (std::size_t k = 0; k < t.size(); k += 97) t[k] = special[(k / 97) % 5];
  return t;
}

// Both versions over every segment of `cut` (indices of type I) for rows [origin, n), their
// carry and cursors held from row `origin` on (a panel of the kernel), the rows split at
// `split_row` into two calls.
template <typename T, typename I>
void compare(const Rows& rows, const ColumnSegments& cut, const std::vector<T>& t, int replicas,
             NodeIndex origin, NodeIndex split_row) {
  const auto n = static_cast<NodeIndex>(rows.row_ptr.size() - 1);
  const auto held = static_cast<std::size_t>(n - origin);
  const std::size_t values = 8 * held * static_cast<std::size_t>(replicas);
  std::vector<T> carry_vector(values, T(7)), carry_scalar(values, T(7));  // first zeroes them
  std::vector<std::uint32_t> cursor_vector(held), cursor_scalar = cursor_vector;
  for (int s = 0; s < cut.count(); ++s) {
    const bool first = s == 0, last = s + 1 == cut.count();
    const T* table = t.data() + 2 * static_cast<std::ptrdiff_t>(replicas) * cut.first_column(s);
    const SegmentPass<T, I> vector_pass{rows.row_ptr.data(),
                                        &cut.runs(),
                                        s,
                                        cut.template cols<I>(s),
                                        table,
                                        carry_vector.data(),
                                        cursor_vector.data(),
                                        first,
                                        last,
                                        origin};
    SegmentPass<T, I> scalar_pass = vector_pass;
    scalar_pass.carry = carry_scalar.data();
    scalar_pass.cursor = cursor_scalar.data();
    add_segment_runs(vector_pass, replicas, origin, split_row, true);
    add_segment_runs(vector_pass, replicas, split_row, n, true);
    add_segment_runs(scalar_pass, replicas, origin, n, false);
    INFO("segment " << s << " of " << cut.count() << ", B = " << replicas << ", rows from "
                    << origin << ", split at " << split_row);
    REQUIRE(test::bit_difference(carry_vector, carry_scalar) == "");
    REQUIRE(cursor_vector == cursor_scalar);
  }
}

}  // namespace

TEST_CASE("the AVX2 segment runs add as the scalar loop does, bit for bit", "[segment_runs]") {
  const NodeIndex n = 300, columns = 240;
  const Rows rows = test::random_rows(n, columns, 11);
  if (!segment_runs_vectorised<double>(1)) WARN("no AVX2 here: scalar against scalar");
  for (const NodeIndex width : {1, 40, 97}) {  // 240 segments (most runs empty), 6 and 3
    const ColumnSegments narrow(rows.row_ptr, rows.cols, columns, width),
        wide(rows.row_ptr, rows.cols, columns, width, false);
    REQUIRE(narrow.count() == (columns - 1) / width + 1);
    REQUIRE(narrow.narrow());
    REQUIRE(!wide.narrow());
    for (const int replicas : {1, 2}) {
      const std::vector<double> t64 = table<double>(columns, replicas, 5);
      const std::vector<float> t32 = table<float>(columns, replicas, 6);
      for (const NodeIndex origin : {0, 37}) {
        for (const NodeIndex split_row : {origin, origin + 1, NodeIndex{151}}) {
          compare<double, std::uint16_t>(rows, narrow, t64, replicas, origin, split_row);
          compare<float, std::uint16_t>(rows, narrow, t32, replicas, origin, split_row);
          compare<double, NodeIndex>(rows, wide, t64, replicas, origin, split_row);
        }
      }
    }
  }
}

TEST_CASE("the AVX2 segment runs mask the slots past a run's end", "[segment_runs]") {
  // The test above must be able to fail: with a table of ones, row 0's run of 5 entries in
  // segment 0 (place 0, all before its last d mod 4) reads 3 slots past its end in its second
  // block; were they added unmasked, the cos partials would sum to 8, not 5.
  if (!segment_runs_vectorised<double>(1)) {
    WARN("no AVX2 here");
    return;
  }
  const Rows rows{{0, 8, 13}, {0, 1, 2, 3, 4, 9, 10, 11, 0, 1, 2, 3, 4}};
  const ColumnSegments cut(rows.row_ptr, rows.cols, 16, 8);
  REQUIRE(cut.count() == 2);
  const std::vector<double> ones(32, 1.0);
  std::vector<double> carry(16, 0.0);
  std::vector<std::uint32_t> cursor(2);
  const SegmentPass<double, std::uint16_t> pass{
      rows.row_ptr.data(), &cut.runs(), 0,    cut.cols<std::uint16_t>(0), ones.data(), carry.data(),
      cursor.data(),       true,        false};
  add_segment_runs(pass, 1, 0, 1, true);
  double cos_sum = 0;
  for (std::size_t j = 0; j < 4; ++j) cos_sum += carry[2 * j];
  CHECK(cos_sum == 5.0);
}

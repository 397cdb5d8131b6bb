// The wide row loop (dynamics/wide_rows.hpp) forms every row's sums and outputs as the definition
// (kernel_arithmetic.hpp: row_field, coupling_force, order_term, coupling_term), bit for bit:
// partial j over the row's entries j, j + 4, ... of its first 4 floor(d / 4), the last d mod 4
// into partial 0, each from +0.0. Rows of degree 0 to 40 (every tail), 0/1 and weighted rows,
// float64 and float32, 2, 4 and 8 replicas and counts run in groups (3 to 24), in every
// instruction set this CPU runs, over 32- and 16-bit column indices, with and without the terms;
// tables with -0.0 and subnormals. A segment's runs (wide_segment_runs) leave the carried partials
// and cursors of the scalar loop, segment after segment, in 16- and 32-bit segments, for row ranges
// that start anywhere.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "dynamics/column_segments.hpp"
#include "dynamics/kernel_arithmetic.hpp"
#include "dynamics/wide_rows.hpp"
#include "support/bit_difference.hpp"
#include "support/random_rows.hpp"

using namespace hmfnet;

namespace {

using Rows = test::RandomRows;

template <typename T>
std::vector<T> random_values(std::size_t n, double lo, double hi, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> value(lo, hi);
  std::vector<T> v(n);
  for (T& x : v) x = static_cast<T>(value(rng));
  return v;
}

// A row kernel's outputs: g, y and the terms of every row and replica.
struct Outputs {
  std::vector<double> g, y, terms;
  Outputs(std::size_t rows, int replicas)
      : g(rows * static_cast<std::size_t>(replicas)), y(2 * g.size()), terms(2 * g.size()) {}
  bool operator==(const Outputs& o) const {
    const auto same = [](const std::vector<double>& a, const std::vector<double>& b) {
      return a.size() == b.size() &&
             std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
    };
    return same(g, o.g) && same(y, o.y) && same(terms, o.terms);
  }
};

template <typename T>
RowKernelArgs<T> args(const Rows& rows, const std::vector<T>& weights, const std::vector<T>& table,
                      const std::vector<double>& owned, Outputs& out) {
  return {rows.row_ptr.data(), rows.cols.data(), weights.empty() ? nullptr : weights.data(),
          table.data(),        owned.data(),     1.0 / 300.0,
          out.g.data(),        out.y.data(),     out.terms.data()};
}

// The definition, one replica at a time: kernel_arithmetic.hpp's row sum and row outputs.
template <typename T>
void reference_rows(const RowKernelArgs<T>& a, NodeIndex rows, int replicas) {
  for (NodeIndex r = 0; r < rows; ++r) {
    for (int b = 0; b < replicas; ++b) {
      const LocalField y =
          row_field(a.row_ptr[r], a.row_ptr[r + 1], a.cols, a.weights, a.column_cs, replicas, b);
      const auto cell = static_cast<std::size_t>(r) * static_cast<std::size_t>(replicas) +
                        static_cast<std::size_t>(b);
      const double c = a.owned_cs[2 * cell], s = a.owned_cs[2 * cell + 1];
      a.g[cell] = coupling_force(a.inverse_n, c, s, y);
      a.y[2 * cell] = y.re;
      a.y[2 * cell + 1] = y.im;
      a.terms[2 * cell] = order_term(y);
      a.terms[2 * cell + 1] = coupling_term(c, s, y);
    }
  }
}

// A [cos, sin] table of 2B values a column, with -0.0 and subnormals among them.
template <typename T>
std::vector<T> table_of(NodeIndex columns, int replicas, std::uint64_t seed) {
  const std::size_t record = 2 * static_cast<std::size_t>(replicas);
  std::vector<T> table = random_values<T>(record * static_cast<std::size_t>(columns), -1, 1, seed);
  const T special[] = {T(-0.0), std::numeric_limits<T>::denorm_min(),
                       -std::numeric_limits<T>::denorm_min()};
  for (std::size_t k = 0; k < table.size(); k += 37) table[k] = special[(k / 37) % 3];
  return table;
}

template <typename T>
void compare(SincosIsa isa, const Rows& rows, int replicas, bool weighted) {
  const auto n = static_cast<NodeIndex>(rows.row_ptr.size() - 1);
  const std::size_t record = 2 * static_cast<std::size_t>(replicas);
  const std::vector<T> table = table_of<T>(n, replicas, 3);
  const std::vector<T> weights =
      weighted ? random_values<T>(rows.cols.size(), -2, 2, 4) : std::vector<T>{};
  const std::vector<double> owned =
      random_values<double>(record * static_cast<std::size_t>(n), -1, 1, 5);
  Outputs wide(static_cast<std::size_t>(n), replicas), reference = wide;
  reference_rows(args(rows, weights, table, owned, reference), n, replicas);
  wide_rows(args(rows, weights, table, owned, wide), n, replicas, isa);
  INFO(sincos_isa_name(isa) << ", " << sizeof(T) * 8 << "-bit, B = " << replicas
                            << (weighted ? ", weighted" : ", 0/1"));
  REQUIRE(wide == reference);
  // Without the terms (an evaluation whose sums no record reads): the same g and y, the terms'
  // buffer as it was.
  Outputs without(static_cast<std::size_t>(n), replicas);
  std::fill(without.terms.begin(), without.terms.end(), 7.0);
  RowKernelArgs<T> no_terms = args(rows, weights, table, owned, without);
  no_terms.terms = nullptr;
  wide_rows(no_terms, n, replicas, isa);
  CHECK(test::bit_difference(without.g, reference.g) == "");
  CHECK(test::bit_difference(without.y, reference.y) == "");
  CHECK(test::bit_difference(without.terms, std::vector<double>(without.terms.size(), 7.0)) == "");
  // The same rows over 16-bit column indices (narrow_columns.hpp): the same bits.
  const std::vector<std::uint16_t> cols16(rows.cols.begin(), rows.cols.end());
  Outputs narrow(static_cast<std::size_t>(n), replicas);
  const RowKernelArgs<T> wide_args = args(rows, weights, table, owned, narrow);
  const RowKernelArgs<T, std::uint16_t> narrow_args{
      wide_args.row_ptr,   cols16.data(),      wide_args.weights,
      wide_args.column_cs, wide_args.owned_cs, wide_args.inverse_n,
      wide_args.g,         wide_args.y,        wide_args.terms};
  wide_rows(narrow_args, n, replicas, isa);
  CHECK(narrow == reference);
}

// Every segment of `cut` (indices of type I) over rows [origin, n), the carry held from row
// `origin` on, in `isa` (two calls, split at row `split`) and in the scalar loop.
template <typename T, typename I>
void compare_runs(SincosIsa isa, const Rows& rows, const ColumnSegments& cut, int replicas,
                  bool weighted, NodeIndex origin, NodeIndex split) {
  const auto n = static_cast<NodeIndex>(rows.row_ptr.size() - 1);
  const std::vector<T> t = table_of<T>(n, replicas, 8);
  const std::vector<T> weights =
      weighted ? random_values<T>(rows.cols.size(), -2, 2, 9) : std::vector<T>{};
  const T* w = weighted ? weights.data() : nullptr;
  const auto held = static_cast<std::size_t>(n - origin);
  std::vector<T> carry_wide(8 * held * static_cast<std::size_t>(replicas), T(7));
  std::vector<T> carry_scalar = carry_wide;  // the first segment zeroes them
  std::vector<std::uint32_t> cursor_wide(held), cursor_scalar(held);
  for (int s = 0; s < cut.count(); ++s) {
    const T* slice = t.data() + 2 * static_cast<std::ptrdiff_t>(replicas) * cut.first_column(s);
    const SegmentPass<T, I> wide{
        rows.row_ptr.data(), &cut.runs(),        s,      cut.template cols<I>(s), slice,
        carry_wide.data(),   cursor_wide.data(), s == 0, s + 1 == cut.count(),    origin};
    SegmentPass<T, I> scalar = wide;
    scalar.carry = carry_scalar.data();
    scalar.cursor = cursor_scalar.data();
    wide_segment_runs(wide, w, replicas, origin, split, isa);
    wide_segment_runs(wide, w, replicas, split, n, isa);
    if (weighted) {
      scalar_segment_runs<T, 0, true, I>(scalar, w, replicas, origin, n);
    } else {
      scalar_segment_runs<T, 0, false, I>(scalar, w, replicas, origin, n);
    }
    INFO(sincos_isa_name(isa) << ", " << sizeof(T) * 8 << "-bit, B = " << replicas
                              << (weighted ? ", weighted" : ", 0/1") << ", segment " << s << " of "
                              << cut.count() << ", rows from " << origin << ", split at " << split);
    REQUIRE(std::memcmp(carry_wide.data(), carry_scalar.data(), carry_wide.size() * sizeof(T)) ==
            0);
    REQUIRE(cursor_wide == cursor_scalar);
  }
}

}  // namespace

TEST_CASE("the wide segment runs add as the scalar loop does, bit for bit", "[wide_rows]") {
  const NodeIndex n = 200;
  const Rows rows = test::random_rows(n, n, 23);
  const ColumnSegments narrow(rows.row_ptr, rows.cols, n, 37),
      wide(rows.row_ptr, rows.cols, n, 64, false);
  REQUIRE(narrow.count() == 6);
  REQUIRE(!wide.narrow());
  int versions = 0;
  for (const SincosIsa isa : {SincosIsa::avx2, SincosIsa::avx512}) {
    // 2, 4 and 8: versions of their own; the others' records cut into registers (24: three
    // pairs of AVX-512 registers; 13 in float64: a pair, a register and one replica in scalars
    // in AVX-512, three registers and one replica in scalars in AVX2; 3 in float32: scalars).
    for (const int replicas : {2, 4, 8, 3, 5, 13, 16, 24}) {
      for (const bool weighted : {false, true}) {
        for (const NodeIndex origin : {0, 41}) {
          if (wide_loops_serve<double>(replicas, isa)) {
            compare_runs<double, std::uint16_t>(isa, rows, narrow, replicas, weighted, origin, 99);
            compare_runs<double, NodeIndex>(isa, rows, wide, replicas, weighted, origin, origin);
            compare_runs<double, NodeIndex>(isa, rows, wide, replicas, weighted, origin, 120);
            ++versions;
          }
          if (wide_loops_serve<float>(replicas, isa)) {
            compare_runs<float, std::uint16_t>(isa, rows, narrow, replicas, weighted, origin, 150);
            compare_runs<float, NodeIndex>(isa, rows, wide, replicas, weighted, origin, 77);
            ++versions;
          }
        }
      }
    }
  }
  if (versions == 0) WARN("no AVX2 here: the wide segment runs do not run on this CPU");
}

TEST_CASE("the wide row loop sums as the definition, bit for bit", "[wide_rows]") {
  const Rows rows = test::random_rows(300, 300, 17, true);
  int versions = 0;
  for (const SincosIsa isa : {SincosIsa::avx2, SincosIsa::avx512}) {
    for (const int replicas : {2, 4, 8}) {
      for (const bool weighted : {false, true}) {
        if (wide_rows_serve<double>(replicas, isa)) {
          compare<double>(isa, rows, replicas, weighted);
          ++versions;
        }
        if (wide_rows_serve<float>(replicas, isa)) {
          compare<float>(isa, rows, replicas, weighted);
          ++versions;
        }
      }
    }
  }
  if (versions == 0) WARN("no AVX2 here: the wide row loop does not run on this CPU");
  // Counts in groups: each group shape (8, 4, 2 and single replicas, float32 without 2) and
  // several groups of one shape, each group at another offset in the record.
  for (const SincosIsa isa : {SincosIsa::avx2, SincosIsa::avx512}) {
    for (const int replicas : {3, 5, 6, 7, 11, 13, 14, 16, 24}) {
      CHECK(wide_groups_serve<double>(replicas, isa) == sincos_isa_available(isa));
      if (!wide_groups_serve<double>(replicas, isa)) continue;
      for (const bool weighted : {false, true}) {
        compare<double>(isa, rows, replicas, weighted);
        compare<float>(isa, rows, replicas, weighted);
      }
    }
    CHECK_FALSE(wide_groups_serve<double>(8, isa));  // a version of its own
    CHECK_FALSE(wide_groups_serve<float>(1, isa));   // rows_kernel_single
  }
  CHECK_FALSE(wide_groups_serve<double>(3, SincosIsa::baseline));
  // Served wherever the CPU runs the set: a CPU with AVX2 must run the versions above.
  for (const SincosIsa isa : {SincosIsa::avx2, SincosIsa::avx512}) {
    CHECK(wide_rows_serve<double>(8, isa) == sincos_isa_available(isa));
    CHECK(wide_rows_serve<double>(2, isa) == sincos_isa_available(isa));
    CHECK(wide_rows_serve<float>(4, isa) == sincos_isa_available(isa));
  }
  // float32 B = 2 (16-byte records) stays with the baseline loop, and the baseline set has none.
  CHECK_FALSE(wide_rows_serve<float>(2, SincosIsa::avx512));
  CHECK_FALSE(wide_rows_serve<double>(8, SincosIsa::baseline));
  CHECK_FALSE(wide_rows_serve<double>(3, SincosIsa::avx2));
  // The predicate the force's kernel choice and segment rule read: every count but one replica
  // and float32 with two, wherever the CPU runs the set; none in the baseline set.
  for (const SincosIsa isa : {SincosIsa::avx2, SincosIsa::avx512}) {
    const bool here = sincos_isa_available(isa);
    CHECK_FALSE(wide_loops_serve<double>(1, isa));
    CHECK_FALSE(wide_loops_serve<float>(1, isa));
    CHECK_FALSE(wide_loops_serve<float>(2, isa));
    for (int replicas = 2; replicas <= 24; ++replicas) {
      INFO("replicas " << replicas);
      CHECK(wide_loops_serve<double>(replicas, isa) == here);
      if (replicas > 2) CHECK(wide_loops_serve<float>(replicas, isa) == here);
    }
  }
  CHECK_FALSE(wide_loops_serve<double>(8, SincosIsa::baseline));
  CHECK_FALSE(wide_loops_serve<float>(13, SincosIsa::baseline));
}

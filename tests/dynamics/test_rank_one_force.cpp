// The rank-one force (dynamics/rank_one_force.hpp) forms Z, g and the order and coupling sums in
// fused passes, without storing the per-row terms. These tests form every quantity the plain way
// (sincos, the per-row terms stored, then summed as the library has always summed them: blocks of
// 2048 rows from 0, each in row order, then the blocks in order, written out here rather than
// taken from OrderedColumnSums, so that a change of that order fails here too) and require the
// same bits: g and the two sums from the fused passes, and the local fields (formed on demand),
// for one replica (the scalar path), two (one SSE2 pair), an odd count (pairs and one scalar
// lane), 16 (two whole work items of 8), with and without the diagonal, with weights, over fewer
// rows than one block and over rows that are not a whole number of blocks; in teams of one and
// two threads.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "dynamics/rank_one_force.hpp"
#include "dynamics/sincos.hpp"
#include "dynamics/team.hpp"
#include "dynamics/thread_choice.hpp"
#include "parallel/parallel_session.hpp"
#include "support/bit_difference.hpp"

using namespace hmfnet;

namespace {

// Column sums of rows x width values in the order every force of the library uses (the block
// size is the one the results have been produced with since the first version).
std::vector<double> block_sums(const std::vector<double>& values, std::size_t rows,
                               std::size_t width) {
  constexpr std::size_t block = 2048;
  std::vector<double> out(width, 0.0);
  for (std::size_t first = 0; first < rows; first += block) {
    std::vector<double> partial(width, 0.0);
    for (std::size_t r = first; r < std::min(rows, first + block); ++r)
      for (std::size_t j = 0; j < width; ++j) partial[j] += values[r * width + j];
    for (std::size_t j = 0; j < width; ++j) out[j] += partial[j];
  }
  return out;
}

struct Evaluation {
  std::vector<double> g, y;
  ForceSums sums;
};

// What the force must give, formed the plain way: y_n = a_n Z - [no diagonal] a_n^2 e^{i theta_n}
// with Z = sum_m a_m e^{i theta_m} (ordered sums of stored a [cos, sin], then over ranks), g_n = (c
// Im y - s Re y) / N, and the ordered sums of the stored [|y_n|, c Re y + s Im y].
Evaluation plain(const RankOneStructure& st, const RotorState& s) {
  const auto w = static_cast<std::size_t>(s.replicas), rows = static_cast<std::size_t>(s.rows);
  const double inverse_n = 1.0 / static_cast<double>(st.a.size());
  std::vector<double> cs(2 * rows * w), scaled(2 * rows * w), z, terms(2 * rows * w), out;
  sincos_interleaved(s.theta.data(), rows * w, cs.data());
  for (std::size_t k = 0; k < 2 * rows * w; ++k) scaled[k] = st.a[k / (2 * w)] * cs[k];
  z = block_sums(scaled, rows, 2 * w);
  // Over ranks, as the force does (here every rank takes every row).
  ParallelSession::sum_in_place(z);
  Evaluation e;
  e.g.resize(rows * w);
  e.y.resize(2 * rows * w);
  for (std::size_t k = 0; k < rows * w; ++k) {
    const double a = st.a[k / w], c = cs[2 * k], sn = cs[2 * k + 1];
    double yc = a * z[2 * (k % w)], ys = a * z[2 * (k % w) + 1];
    if (!st.diagonal) {
      yc -= a * a * c;
      ys -= a * a * sn;
    }
    e.g[k] = inverse_n * (c * ys - sn * yc);
    e.y[2 * k] = yc;
    e.y[2 * k + 1] = ys;
    terms[2 * k] = std::sqrt(yc * yc + ys * ys);
    terms[2 * k + 1] = c * yc + sn * ys;
  }
  out = block_sums(terms, rows, 2 * w);
  for (std::size_t b = 0; b < w; ++b) {
    e.sums.order.push_back(out[2 * b]);
    e.sums.coupling.push_back(out[2 * b + 1]);
  }
  return e;
}

Evaluation fused(const RankOneStructure& st, const RotorState& s, int threads) {
  const ThreadCountScope scope(threads);
  RankOneForce force(st, 0, s.rows);
  Evaluation e;
  force.prepare(s, e.g, e.sums);
  in_team([&] { force.evaluate(s, e.g, e.sums); });
  e.y = force.local_fields();
  return e;
}

RotorState replicas(NodeIndex rows, int count) {
  std::vector<InitialCondition> ic;
  for (int b = 0; b < count; ++b)
    ic.push_back({0.5 * b, 0.3 + 0.1 * b, static_cast<std::uint64_t>(40 + b)});
  RotorState s = initial_state(0, rows, ic);
  // Partly ordered phases, so that Z is not a sum of noise only.
  for (std::size_t k = 0; k < s.theta.size(); ++k) s.theta[k] *= 0.25;
  return s;
}

}  // namespace

TEST_CASE("Rank-one force: the fused passes give the plain sums bit for bit", "[rank_one]") {
  // 1000 rows: one short block; 5000: three blocks of 2048 rows, the last one short.
  for (const NodeIndex rows : {1000, 5000}) {
    for (const bool diagonal : {true, false}) {
      for (const bool weighted : {false, true}) {
        RankOneStructure st;
        st.diagonal = diagonal;
        for (NodeIndex n = 0; n < rows; ++n) st.a.push_back(weighted ? 1.0 + (n % 7) / 10.0 : 1.0);
        for (const int count : {1, 2, 3, 11, 16}) {
          const RotorState s = replicas(rows, count);
          const Evaluation expected = plain(st, s);
          for (const int threads : {1, 2}) {
            INFO("rows " << rows << ", diagonal " << diagonal << ", weighted " << weighted
                         << ", replicas " << count << ", threads " << threads);
            const Evaluation got = fused(st, s, threads);
            CHECK(test::bit_difference(got.g, expected.g) == "");
            CHECK(test::bit_difference(got.y, expected.y) == "");
            CHECK(test::bit_difference(got.sums.order, expected.sums.order) == "");
            CHECK(test::bit_difference(got.sums.coupling, expected.sums.coupling) == "");
          }
        }
      }
    }
  }
}

TEST_CASE("Rank-one force: the local fields follow the last evaluation", "[rank_one]") {
  // Formed on demand and kept until the next evaluation: asked once after the first
  // evaluation, they must be formed again after a second one at other phases (in a team).
  const RankOneStructure st{std::vector<double>(300, 1.0), false};
  RankOneForce force(st, 0, 300);
  RotorState s = replicas(300, 2);
  std::vector<double> g;
  ForceSums sums;
  force.evaluate(s, g, sums);
  CHECK(test::bit_difference(force.local_fields(), plain(st, s).y) == "");
  for (double& theta : s.theta) theta += 0.5;
  const ThreadCountScope two(2);
  force.prepare(s, g, sums);
  in_team([&] { force.evaluate(s, g, sums); });
  CHECK(test::bit_difference(force.local_fields(), plain(st, s).y) == "");
}

// Device ensembles spread over ranks (rank_exchange.hpp), threads standing for the MPI ranks
// (thread_ranks.hpp), against the CPU's arithmetic in its order (host_ensemble.hpp). The sparse
// force over 2 and 3 ranks: every rank's rows step with the one-rank run's bits (each row is
// summed in its global column order whatever the split), and each rank's order sums, fields and
// record sums are the CPU's over its rows. The rank-one force over 2 ranks: Z per rank and then
// over the ranks as rank_one_force.cpp forms it; split at a 2048-row block, the one-rank run's
// bits. A rank the device refuses stops every rank with its message, no hang.
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "dynamics/cuda/rank_one_ensemble.hpp"
#include "dynamics/cuda/sparse_ensemble.hpp"
#include "host_ensemble.hpp"
#include "thread_ranks.hpp"

using namespace hmfnet;
using hmfnet::gpu_test::differing;
using hmfnet::gpu_test::HostEnsemble;

namespace {

// One rank's results, as each rank's device ensemble reads them back.
struct RankRun {
  std::vector<double> theta, p, order, fields;
  cuda::EnsembleSums sums;
};

// The run's start and schedule, the same for every split.
struct Schedule {
  std::vector<double> theta, p, K;
  SplittingCoefficients splitting;
  double h = 0.05;
  std::vector<std::int64_t> chunks;  // advance's calls, each with the order sums
};

Schedule schedule(std::int64_t n, int replicas, SplittingCoefficients c,
                  std::vector<std::int64_t> chunks) {
  Schedule s;
  gpu_test::waterbag(n, replicas, 0.6, 23, s.theta, s.p);
  for (int b = 0; b < replicas; ++b) s.K.push_back(1.0 + 2.5 * b);  // a K per replica
  s.splitting = std::move(c);
  s.chunks = std::move(chunks);
  return s;
}

// Rows [first, first + rows) of rows x replicas values (x width each).
std::vector<double> row_slice(const std::vector<double>& v, std::int64_t first, std::int64_t rows,
                              int replicas, int width = 1) {
  const auto per_row = static_cast<std::ptrdiff_t>(replicas) * width;
  return {v.begin() + first * per_row, v.begin() + (first + rows) * per_row};
}

// Rank r's part of the host's order sums (steps x ranks x replicas).
std::vector<double> rank_order(const std::vector<double>& order, std::size_t ranks, std::size_t r,
                               int replicas) {
  const auto w = static_cast<std::size_t>(replicas);
  std::vector<double> part;
  for (std::size_t at = r * w; at < order.size(); at += ranks * w) {
    part.insert(part.end(), order.begin() + static_cast<std::ptrdiff_t>(at),
                order.begin() + static_cast<std::ptrdiff_t>(at + w));
  }
  return part;
}

// What every rank's thread does with its ensemble: the schedule from its rows' start, the fields
// kept, the state, fields and sums read back. Every call is collective over the ranks.
void run_rank(cuda::DeviceEnsemble& e, const Schedule& s, std::int64_t first, RankRun& out) {
  const std::int64_t rows = e.rows();
  e.set_coupling(s.K);
  e.keep_fields();
  e.set_state(row_slice(s.theta, first, rows, e.replicas()),
              row_slice(s.p, first, rows, e.replicas()));
  for (const std::int64_t chunk : s.chunks) e.advance(s.splitting, s.h, chunk, &out.order);
  e.get_state(out.theta, out.p);
  e.fields(out.fields);
  out.sums = e.sums();
}

std::vector<std::int64_t> first_rows(const std::vector<std::int64_t>& rank_rows) {
  std::vector<std::int64_t> first{0};
  for (const std::int64_t r : rank_rows) first.push_back(first.back() + r);
  return first;
}

// The sparse ensembles of `rank_rows` rows a rank, over thread ranks.
std::vector<RankRun> sparse_over_ranks(const cuda::HostCsr& net,
                                       const std::vector<std::int64_t>& rank_rows, int replicas,
                                       cuda::DevicePrecision precision, const Schedule& s) {
  const std::vector<std::int64_t> first = first_rows(rank_rows);
  std::vector<gpu_test::RankRows> blocks;
  for (std::size_t r = 0; r < rank_rows.size(); ++r)
    blocks.push_back(gpu_test::rank_rows(net, first[r], first[r + 1]));
  gpu_test::ThreadRanks ranks(static_cast<int>(rank_rows.size()), net.rows);
  std::vector<RankRun> out(rank_rows.size());
  ranks.run([&](int r) {
    const auto k = static_cast<std::size_t>(r);
    cuda::SparseEnsemble e(blocks[k].csr, replicas, precision, ranks.sparse(blocks[k]));
    run_rank(e, s, first[k], out[k]);
  });
  return out;
}

// The rank-one ensembles of A = a a^T of `rank_rows` rows a rank, over thread ranks.
std::vector<RankRun> rank_one_over_ranks(const std::vector<double>& a, bool diagonal,
                                         const std::vector<std::int64_t>& rank_rows, int replicas,
                                         const Schedule& s) {
  const std::vector<std::int64_t> first = first_rows(rank_rows);
  gpu_test::ThreadRanks ranks(static_cast<int>(rank_rows.size()),
                              static_cast<std::int64_t>(a.size()));
  std::vector<RankRun> out(rank_rows.size());
  ranks.run([&](int r) {
    const auto k = static_cast<std::size_t>(r);
    const std::vector<double> mine(a.begin() + first[k], a.begin() + first[k + 1]);
    cuda::RankOneEnsemble e(mine, diagonal, replicas, ranks.rank_one(r));
    run_rank(e, s, first[k], out[k]);
  });
  return out;
}

// The host's run of the same schedule.
void host_run(HostEnsemble& host, const Schedule& s, std::vector<double>& order) {
  host.K = s.K;
  host.set_state(s.theta, s.p);
  std::int64_t steps = 0;
  for (const std::int64_t chunk : s.chunks) steps += chunk;
  host.advance(s.splitting, s.h, steps, &order);
}

// Each rank against the host's run spread over the same ranks.
void require_ranks_match(const std::vector<RankRun>& ranks, const HostEnsemble& host,
                         const std::vector<double>& host_order,
                         const std::vector<std::int64_t>& rank_rows, int replicas) {
  const std::vector<std::int64_t> first = first_rows(rank_rows);
  const std::vector<double> host_fields = host.fields();
  for (std::size_t r = 0; r < ranks.size(); ++r) {
    INFO("rank " << r << " of " << ranks.size() << ", rows " << first[r] << " to "
                 << first[r + 1] - 1);
    const RankRun& d = ranks[r];
    CHECK(differing(d.theta, row_slice(host.theta, first[r], rank_rows[r], replicas)) == 0);
    CHECK(differing(d.p, row_slice(host.p, first[r], rank_rows[r], replicas)) == 0);
    CHECK(differing(d.fields, row_slice(host_fields, first[r], rank_rows[r], replicas, 2)) == 0);
    CHECK(differing(d.order, rank_order(host_order, ranks.size(), r, replicas)) == 0);
    const cuda::EnsembleSums h = host.rank_sums(r);
    CHECK(differing(d.sums.order, h.order) == 0);
    CHECK(differing(d.sums.coupling, h.coupling) == 0);
    CHECK(differing(d.sums.kinetic, h.kinetic) == 0);
    CHECK(differing(d.sums.momentum, h.momentum) == 0);
    CHECK(differing(d.sums.momentum_scale, h.momentum_scale) == 0);
  }
}

// The network of the test: N = 1500, degree 12, weighted (A_nm in [0.5, 2]) or 0/1.
cuda::HostCsr network(bool weighted) {
  cuda::HostCsr net = gpu_test::random_network(1500, 12.0, 5);
  if (!weighted) return net;
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> weight(0.5, 2.0);
  for (std::size_t k = 0; k < net.columns.size(); ++k) net.weights.push_back(weight(rng));
  return net;
}

}  // namespace

TEST_CASE(
    "the sparse step over 2 and 3 ranks: each rank's rows have the one-rank bits, its sums the "
    "CPU's over its rows",
    "[gpu][ranks]") {
  // Splits that cut the 2048-row sum blocks and the ghosts differently; 1 replica takes the
  // four-threads-a-row kernel, 3 the one-thread one.
  const std::vector<std::vector<std::int64_t>> splits = {{700, 800}, {400, 600, 500}};
  for (const bool weighted : {false, true}) {
    const cuda::HostCsr net = network(weighted);
    for (const bool float32 : {false, true}) {
      for (const int replicas : {1, 3}) {
        const Schedule s = schedule(net.rows, replicas, leap_frog_coefficients(), {1, 25, 34});
        for (const auto& split : splits) {
          INFO((weighted ? "weighted" : "0/1")
               << ", " << (float32 ? "float32" : "float64") << ", " << replicas << " replicas, "
               << split.size() << " ranks");
          HostEnsemble host(net, replicas, float32);
          host.spread_over(split);
          std::vector<double> host_order;
          host_run(host, s, host_order);
          const auto ranks = sparse_over_ranks(
              net, split, replicas,
              float32 ? cuda::DevicePrecision::float32 : cuda::DevicePrecision::float64, s);
          require_ranks_match(ranks, host, host_order, split, replicas);
        }
      }
    }
  }
}

TEST_CASE("the sparse step over 2 ranks with yoshida4: the one-rank bits", "[gpu][ranks]") {
  const cuda::HostCsr net = network(true);
  const Schedule s = schedule(net.rows, 3, yoshida4_coefficients(), {10, 20});
  const std::vector<std::int64_t> split = {900, 600};
  HostEnsemble host(net, 3, false);
  host.spread_over(split);
  std::vector<double> host_order;
  host_run(host, s, host_order);
  require_ranks_match(sparse_over_ranks(net, split, 3, cuda::DevicePrecision::float64, s), host,
                      host_order, split, 3);
}

TEST_CASE(
    "the rank-one step over 2 ranks: Z per rank then over the ranks, the CPU's bits; split at a "
    "sum block, the one-rank run's",
    "[gpu][ranks]") {
  // N = 5000: rank 0 of {2600, 2400} sums Z in blocks of 2048 and 552 rows, rank 1 of 2048 and
  // 352, so the Z of 2 ranks differs from one rank's in its last bits; {4096, 904} keeps the
  // blocks of one rank, and with them its bits.
  constexpr std::int64_t n = 5000;
  std::vector<double> a(n);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> spread(0.5, 1.5);
  for (double& x : a) x = spread(rng);
  const Schedule s = schedule(n, 3, leap_frog_coefficients(), {1, 30, 19});
  for (const bool diagonal : {true, false}) {
    HostEnsemble one_rank = HostEnsemble::rank_one(a, 3, diagonal);
    std::vector<double> one_rank_order;
    host_run(one_rank, s, one_rank_order);
    for (const auto& split :
         {std::vector<std::int64_t>{2600, 2400}, std::vector<std::int64_t>{4096, 904}}) {
      INFO((diagonal ? "with" : "without")
           << " the diagonal, rows " << split[0] << " and " << split[1]);
      HostEnsemble host = HostEnsemble::rank_one(a, 3, diagonal);
      host.spread_over(split);
      std::vector<double> host_order;
      host_run(host, s, host_order);
      require_ranks_match(rank_one_over_ranks(a, diagonal, split, 3, s), host, host_order, split,
                          3);
      const std::size_t moved = differing(host.theta, one_rank.theta);
      if (split[0] % 2048 == 0) {
        CHECK(moved == 0);
      } else {
        // The split's own Z: if this ever read 0, the test above would no longer tell the
        // per-rank sum from one rank's.
        CHECK(moved > 0);
      }
    }
  }
}

TEST_CASE("a rank the device refuses stops every rank with its message, no hang", "[gpu][ranks]") {
  // Rank 1 holds no rows (device ensembles need at least one): rank 0, already waiting in the
  // first exchange, must leave it.
  const cuda::HostCsr net = network(false);
  const Schedule s = schedule(net.rows, 3, leap_frog_coefficients(), {5});
  CHECK_THROWS_WITH(sparse_over_ranks(net, {1500, 0}, 3, cuda::DevicePrecision::float64, s),
                    Catch::Contains("rows 0 outside [1, 2^31 - 1]"));
  CHECK_THROWS_WITH(rank_one_over_ranks(std::vector<double>(1500, 1.0), false, {1500, 0}, 3, s),
                    Catch::Contains("rows 0 outside [1, 2^31 - 1]"));
}

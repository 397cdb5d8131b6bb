#include "network/erdos_renyi.hpp"

#include <omp.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "core/error.hpp"
#include "core/index_cast.hpp"
#include "core/random.hpp"

namespace hmfnet {

namespace {

// Upper neighbours m > n of row n, in increasing order, by geometric skipping: the gap to the
// next linked pair is Geometric(q), drawn as floor(log U / log(1 - q)).
template <class Sink>
void upper_row(NodeIndex n, NodeIndex rows, double log_miss, std::uint64_t seed, Sink&& sink) {
  Rng rng(seed, static_cast<std::uint64_t>(n));
  std::int64_t m = n;
  const std::int64_t last = rows - 1;
  for (;;) {
    const double skip = std::floor(std::log(rng.uniform_open_zero()) / log_miss);
    if (!(skip < static_cast<double>(last - m))) break;  // also stops on NaN
    m += 1 + static_cast<std::int64_t>(skip);
    sink(static_cast<NodeIndex>(m));
  }
}

struct UpperTriangle {
  std::vector<EdgeOffset> count;               // upper entries per row
  std::vector<std::vector<NodeIndex>> blocks;  // one per thread, rows in block order
  std::vector<NodeIndex> block_first;
};

UpperTriangle generate_upper(const ErdosRenyiParameters& p, double log_miss) {
  UpperTriangle u;
  u.count.assign(idx(p.n), 0);
  const int threads = omp_get_max_threads();
  u.blocks.resize(idx(threads));
  u.block_first.resize(idx(threads) + 1);
  for (int t = 0; t <= threads; ++t) {
    u.block_first[idx(t)] = static_cast<NodeIndex>(static_cast<std::int64_t>(p.n) * t / threads);
  }
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (int t = 0; t < threads; ++t) {
    auto& out = u.blocks[idx(t)];
    for (NodeIndex n = u.block_first[idx(t)]; n < u.block_first[idx(t) + 1]; ++n) {
      const std::size_t before = out.size();
      upper_row(n, p.n, log_miss, p.seed, [&out](NodeIndex m) { out.push_back(m); });
      u.count[idx(n)] = static_cast<EdgeOffset>(out.size() - before);
    }
  }
  return u;
}

void require_valid(const ErdosRenyiParameters& p) {
  if (p.n < 1) throw ParameterError("n", std::to_string(p.n), "n >= 1");
  if (!(p.q >= 0.0 && p.q <= 1.0)) throw ParameterError("q", std::to_string(p.q), "0 <= q <= 1");
}

class ErdosRenyiSource final : public EdgeSource {
 public:
  explicit ErdosRenyiSource(const ErdosRenyiParameters& p) : m_p(p), m_log_miss(std::log1p(-p.q)) {}
  NodeIndex nodes() const override { return m_p.n; }
  std::int64_t units() const override { return m_p.n; }
  double work_before(std::int64_t k) const override {
    // Pairs {i, j > i} with i < k: k (N - 1) - k (k - 1) / 2.
    const auto kk = static_cast<double>(k);
    return kk * (m_p.n - 1) - kk * (kk - 1.0) / 2.0;
  }
  void emit(std::int64_t k, std::vector<Edge>& out) const override {
    if (m_p.q == 0.0) return;
    const auto row = static_cast<NodeIndex>(k);
    upper_row(row, m_p.n, m_log_miss, m_p.seed,
              [&out, row](NodeIndex m) { out.emplace_back(row, m); });
  }

 private:
  ErdosRenyiParameters m_p;
  double m_log_miss;  // log(1 - q): -inf for q = 1, every skip 0
};

}  // namespace

double erdos_renyi_probability(NodeIndex n, double mean_degree) {
  if (n < 2) throw ParameterError("n", std::to_string(n), "n >= 2 for a mean degree");
  if (!(mean_degree >= 0.0 && mean_degree <= n - 1)) {
    throw ParameterError("mean degree", std::to_string(mean_degree), "0 <= ||d|| <= N-1");
  }
  return mean_degree / (n - 1);
}

std::unique_ptr<EdgeSource> erdos_renyi_source(const ErdosRenyiParameters& params) {
  require_valid(params);
  return std::make_unique<ErdosRenyiSource>(params);
}

Network erdos_renyi(const ErdosRenyiParameters& p) {
  require_valid(p);
  const double log_miss = std::log1p(-p.q);  // -inf for q = 1: every skip is 0
  UpperTriangle u = p.q > 0.0 ? generate_upper(p, log_miss) : UpperTriangle{};
  if (p.q == 0.0) u.count.assign(idx(p.n), 0);

  // Full matrix = U + U^T. Row n: the lower part (from rows i < n, increasing i) then the upper
  // part (increasing m): sorted without a sort.
  std::vector<EdgeOffset> lower(idx(p.n), 0);
  for (const auto& block : u.blocks)
    for (const NodeIndex m : block) ++lower[idx(m)];
  std::vector<EdgeOffset> row_ptr(idx(p.n) + 1, 0);
  for (std::size_t n = 0; n < idx(p.n); ++n) row_ptr[n + 1] = row_ptr[n] + lower[n] + u.count[n];
  std::vector<NodeIndex> cols(idx(row_ptr.back()));
  std::vector<EdgeOffset> next_lower(row_ptr.begin(), row_ptr.end() - 1);
  for (std::size_t t = 0; t < u.blocks.size(); ++t) {
    const NodeIndex* src = u.blocks[t].data();
    for (NodeIndex n = u.block_first[t]; n < u.block_first[t + 1]; ++n) {
      const std::size_t c = idx(u.count[idx(n)]);
      if (c > 0) {
        std::memcpy(&cols[idx(row_ptr[idx(n)] + lower[idx(n)])], src, c * sizeof(NodeIndex));
      }
      for (std::size_t k = 0; k < c; ++k) cols[idx(next_lower[idx(src[k])]++)] = n;
      src += c;
    }
  }
  return Network::from_trusted_csr(p.n, std::move(row_ptr), std::move(cols));
}

}  // namespace hmfnet

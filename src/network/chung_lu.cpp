#include "network/chung_lu.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <iterator>
#include <numeric>

#include "core/error.hpp"
#include "core/random.hpp"

namespace hmfnet {

namespace {

// Stream ids: targets use stream 0 of a seed derived from `seed` so they never coincide with
// the per-node link streams below.
constexpr std::uint64_t k_target_seed_salt = 0x5f3759df2545f491ULL;

double link(LinkProbability kind, double x) {
  switch (kind) {
    case LinkProbability::capped:
      return std::min(1.0, x);
    case LinkProbability::poisson:
      return -std::expm1(-x);
    case LinkProbability::odds:
      return x / (1.0 + x);
  }
  return 0.0;
}

void check_law(const PowerLaw& law) {
  if (!(law.alpha > 2.0) || !std::isfinite(law.alpha)) {
    throw ParameterError("alpha", std::to_string(law.alpha), "alpha > 2 (finite mean degree)");
  }
  if (!(law.d_min > 0.0) || !std::isfinite(law.d_min)) {
    throw ParameterError("d_min", std::to_string(law.d_min), "d_min > 0");
  }
  if (!(law.cutoff > law.d_min)) {
    throw ParameterError("cutoff", std::to_string(law.cutoff), "cutoff > d_min");
  }
}

class ChungLuSource final : public EdgeSource {
 public:
  ChungLuSource(const std::vector<double>& targets, LinkProbability kind, std::uint64_t seed)
      : m_kind(kind), m_seed(seed), m_order(targets.size()), m_sorted(targets.size()) {
    m_total = std::accumulate(targets.begin(), targets.end(), 0.0);
    std::iota(m_order.begin(), m_order.end(), 0);
    std::stable_sort(m_order.begin(), m_order.end(), [&](NodeIndex a, NodeIndex b) {
      return targets[static_cast<std::size_t>(a)] > targets[static_cast<std::size_t>(b)];
    });
    for (std::size_t a = 0; a < m_order.size(); ++a) {
      m_sorted[a] = targets[static_cast<std::size_t>(m_order[a])];
    }
    // Expected edges of position a, bounded by w_a (sum of the smaller targets) / S.
    m_work_before.assign(m_order.size() + 1, 0.0);
    double after = m_total;
    for (std::size_t a = 0; a < m_order.size(); ++a) {
      after -= m_sorted[a];
      const double expected = m_total > 0.0 ? m_sorted[a] * std::max(after, 0.0) / m_total : 0.0;
      m_work_before[a + 1] = m_work_before[a] + expected + 1.0;  // + 1: the unit's own cost
    }
  }
  NodeIndex nodes() const override { return static_cast<NodeIndex>(m_order.size()); }
  std::int64_t units() const override { return nodes(); }
  double work_before(std::int64_t k) const override {
    return m_work_before[static_cast<std::size_t>(k)];
  }

  void emit(std::int64_t a, std::vector<Edge>& out) const override {
    const std::int64_t n = nodes();
    if (a + 1 >= n || !(m_total > 0.0)) return;
    const NodeIndex u = m_order[static_cast<std::size_t>(a)];
    Rng rng(m_seed, static_cast<std::uint64_t>(u));
    const double scale = w_at(a) / m_total;
    std::int64_t b = a + 1;
    double p = link(m_kind, scale * w_at(b));
    // Miller & Hagberg (2011): skip Geometric(p) candidates, p an upper bound of every later
    // probability (targets decrease along the order), then accept with the ratio q / p.
    while (b < n && p > 0.0) {
      if (p < 1.0) {
        const double skip = std::floor(std::log(rng.uniform_open_zero()) / std::log1p(-p));
        if (!(skip < static_cast<double>(n - b))) break;
        b += static_cast<std::int64_t>(skip);
      }
      const double q = link(m_kind, scale * w_at(b));
      if (rng.uniform() < q / p) out.emplace_back(u, m_order[static_cast<std::size_t>(b)]);
      p = q;
      ++b;
    }
  }

 private:
  double w_at(std::int64_t position) const { return m_sorted[static_cast<std::size_t>(position)]; }

  LinkProbability m_kind;
  std::uint64_t m_seed;
  double m_total = 0.0;
  std::vector<NodeIndex> m_order;  // nodes by decreasing target (stable)
  std::vector<double> m_sorted;    // targets in that order
  std::vector<double> m_work_before;
};

}  // namespace

namespace {

// In the order of the enumerators of LinkProbability.
constexpr const char* k_link_names[] = {"capped", "poisson", "odds"};

}  // namespace

LinkProbability link_probability_from_name(const std::string& name) {
  for (std::size_t k = 0; k < std::size(k_link_names); ++k) {
    if (name == k_link_names[k]) return static_cast<LinkProbability>(k);
  }
  throw ParameterError("link probability", name, "capped, poisson, odds");
}

std::string link_probability_name(LinkProbability kind) {
  return k_link_names[static_cast<std::size_t>(kind)];
}

double power_law_mean(const PowerLaw& law) {
  check_law(law);
  const double a = law.alpha;
  const double x = law.d_min / law.cutoff;  // 0 without a cutoff
  return law.d_min * (a - 1.0) / (a - 2.0) * (1.0 - std::pow(x, a - 2.0)) /
         (1.0 - std::pow(x, a - 1.0));
}

double power_law_d_min_for_mean(double alpha, double mean_degree, double cutoff) {
  if (!(mean_degree > 0.0)) {
    throw ParameterError("mean degree", std::to_string(mean_degree), "> 0");
  }
  const double untruncated = mean_degree * (alpha - 2.0) / (alpha - 1.0);
  check_law({alpha, untruncated, std::numeric_limits<double>::infinity()});
  if (std::isinf(cutoff)) return untruncated;
  if (!(cutoff > mean_degree)) {
    throw ParameterError("cutoff", std::to_string(cutoff), "cutoff > mean degree");
  }
  // The truncated mean rises monotonically with d_min on (0, cutoff): bracket [untruncated, D].
  const auto f = [&](double d_min) { return power_law_mean({alpha, d_min, cutoff}) - mean_degree; };
  boost::uintmax_t iterations = 200;
  const auto r = boost::math::tools::toms748_solve(
      f, untruncated, mean_degree, boost::math::tools::eps_tolerance<double>(50), iterations);
  return 0.5 * (r.first + r.second);
}

std::vector<double> power_law_targets(NodeIndex n, const PowerLaw& law, std::uint64_t seed) {
  check_law(law);
  if (n < 1) throw ParameterError("n", std::to_string(n), "n >= 1");
  Rng rng(seed ^ k_target_seed_salt, 0);
  const double a1 = law.alpha - 1.0;
  // Inverse CDF of the truncated Pareto: d = d_min [1 - U (1 - (d_min/cutoff)^(a-1))]^(-1/(a-1)).
  const double tail = 1.0 - std::pow(law.d_min / law.cutoff, a1);
  std::vector<double> w(static_cast<std::size_t>(n));
  for (auto& value : w) value = law.d_min * std::pow(1.0 - rng.uniform() * tail, -1.0 / a1);
  return w;
}

std::unique_ptr<EdgeSource> chung_lu_source(const std::vector<double>& targets,
                                            LinkProbability link, std::uint64_t seed) {
  if (targets.empty()) throw ParameterError("n", "0", "n >= 1");
  for (const double w : targets) {
    if (!(w >= 0.0) || !std::isfinite(w)) {
      throw ParameterError("target degree", std::to_string(w), "finite and >= 0");
    }
  }
  return std::make_unique<ChungLuSource>(targets, link, seed);
}

Network chung_lu(const std::vector<double>& targets, LinkProbability link, std::uint64_t seed) {
  return network_from_source(*chung_lu_source(targets, link, seed));
}

}  // namespace hmfnet

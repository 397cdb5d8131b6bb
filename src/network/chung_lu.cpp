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

Network chung_lu(const std::vector<double>& targets, LinkProbability kind, std::uint64_t seed) {
  const auto n = static_cast<NodeIndex>(targets.size());
  if (n < 1) throw ParameterError("n", "0", "n >= 1");
  for (const double w : targets) {
    if (!(w >= 0.0) || !std::isfinite(w)) {
      throw ParameterError("target degree", std::to_string(w), "finite and >= 0");
    }
  }
  const double total = std::accumulate(targets.begin(), targets.end(), 0.0);
  std::vector<NodeIndex> order(targets.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](NodeIndex a, NodeIndex b) {
    return targets[static_cast<std::size_t>(a)] > targets[static_cast<std::size_t>(b)];
  });
  std::vector<std::pair<NodeIndex, NodeIndex>> edges;
  const auto w_at = [&](std::int64_t pos) {
    return targets[static_cast<std::size_t>(order[static_cast<std::size_t>(pos)])];
  };
  for (std::int64_t a = 0; a + 1 < n && total > 0.0; ++a) {
    const NodeIndex u = order[static_cast<std::size_t>(a)];
    Rng rng(seed, static_cast<std::uint64_t>(u));
    const double scale = w_at(a) / total;
    std::int64_t b = a + 1;
    double p = link(kind, scale * w_at(b));
    // Miller & Hagberg (2011): skip Geometric(p) candidates, p an upper bound of every later
    // probability (targets decrease along `order`), then accept with the ratio q / p.
    while (b < n && p > 0.0) {
      if (p < 1.0) {
        const double skip = std::floor(std::log(rng.uniform_open_zero()) / std::log1p(-p));
        if (!(skip < static_cast<double>(n - b))) break;
        b += static_cast<std::int64_t>(skip);
      }
      const double q = link(kind, scale * w_at(b));
      if (rng.uniform() < q / p) edges.emplace_back(u, order[static_cast<std::size_t>(b)]);
      p = q;
      ++b;
    }
  }
  return Network::from_undirected_edges(n, edges);
}

}  // namespace hmfnet

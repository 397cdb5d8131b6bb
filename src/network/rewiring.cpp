#include "network/rewiring.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/random.hpp"
#include "network/degree_statistics.hpp"

namespace hmfnet {

namespace {

using Edge = std::pair<NodeIndex, NodeIndex>;

std::uint64_t key(NodeIndex u, NodeIndex v) {
  const auto lo = static_cast<std::uint64_t>(std::min(u, v));
  const auto hi = static_cast<std::uint64_t>(std::max(u, v));
  return (hi << 32) | lo;
}

struct EdgeSet {
  std::vector<Edge> edges;
  std::unordered_set<std::uint64_t> present;
};

EdgeSet edge_set(const Network& net) {
  EdgeSet s;
  s.edges.reserve(static_cast<std::size_t>(net.edges()));
  for (NodeIndex i = 0; i < net.size(); ++i) {
    for (const RowEntry entry : net.row(i))
      if (entry.col > i) s.edges.emplace_back(i, entry.col);
  }
  s.present.reserve(2 * s.edges.size());
  for (const auto& [u, v] : s.edges) s.present.insert(key(u, v));
  return s;
}

// Change of sum over ordered pairs of d_u d_v (= d^T A d) when {a,b},{c,d} become {a,x},{b,y}.
double change(const std::vector<double>& deg, NodeIndex a, NodeIndex b, NodeIndex c, NodeIndex d,
              NodeIndex x, NodeIndex y) {
  const auto D = [&](NodeIndex i) { return deg[static_cast<std::size_t>(i)]; };
  return 2.0 * (D(a) * D(x) + D(b) * D(y) - D(a) * D(b) - D(c) * D(d));
}

void check_input(const Network& network, const RewiringParameters& p) {
  if (network.weighted()) {
    throw ParameterError("network", "weighted", "rewiring needs an unweighted network");
  }
  if (network.self_loops() > 0) {
    throw ParameterError("network", "has self-loops",
                         "rewiring needs a network without self-loops");
  }
  if (network.edges() < 2) throw ParameterError("network", "fewer than 2 edges", ">= 2 edges");
  if (network.nnz() > k_max_rewiring_entries) {
    throw ParameterError("network", std::to_string(network.nnz()) + " stored entries",
                         "at most " + std::to_string(k_max_rewiring_entries) +
                             " (rewiring is a serial Markov chain on one rank; it is not "
                             "distributed)");
  }
  if (!(p.target_rho > 0.0) || !std::isfinite(p.target_rho)) {
    throw ParameterError("target rho", std::to_string(p.target_rho), "finite and > 0");
  }
}

}  // namespace

RewiringResult rewire_to_correlation(const Network& network, const RewiringParameters& p) {
  check_input(network, p);
  const std::vector<double> deg = network.degrees();
  double sum_d = 0.0, sum_d2 = 0.0;
  for (const double d : deg) {
    sum_d += d;
    sum_d2 += d * d;
  }
  const double rho_per_dad = sum_d / (sum_d2 * sum_d2);  // rho = dad * this (eq:rhodef)
  RewiringResult r;
  r.initial_rho = degree_correlation(network);
  double dad = r.initial_rho / rho_per_dad;
  const double target_dad = p.target_rho / rho_per_dad;
  const bool raise = p.target_rho > r.initial_rho;
  const auto reached = [&] { return raise ? dad >= target_dad : dad <= target_dad; };

  EdgeSet s = edge_set(network);
  const std::int64_t limit = p.max_attempts > 0 ? p.max_attempts : 200 * network.edges();
  Rng rng(p.seed, 0);
  const auto m = static_cast<std::uint64_t>(s.edges.size());
  while (!reached() && r.attempts < limit) {
    ++r.attempts;
    const std::size_t e1 = rng.below(m), e2 = rng.below(m);
    if (e1 == e2) continue;
    const auto [a, b] = s.edges[e1];
    const auto [c, d] = s.edges[e2];
    // The two pairings; keep the one moving d^T A d in the wanted direction.
    double delta1 = change(deg, a, b, c, d, c, d);  // {a,c},{b,d}
    double delta2 = change(deg, a, b, c, d, d, c);  // {a,d},{b,c}
    const bool first = raise ? delta1 >= delta2 : delta1 <= delta2;
    const NodeIndex x = first ? c : d, y = first ? d : c;
    const double delta = first ? delta1 : delta2;
    if (raise ? delta <= 0.0 : delta >= 0.0) continue;
    if (a == x || b == y || s.present.count(key(a, x)) || s.present.count(key(b, y))) continue;
    s.present.erase(key(a, b));
    s.present.erase(key(c, d));
    s.present.insert(key(a, x));
    s.present.insert(key(b, y));
    s.edges[e1] = {a, x};
    s.edges[e2] = {b, y};
    dad += delta;
    ++r.swaps;
  }
  r.network = Network::from_undirected_edges(network.size(), s.edges);
  r.final_rho = degree_correlation(r.network);
  if (r.network.degrees() != deg) {
    throw std::logic_error("rewiring changed the degree sequence: this is a bug in hmfnet");
  }
  if (!reached()) {
    throw ConvergenceError("rewiring reached rho = " + std::to_string(r.final_rho) + " after " +
                           std::to_string(r.attempts) + " attempts (" + std::to_string(r.swaps) +
                           " swaps), short of the target " + std::to_string(p.target_rho) +
                           "; raise --max-attempts or lower the target");
  }
  return r;
}

}  // namespace hmfnet

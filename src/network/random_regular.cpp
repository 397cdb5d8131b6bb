#include "network/random_regular.hpp"

#include <algorithm>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/index_cast.hpp"
#include "core/random.hpp"

namespace hmfnet {

namespace {

// The unordered pairs joined so far: open addressing on 64-bit keys (min * 2^32 + max + 1, so 0
// marks an empty slot), at most half full. std::unordered_set costs ~3x the memory.
class PairSet {
 public:
  explicit PairSet(std::int64_t pairs) {
    std::size_t capacity = 16;
    while (capacity < 2 * idx(pairs)) capacity *= 2;
    m_slots.assign(capacity, 0);
  }
  bool contains(NodeIndex u, NodeIndex v) const { return m_slots[find(key(u, v))] != 0; }
  void insert(NodeIndex u, NodeIndex v) {
    const std::uint64_t k = key(u, v);
    m_slots[find(k)] = k;
  }

 private:
  static std::uint64_t key(NodeIndex u, NodeIndex v) {
    const auto a = static_cast<std::uint64_t>(std::min(u, v));
    const auto b = static_cast<std::uint64_t>(std::max(u, v));
    return (a << 32 | b) + 1;
  }
  // The slot holding k, or the empty slot where it would go (linear probing).
  std::size_t find(std::uint64_t k) const {
    const std::size_t mask = m_slots.size() - 1;
    std::uint64_t state = k;
    std::size_t i = idx(static_cast<std::int64_t>(splitmix64(state) & mask));
    while (m_slots[i] != 0 && m_slots[i] != k) i = (i + 1) & mask;
    return i;
  }
  std::vector<std::uint64_t> m_slots;
};

// Whether two of the unpaired stubs [0, live) can still be joined (different nodes, not yet
// linked). Called only after many failed draws, when few stubs are left.
bool joinable_pair_left(const std::vector<NodeIndex>& stubs, std::size_t live,
                        const PairSet& joined) {
  std::vector<NodeIndex> nodes(stubs.begin(), stubs.begin() + static_cast<std::ptrdiff_t>(live));
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    for (std::size_t b = a + 1; b < nodes.size(); ++b) {
      if (!joined.contains(nodes[a], nodes[b])) return true;
    }
  }
  return false;
}

// One pairing attempt from random stream `attempt`: the edges, or nothing at a dead end.
bool try_pairing(NodeIndex n, NodeIndex d, std::uint64_t seed, std::uint64_t attempt,
                 std::vector<Edge>& edges) {
  const std::int64_t entries = static_cast<std::int64_t>(n) * d;
  std::vector<NodeIndex> stubs(idx(entries));
  for (NodeIndex u = 0; u < n; ++u) {
    std::fill_n(stubs.begin() + static_cast<std::ptrdiff_t>(u) * d, d, u);
  }
  PairSet joined(entries / 2);
  edges.clear();
  edges.reserve(idx(entries / 2));
  Rng rng(seed, attempt);
  std::size_t live = stubs.size();
  std::size_t failures = 0;
  while (live > 0) {
    std::size_t i = rng.below(live);
    std::size_t j = rng.below(live - 1);
    if (j >= i) ++j;
    const NodeIndex u = stubs[i], v = stubs[j];
    if (u != v && !joined.contains(u, v)) {
      joined.insert(u, v);
      edges.emplace_back(std::min(u, v), std::max(u, v));
      // Drop both stubs: the larger index first, so the smaller one is not moved under us.
      if (i < j) std::swap(i, j);
      stubs[i] = stubs[--live];
      stubs[j] = stubs[--live];
      failures = 0;
      continue;
    }
    // Rejected draws are rare until the end; when they pile up, ask whether any pair is left.
    if (++failures > 64 + live) {
      if (!joinable_pair_left(stubs, live, joined)) return false;
      failures = 0;
    }
  }
  return true;
}

// Dead ends are rare on the pairing's easy side (measured: none in the unit tests' sizes); a run
// of this many is a bug or an input far outside it, not bad luck.
constexpr std::uint64_t k_max_pairing_attempts = 1000;

// The edges of a random d-regular graph, d <= (n - 1) / 2 (the pairing's easy side).
std::vector<Edge> pairing(NodeIndex n, NodeIndex d, std::uint64_t seed) {
  std::vector<Edge> edges;
  if (d == 0) return edges;
  for (std::uint64_t attempt = 0; attempt < k_max_pairing_attempts; ++attempt) {
    if (try_pairing(n, d, seed, attempt, edges)) return edges;
  }
  throw ConvergenceError("random regular graph: " + std::to_string(k_max_pairing_attempts) +
                         " pairings of N = " + std::to_string(n) + ", d = " + std::to_string(d) +
                         " all reached a dead end");
}

// Every pair {u, v}, u != v, that is not in `network`.
Network complement(const Network& network) {
  const NodeIndex n = network.size();
  std::vector<Edge> edges;
  edges.reserve(idx(static_cast<std::int64_t>(n) * (n - 1) / 2 - network.nnz() / 2));
  for (NodeIndex u = 0; u < n; ++u) {
    EdgeOffset k = network.row_begin(u);
    const EdgeOffset end = network.row_end(u);
    for (NodeIndex v = u + 1; v < n; ++v) {
      while (k < end && network.col(k) < v) ++k;
      if (k < end && network.col(k) == v) continue;
      edges.emplace_back(u, v);
    }
  }
  return Network::from_undirected_edges(n, edges);
}

void require_valid(const RandomRegularParameters& p) {
  if (p.n < 1 || p.n > k_max_random_regular_entries) {
    throw ParameterError("n", std::to_string(p.n),
                         "1 <= n <= " + std::to_string(k_max_random_regular_entries));
  }
  if (p.degree < 0 || p.degree > p.n - 1) {
    throw ParameterError("degree", std::to_string(p.degree),
                         "0 <= d <= n - 1 = " + std::to_string(p.n - 1));
  }
  const std::int64_t entries = static_cast<std::int64_t>(p.n) * p.degree;
  if (entries % 2 != 0) {
    throw ParameterError("degree", std::to_string(p.degree),
                         "n d even (n = " + std::to_string(p.n) + ": every edge has two ends)");
  }
  if (entries > k_max_random_regular_entries) {
    throw ParameterError("degree", std::to_string(p.degree),
                         "n d <= " + std::to_string(k_max_random_regular_entries) +
                             " stored entries (the pairing holds the whole network on every rank)");
  }
}

// The network is paired on the first emit (so a caller timing the generation times the pairing),
// once, whichever thread asks first.
class RandomRegularSource final : public EdgeSource {
 public:
  explicit RandomRegularSource(const RandomRegularParameters& p) : m_p(p) {}
  NodeIndex nodes() const override { return m_p.n; }
  std::int64_t units() const override { return m_p.n; }
  double work_before(std::int64_t k) const override {
    return static_cast<double>(k) * m_p.degree;  // every row holds d entries
  }
  void emit(std::int64_t k, std::vector<Edge>& out) const override {
    std::call_once(m_paired, [this] { m_network = random_regular(m_p); });
    const auto u = static_cast<NodeIndex>(k);
    for (EdgeOffset e = m_network.row_begin(u); e < m_network.row_end(u); ++e) {
      if (m_network.col(e) > u) out.emplace_back(u, m_network.col(e));
    }
  }

 private:
  RandomRegularParameters m_p;
  mutable std::once_flag m_paired;
  mutable Network m_network;
};

}  // namespace

Network random_regular(const RandomRegularParameters& p) {
  require_valid(p);
  const NodeIndex other = p.n - 1 - p.degree;
  if (p.degree > other) return complement(random_regular({p.n, other, p.seed}));
  std::vector<Edge> edges = pairing(p.n, p.degree, p.seed);
  std::sort(edges.begin(), edges.end());  // increasing (min, max): sorted rows without a sort
  return Network::from_undirected_edges(p.n, edges);
}

std::unique_ptr<EdgeSource> random_regular_source(const RandomRegularParameters& params) {
  require_valid(params);
  return std::make_unique<RandomRegularSource>(params);
}

}  // namespace hmfnet

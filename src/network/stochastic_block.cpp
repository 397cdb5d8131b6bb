#include "network/stochastic_block.hpp"

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/random.hpp"

namespace hmfnet {

namespace {

void require_probability(const char* name, double p) {
  if (!(p >= 0.0 && p <= 1.0)) throw ParameterError(name, std::to_string(p), "0 <= p <= 1");
}

class TwoBlockSource final : public EdgeSource {
 public:
  explicit TwoBlockSource(const TwoBlockParameters& p) : m_p(p) {}
  NodeIndex nodes() const override { return 2 * m_p.half; }
  std::int64_t units() const override { return nodes(); }
  double work_before(std::int64_t k) const override {
    const auto kk = static_cast<double>(k);  // pairs {i, j > i} with i < k
    return kk * (nodes() - 1) - kk * (kk - 1.0) / 2.0;
  }
  void emit(std::int64_t k, std::vector<Edge>& out) const override {
    const auto i = static_cast<NodeIndex>(k);
    Rng rng(m_p.seed, static_cast<std::uint64_t>(i));
    for (NodeIndex j = i + 1; j < nodes(); ++j) {
      const bool same = (i < m_p.half) == (j < m_p.half);
      if (rng.uniform() < (same ? m_p.p_in : m_p.p_out)) out.emplace_back(i, j);
    }
  }

 private:
  TwoBlockParameters m_p;
};

}  // namespace

std::unique_ptr<EdgeSource> two_block_sbm_source(const TwoBlockParameters& params) {
  if (params.half < 1 || params.half > std::numeric_limits<NodeIndex>::max() / 2) {
    throw ParameterError("half", std::to_string(params.half), "1 <= half <= 2^30");
  }
  require_probability("p_in", params.p_in);
  require_probability("p_out", params.p_out);
  return std::make_unique<TwoBlockSource>(params);
}

Network two_block_sbm(const TwoBlockParameters& params) {
  // Units in increasing i, pairs in increasing j: sorted rows without a sort.
  return network_from_source(*two_block_sbm_source(params));
}

}  // namespace hmfnet

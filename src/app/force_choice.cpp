#include "app/force_choice.hpp"

#include "core/error.hpp"
#include "dynamics/force_precision.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"

namespace hmfnet::app {

namespace {

// K_N held implicitly has no rows for the sparse kernel: the O(N) rank-one force with a = 1
// (without the diagonal unless it has self-loops) is its only force, exact in float64.
std::unique_ptr<CouplingForce> complete_graph_force(const std::string& force,
                                                    const std::string& precision,
                                                    const CompleteGraph& graph,
                                                    const DistributedNetwork& distributed) {
  if (force == "sparse") {
    throw ParameterError("--force", "sparse on the complete graph stored implicitly",
                         "auto or rank-one (K_N has no stored rows)");
  }
  if (parse_force_precision(precision) == ForcePrecision::float32) {
    throw ParameterError("--precision", "float32 on the complete graph stored implicitly",
                         "float64 (its rank-one force)");
  }
  return std::make_unique<RankOneForce>(complete_graph_structure(graph), distributed.first_row(),
                                        distributed.local_size());
}

std::unique_ptr<CouplingForce> stored_rows_force(const std::string& force,
                                                 const std::string& precision,
                                                 const DistributedNetwork& distributed) {
  const ForcePrecision p = parse_force_precision(precision);
  if (p == ForcePrecision::float32 && force == "rank-one") {
    throw ParameterError("--precision", "float32",
                         "only for the sparse force (--force sparse|auto)");
  }
  // float32 is a property of the sparse kernel: asking for it selects that kernel under auto.
  if (force != "sparse" && p == ForcePrecision::float64) {
    auto structure = detect_rank_one(distributed);
    if (structure) {
      return std::make_unique<RankOneForce>(std::move(*structure), distributed.first_row(),
                                            distributed.local_size());
    }
    if (force == "rank-one") {
      throw ParameterError("--force", "rank-one", "only for A = a a^T networks (see --help)");
    }
  }
  return std::make_unique<NetworkForce>(distributed, p);
}

}  // namespace

std::unique_ptr<CouplingForce> choose_force(const std::string& force, const std::string& precision,
                                            const DistributedInput& input) {
  const DistributedNetwork& distributed = *input.network;
  if (input.complete) return complete_graph_force(force, precision, *input.complete, distributed);
  return stored_rows_force(force, precision, distributed);
}

std::unique_ptr<CouplingForce> choose_force(const std::string& force, const std::string& precision,
                                            const DistributedNetwork& network) {
  if (!network.stores_rows()) {
    // The only structure held without rows is K_N (parallel/distributed_network.hpp); its size
    // and self-loops are all the rank-one force needs of it.
    const CompleteGraph graph{network.global_size(), network.global_self_loops() != 0};
    return complete_graph_force(force, precision, graph, network);
  }
  return stored_rows_force(force, precision, network);
}

}  // namespace hmfnet::app

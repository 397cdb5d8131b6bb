#include "app/network_rewiring.hpp"

#include "app/provenance.hpp"
#include "core/atomic_file.hpp"
#include "core/distinct_files.hpp"
#include "io/network_file.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet::app {

void check_rewire(const RewireRequest& r) {
  validate(r);
  format_from_extension(r.output);
  require_writable_destination(r.output);
  require_distinct_files({{"input", r.input}}, {{"--output", r.output}});
}

RewiringResult rewire(const RewireRequest& r, const Network& network) {
  check_rewire(r);
  RewiringResult result = rewire_to_correlation(network, {r.target_rho, r.seed, r.max_attempts});
  if (ParallelSession::rank() != 0) return result;
  write_network(r.output, result.network,
                provenance("rewire", {{"input", r.input},
                                      {"target_rho", r.target_rho},
                                      {"seed", r.seed},
                                      {"initial_rho", result.initial_rho},
                                      {"final_rho", result.final_rho},
                                      {"attempts", result.attempts},
                                      {"swaps", result.swaps}}));
  return result;
}

}  // namespace hmfnet::app

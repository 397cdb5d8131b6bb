// Generates an Erdos-Renyi network, finds its largest eigenvalue with the installed library and
// prints lambda and K_c (eq:criticalKFirstOrder) for the test to compare with the installed CLI.
#include <cstdio>

#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "theory/critical_coupling.hpp"

int main(int argc, char** argv) {
  hmfnet::ParallelSession session(&argc, &argv);
  const int n = 500;
  const hmfnet::ErdosRenyiParameters params{n, hmfnet::erdos_renyi_probability(n, 10.0), 3};
  const hmfnet::DistributedNetwork network(hmfnet::erdos_renyi(params));
  const double lambda = hmfnet::perron_eigenpair(network).lambda;
  std::printf("%.17g %.17g\n", lambda, hmfnet::critical_coupling(0.35, n, lambda));
  return 0;
}

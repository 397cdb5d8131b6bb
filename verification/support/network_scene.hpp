#pragma once
// A network as the long-run drivers (near_onset_gap, qss_networks, waterbag_threshold) integrate
// and solve it: its rows over the ranks, its force (the one a user's run gets, app::choose_force
// under auto: the O(N) rank-one force on the complete graph, the sparse one on the stored
// networks here) and what eq:rSigmaBesselMain needs of it (on K_N its one-node quotient: the
// same map and solution, network/complete_graph.hpp), with the comparison at a run's own
// conserved E and P (run_variance.hpp).
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/force_choice.hpp"
#include "dynamics/simulation.hpp"
#include "network/complete_graph.hpp"
#include "network/degree_statistics.hpp"
#include "parallel/distributed_network.hpp"
#include "spectral/perron.hpp"
#include "support/run_variance.hpp"
#include "theory/self_consistent.hpp"

namespace hmfnet::verification {

struct NetworkScene {
  bool complete = false;
  NodeIndex n = 0;
  double degree = 0.0;  ///< mean degree
  double lambda = 0.0;  ///< the largest eigenvalue of A
  Network theory_net;   ///< the network itself, or K_N's one-node quotient
  double theory_lambda = 0.0;
  std::vector<double> perron;
  std::vector<double> degrees;
  std::unique_ptr<DistributedNetwork> rows;
  std::unique_ptr<CouplingForce> force;
};

/// K_N without self-loops (d = N - 1), on the rank-one force. Scene: NetworkScene or a driver's
/// type derived from it.
template <class Scene = NetworkScene>
std::unique_ptr<Scene> complete_scene(NodeIndex n) {
  auto s = std::make_unique<Scene>();
  const CompleteGraph graph = CompleteGraph::make(n, false);
  s->complete = true;
  s->n = n;
  s->theory_net = graph.quotient();
  s->theory_lambda = s->theory_net.weights().front();  // a 1 x 1 matrix: its one entry
  s->perron = {1.0};
  s->degree = graph.degree();
  s->lambda = graph.lambda();
  s->degrees.assign(static_cast<std::size_t>(n), graph.degree());
  s->rows = std::make_unique<DistributedNetwork>(graph);
  s->force = app::choose_force("auto", "float64", *s->rows);
  return s;
}

/// A stored network, on the force auto gives it (sparse unless A = a a^T); its Perron pair from
/// Anasazi.
template <class Scene = NetworkScene>
std::unique_ptr<Scene> stored_scene(const Network& network) {
  auto s = std::make_unique<Scene>();
  s->n = network.size();
  s->theory_net = network;
  s->rows = std::make_unique<DistributedNetwork>(s->theory_net);
  const PerronResult perron = perron_eigenpair(*s->rows);
  s->lambda = s->theory_lambda = perron.lambda;
  s->perron = perron.u;
  s->degree = mean_degree(s->theory_net);
  s->degrees = s->theory_net.degrees();
  s->force = app::choose_force("auto", "float64", *s->rows);
  return s;
}

/// eq:rSigmaBesselMain at coupling K for replica b of `sim`, at its own conserved E and P (the
/// initial momenta's nominal variance sigma0^2 fixes only the solver's scale).
inline SelfConsistentSolution theory_at_run(const NetworkScene& scene, const SimulationResult& sim,
                                            double K, std::size_t b, double sigma0) {
  const double mu0 = incoherent_variance(sim, K, b, static_cast<double>(scene.n));
  const double c0 = (sigma0 * sigma0 - mu0) / K;  // mu0 = sigma0^2 - K c0 (self_consistent.hpp)
  const SelfConsistentSystem system(scene.theory_net, scene.theory_lambda, sigma0, c0,
                                    scene.perron);
  return system.solve(K);
}

}  // namespace hmfnet::verification

// Regression against stored references (reference/*.h5): the same seeds must keep giving the
// same networks, spectra and short simulations.
//   hmfnet_regression [--reference DIR]          compare (CTest label `regression`)
//   hmfnet_regression --write DIR                regenerate on purpose (never done by CI)
// Tolerances: network structure (row_ptr, col) exact: generators are integer-deterministic;
// lambda, rho, G to 1e-12 relative (eigen-residual tolerance 1e-10, squared); simulation
// observables to 1e-9 relative: the run is deterministic, but a different libm, FMA use or rank
// count changes last bits, which the chaotic dynamics amplify by at most ~e^(Lyapunov * T) ~ 1e3
// over the 5 time units stored. The maximal relative energy error is itself a difference of
// nearly equal energies (~1e-8 of H), so it is compared to 1e-12 absolute, not relatively.
// Theory curves to 1e-10 relative: each solve stops at a relative residual of 1e-12, and the
// solution's sensitivity to the residual grows like 1 / (K/K_c - 1) <= 10 on the grid stored
// (K/K_c >= 1.1), so two solves may differ by ~2e-11; G, K_c and gamma are closed forms.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/simulation.hpp"
#include "io/hdf5_file.hpp"
#include "network/chung_lu.hpp"
#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/growth_rate.hpp"
#include "theory/large_k_limit.hpp"
#include "theory/onset_amplitude.hpp"
#include "theory/self_consistent.hpp"

using namespace hmfnet;

namespace {

struct Values {
  std::vector<std::pair<std::string, std::vector<double>>> real;      // relative tolerance
  std::vector<std::pair<std::string, std::vector<double>>> absolute;  // 1e-12 absolute
  std::vector<std::pair<std::string, std::vector<std::int64_t>>> integer;
};

Values network_case(const Network& net) {
  const DistributedNetwork d(net);
  const PerronResult perron = perron_eigenpair(d);
  Values v;
  v.integer.push_back({"row_ptr", net.row_ptr()});
  v.integer.push_back({"col", std::vector<std::int64_t>(net.cols().begin(), net.cols().end())});
  v.real.push_back({"spectrum",
                    {perron.lambda, degree_correlation(net),
                     onset_amplitude(perron.lambda, mean_degree(net), perron.u)}});
  return v;
}

Values simulation_case() {
  const Network net = erdos_renyi({500, 0.04, 2});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p;
  p.h = 0.02;
  p.duration = 5.0;
  p.transient = 2.0;
  p.K = {10.0, 40.0, 80.0};
  p.record_stride = 5;
  p.replicas = {{6.0, 1.0, 3}};
  const SimulationResult r = simulate(d, net.degrees(), force, p);
  Values v;
  std::vector<double> R_mean, R_sem, energy_error;
  for (const auto& pt : r.points) {
    R_mean.push_back(pt.R_mean[0]);
    R_sem.push_back(pt.R_sem[0]);
    energy_error.push_back(pt.energy_rel_error_max[0]);
  }
  v.real.push_back({"R_mean", R_mean});
  v.real.push_back({"R_sem", R_sem});
  v.absolute.push_back({"energy_rel_error_max", energy_error});
  v.real.push_back({"R_series", r.series.R});
  v.real.push_back({"energy_series", r.series.energy});
  return v;
}

// The theory curves of one seeded network: K_c, G, gamma(K/K_c) (eq:gammaKKc), R(K) of
// eq:rSigmaBesselMain, R_hat of eq:KtoInfinity and of eq:rd.
Values theory_case() {
  const Network net = erdos_renyi({2000, 0.01, 1});
  const DistributedNetwork d(net);
  const PerronResult perron = perron_eigenpair(d);
  const double sigma0 = 0.35;
  const double Kc = critical_coupling(sigma0, net.size(), perron.lambda);
  const std::vector<double> ratios{1.1, 1.5, 2.0, 3.0, 5.0};
  std::vector<double> Ks, gamma;
  for (const double x : ratios) {
    Ks.push_back(x * Kc);
    gamma.push_back(growth_rate(x, sigma0));
  }
  SelfConsistentOptions options;
  options.tolerance = 1e-12;
  const SelfConsistentSystem system(net, perron.lambda, sigma0, 0.0, perron.u);
  std::vector<double> R;
  for (const SelfConsistentSolution& s : system.sweep(Ks, options)) {
    if (s.status != SolveStatus::converged) throw ConvergenceError("theory case: " + s.message);
    R.push_back(s.R);
  }
  const LargeKLimit large = solve_large_k_limit(net, options);
  Values v;
  v.real.push_back(
      {"closed_forms", {Kc, onset_amplitude(perron.lambda, mean_degree(net), perron.u)}});
  v.real.push_back({"gamma", gamma});
  v.real.push_back({"R_of_K", R});
  v.real.push_back({"R_hat", {large.R_hat, degree_approximation_R_hat(net.degrees())}});
  return v;
}

struct Case {
  std::string name;
  Values values;
};

std::vector<Case> all_cases() {
  return {{"er_n2000_q001_seed1", network_case(erdos_renyi({2000, 0.01, 1}))},
          {"sf_n2000_alpha25_seed1",
           network_case(chung_lu(power_law_targets(2000, {2.5, 10.0, 1999}, 1),
                                 LinkProbability::capped, 1))},
          {"simulation_er_n500", simulation_case()},
          {"theory_er_n2000", theory_case()}};
}

void write(const std::string& dir, const Case& c) {
  AtomicFile out(dir + "/" + c.name + ".h5");
  {
    const Hdf5File f(out.temp_path(), Hdf5File::Mode::create);
    f.set_attribute(f.id(), "hmfnet_format", std::string("regression"));
    for (const auto& [name, data] : c.values.real) f.write(f.id(), name, data);
    for (const auto& [name, data] : c.values.absolute) f.write(f.id(), name, data);
    for (const auto& [name, data] : c.values.integer) f.write(f.id(), name, data);
  }
  out.commit();
}

int compare(const std::string& dir, const Case& c) {
  const std::string path = dir + "/" + c.name + ".h5";
  const Hdf5File f(path, Hdf5File::Mode::read);
  int failures = 0;
  const double tolerance = c.name.rfind("simulation", 0) == 0 ? 1e-9
                           : c.name.rfind("theory", 0) == 0   ? 1e-10
                                                              : 1e-12;
  for (const auto& [name, data] : c.values.integer) {
    const bool same = f.read_int64(f.id(), name) == data;
    std::printf("  %s  %s/%s: exact\n", same ? "PASS" : "FAIL", c.name.c_str(), name.c_str());
    failures += same ? 0 : 1;
  }
  const auto check = [&](const std::string& name, const std::vector<double>& data, bool relative,
                         double limit) {
    const std::vector<double> ref = f.read_double(f.id(), name);
    double worst = ref.size() == data.size() ? 0.0 : INFINITY;
    for (std::size_t k = 0; k < ref.size() && k < data.size(); ++k) {
      const double scale = relative ? std::max(std::abs(ref[k]), 1e-300) : 1.0;
      worst = std::max(worst, std::abs(data[k] - ref[k]) / scale);
    }
    const bool ok = worst <= limit;
    std::printf("  %s  %s/%s: max %s difference %.2e (tolerance %.0e)\n", ok ? "PASS" : "FAIL",
                c.name.c_str(), name.c_str(), relative ? "relative" : "absolute", worst, limit);
    failures += ok ? 0 : 1;
  };
  for (const auto& [name, data] : c.values.real) check(name, data, true, tolerance);
  for (const auto& [name, data] : c.values.absolute) check(name, data, false, 1e-12);
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  std::string dir = HMFNET_REFERENCE_DIR;
  bool writing = false;
  for (int k = 1; k + 1 < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--write") writing = true;
    if (arg == "--write" || arg == "--reference") dir = argv[k + 1];
  }
  int failures = 0;
  try {
    for (const Case& c : all_cases()) {
      if (writing) {
        if (ParallelSession::rank() == 0) write(dir, c);
      } else {
        failures += compare(dir, c);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hmfnet_regression: %s\n", e.what());
    return 2;
  }
  std::printf("%s\n", writing         ? "references written"
                      : failures == 0 ? "regression: all match"
                                      : "regression: MISMATCH");
  return failures == 0 ? 0 : 1;
}

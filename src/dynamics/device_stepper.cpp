#include "dynamics/device_stepper.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/splitting_coefficients.hpp"
#include "parallel/parallel_session.hpp"

#if defined(HMFNET_HAVE_CUDA)
#include "dynamics/cuda/device.hpp"
#include "dynamics/cuda/rank_one_ensemble.hpp"
#include "dynamics/cuda/sparse_ensemble.hpp"
#endif

namespace hmfnet {

namespace {

[[noreturn]] void refuse(const std::string& what) {
  throw ParameterError("--device cuda: " + what + "; run it with --device cpu");
}

// The first thing of `network` with `force` that the device does not take.
void check_network(const CouplingForce& force) {
  if (dynamic_cast<const RankOneForce*>(&force) != nullptr) return;
  if (dynamic_cast<const NetworkForce*>(&force) == nullptr) {
    refuse(std::string("the ") + force.name() + " force is not on the device");
  }
}

}  // namespace

void require_device_for(const SimulationParameters& params) {
  if (ParallelSession::ranks() > 1) {
    refuse("one MPI rank only (this run has " + std::to_string(ParallelSession::ranks()) + ")");
  }
  for (std::size_t k = 0; k < params.K.size(); ++k) {
    const std::string method = step_at(params, k).integrator;
    if (!splitting_coefficients(method)) {
      refuse("the integrator " + method +
             " is no kick-drift splitting (leapfrog, yoshida4, blanes_moan)");
    }
  }
  const std::string why = cuda_unavailable();
  if (!why.empty()) refuse(why);
}

#if defined(HMFNET_HAVE_CUDA)

namespace {

// Over cuda::SparseEnsemble or cuda::RankOneEnsemble.
class DeviceStepper : public EnsembleStepper {
 public:
  DeviceStepper(std::unique_ptr<cuda::DeviceEnsemble> ensemble, CouplingForce& force)
      : m_ensemble(std::move(ensemble)), m_force(force), m_device(cuda::device_description()) {}

  void set_state(const RotorState& state) override {
    m_state = state;
    m_ensemble->set_state(m_state.theta, m_state.p);
    m_state_current = true;
    ++m_evaluations;
  }

  const RotorState& state() override {
    if (!m_state_current) m_ensemble->get_state(m_state.theta, m_state.p);
    m_state_current = true;
    return m_state;
  }

  void advance(const Integrator& method, double h, const std::vector<double>& K, std::int64_t steps,
               std::vector<double>* order) override {
    const std::optional<SplittingCoefficients> table = splitting_coefficients(method.name());
    if (!table) refuse("the integrator " + method.name() + " is no kick-drift splitting");
    if (K != m_K) {
      m_ensemble->set_coupling(K);
      m_K = K;
    }
    m_ensemble->advance(*table, h, steps, order);
    m_state_current = false;
    m_evaluations += steps * static_cast<long long>(table->drifts.size());
  }

  StepperSums sums() override {
    cuda::EnsembleSums s = m_ensemble->sums();
    return {std::move(s.order), std::move(s.coupling), std::move(s.kinetic), std::move(s.momentum),
            std::move(s.momentum_scale)};
  }

  // Node data read every step's fields: the device keeps them (keep_fields) and they are copied
  // here. Otherwise only a blow-up report reads them: the CPU's force at the device's state.
  // Both are the CPU's bits.
  const std::vector<double>& local_fields() override {
    if (m_fields_kept) {
      m_ensemble->fields(m_fields);
      return m_fields;
    }
    m_force.evaluate(state(), m_g, m_host_sums);
    return m_force.local_fields();
  }

  void keep_fields() {
    m_ensemble->keep_fields();
    m_fields_kept = true;
  }

  long long evaluations() const override { return m_evaluations; }
  std::string device() const override { return m_device; }

 private:
  std::unique_ptr<cuda::DeviceEnsemble> m_ensemble;
  CouplingForce& m_force;
  std::string m_device;
  RotorState m_state;  // the host's copy: rows, replicas, first row; theta and p when current
  bool m_state_current = false;
  std::vector<double> m_K;  // what the device holds
  long long m_evaluations = 0;
  bool m_fields_kept = false;
  std::vector<double> m_fields;  // the device's fields, when kept
  std::vector<double> m_g;       // local_fields' scratch
  ForceSums m_host_sums;
};

// This rank's rows as the device takes them (one rank: the column space is the rows).
cuda::HostCsr host_csr(const DistributedNetwork& network) {
  const auto& rows = network.local_adjacency();
  cuda::HostCsr csr;
  csr.rows = network.local_size();
  csr.offsets.assign(rows.row_ptr.begin(), rows.row_ptr.end());
  csr.columns.reserve(rows.cols.size());
  for (const NodeIndex c : rows.cols) csr.columns.push_back(static_cast<std::int32_t>(c));
  csr.weights = rows.weights;
  return csr;
}

// The ensemble of `force` on the device: the rank-one force of the complete graph, or the sparse
// force on the network's rows.
std::unique_ptr<cuda::DeviceEnsemble> device_ensemble(const DistributedNetwork& network,
                                                      const CouplingForce& force,
                                                      const SimulationParameters& params) {
  const int replicas = static_cast<int>(lanes(params));
  if (const auto* rank_one = dynamic_cast<const RankOneForce*>(&force)) {
    const RankOneStructure& s = rank_one->structure();
    return std::make_unique<cuda::RankOneEnsemble>(s.a, s.diagonal, replicas);
  }
  if (!network.columns_are_owned_rows()) refuse("the network's columns are not its rows");
  const auto& sparse = dynamic_cast<const NetworkForce&>(force);
  const cuda::DevicePrecision precision = sparse.precision() == ForcePrecision::float64
                                              ? cuda::DevicePrecision::float64
                                              : cuda::DevicePrecision::float32;
  return std::make_unique<cuda::SparseEnsemble>(host_csr(network), replicas, precision);
}

}  // namespace

std::string cuda_unavailable() {
  std::string why;
  return cuda::device_usable(why) ? std::string() : why;
}

std::unique_ptr<EnsembleStepper> make_device_stepper(const DistributedNetwork& network,
                                                     CouplingForce& force,
                                                     const SimulationParameters& params) {
  require_device_for(params);
  check_network(force);
  if (network.local_size() > INT32_MAX) refuse("more than 2^31 - 1 rows");
  auto stepper = std::make_unique<DeviceStepper>(device_ensemble(network, force, params), force);
  if (params.node_data) stepper->keep_fields();
  return stepper;
}

#else

std::string cuda_unavailable() {
  return "built without CUDA (configure where nvcc is on the PATH: cmake/HmfnetCuda.cmake)";
}

std::unique_ptr<EnsembleStepper> make_device_stepper(const DistributedNetwork& network,
                                                     CouplingForce& force,
                                                     const SimulationParameters& params) {
  require_device_for(params);
  check_network(force);
  refuse(cuda_unavailable());
}

#endif

}  // namespace hmfnet

#include "dynamics/device_stepper.hpp"

#include <algorithm>
#include <iostream>

#include "core/error.hpp"
#include "dynamics/device_assignment.hpp"
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
  /// `sharing`: what follows the device's description (the ranks and how they share it).
  DeviceStepper(std::unique_ptr<cuda::DeviceEnsemble> ensemble, CouplingForce& force,
                const std::string& sharing)
      : m_ensemble(std::move(ensemble)),
        m_force(force),
        m_device(cuda::device_description() + sharing) {}

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

// This rank's rows as the device takes them, over its column space (one rank: the rows).
cuda::HostCsr host_csr(const DistributedNetwork& network) {
  const auto& rows = network.local_adjacency();
  if (rows.columns > INT32_MAX) refuse("a column space of more than 2^31 - 1 columns on a rank");
  cuda::HostCsr csr;
  csr.rows = network.local_size();
  csr.column_count = rows.columns;
  csr.offsets.assign(rows.row_ptr.begin(), rows.row_ptr.end());
  csr.columns.reserve(rows.cols.size());
  for (const NodeIndex c : rows.cols) csr.columns.push_back(static_cast<std::int32_t>(c));
  csr.weights = rows.weights;
  return csr;
}

// Over ranks, what each evaluation exchanges through the host, as the CPU's forces do: the
// ghosts' [cos, sin] through the network's Tpetra Import (network_force.cpp), Z summed over the
// ranks (rank_one_force.cpp). `network` outlives the stepper (make_device_stepper's contract).
cuda::RankExchange rank_exchange(const DistributedNetwork& network, bool sparse) {
  cuda::RankExchange ranks;
  ranks.global_rows = network.global_size();
  if (sparse) {
    ranks.import_columns = [&network](const double* owned, int width, double* columns) {
      network.import_columns(owned, width, columns);
    };
  } else {
    ranks.sum_over_ranks = [z = std::vector<double>()](double* values, int count) mutable {
      z.assign(values, values + count);
      ParallelSession::sum_in_place(z);
      std::copy(z.begin(), z.end(), values);
    };
  }
  return ranks;
}

// The ensemble of `force` on the device: the rank-one force of the complete graph, or the sparse
// force on the network's rows; over ranks, this rank's rows with their exchange.
std::unique_ptr<cuda::DeviceEnsemble> device_ensemble(const DistributedNetwork& network,
                                                      const CouplingForce& force,
                                                      const SimulationParameters& params) {
  const int replicas = static_cast<int>(lanes(params));
  const bool one_rank = ParallelSession::ranks() == 1;
  if (const auto* rank_one = dynamic_cast<const RankOneForce*>(&force)) {
    const RankOneStructure& s = rank_one->structure();
    if (one_rank) return std::make_unique<cuda::RankOneEnsemble>(s.a, s.diagonal, replicas);
    const auto first = s.a.begin() + network.first_row();
    const std::vector<double> a(first, first + network.local_size());
    return std::make_unique<cuda::RankOneEnsemble>(a, s.diagonal, replicas,
                                                   rank_exchange(network, false));
  }
  const auto& sparse = dynamic_cast<const NetworkForce&>(force);
  const cuda::DevicePrecision precision = sparse.precision() == ForcePrecision::float64
                                              ? cuda::DevicePrecision::float64
                                              : cuda::DevicePrecision::float32;
  if (network.columns_are_owned_rows()) {
    return std::make_unique<cuda::SparseEnsemble>(host_csr(network), replicas, precision);
  }
  return std::make_unique<cuda::SparseEnsemble>(host_csr(network), replicas, precision,
                                                rank_exchange(network, true));
}

// This rank's device: the machine's ranks take its devices in turn; where they share one, the
// run says so once (rank 0, on the standard error, and in the device's line of the output).
std::string use_assigned_device(const ParallelSession::MachineRanks& machine) {
  const DeviceAssignment a = assign_device(machine.index, machine.count, cuda::device_count());
  cuda::use_device(a.device);
  if (a.shared && ParallelSession::rank() == 0) std::cerr << "hmfnet: note: " << a.note << "\n";
  if (a.shared) return "; " + a.note;
  const int ranks = ParallelSession::ranks();
  return ranks == 1 ? std::string() : "; " + std::to_string(ranks) + " MPI ranks, a device each";
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
  const ParallelSession::MachineRanks machine = ParallelSession::machine_ranks();
  std::unique_ptr<DeviceStepper> stepper;
  const auto build = [&] {
    if (network.local_size() > INT32_MAX) refuse("more than 2^31 - 1 rows on a rank");
    const std::string sharing = use_assigned_device(machine);
    stepper =
        std::make_unique<DeviceStepper>(device_ensemble(network, force, params), force, sharing);
  };
  // Over ranks, a rank whose part the device refuses (its memory, a rank without rows) fails
  // every rank with its message, before the first collective exchange.
  if (ParallelSession::ranks() == 1) {
    build();
  } else {
    ParallelSession::agree(build);
  }
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

#pragma once
// Replicas of the all-to-all HMF (K_N with self-loops, A = 1 1^T: the rank-one force of
// rank_one_force.hpp with a = 1 and the diagonal) stepped on a CUDA device, one cluster of 1 to
// 8 thread blocks per replica (sm_90's thread block clusters: few replicas still fill every
// multiprocessor) for many steps per launch. Several systems (sizes N) run side by side in one
// launch, as a finite-size campaign needs (qss_lifetime). Per step and stage a cluster updates its
// rotors (the CPU's kick, kick-drift and sincos, kernel_arithmetic.hpp) and sums
// Z = sum_m e^{i theta_m} over min(N, 2048) fixed tiles (rotor m in tile m mod tiles), each in
// order; every block of the cluster reads the other blocks' tile sums from their shared memory
// and adds all tiles by the same fixed pairwise tree: the bits depend on N alone, not on the
// launch (threads per block, blocks per cluster), and repeat run to run.
// The CPU sums Z in another fixed order (2048-row blocks), so the two agree to rounding, not to
// the bit (tests/gpu/test_complete_graph_ensembles.cpp: 1e-12 relative over 100 steps).
//
// Records: every `record_every` steps of a system, each replica's R averaged over the steps of
// that interval (R = |Z| / N after each step) and its energy at the interval's end,
// H = sum p^2 / 2 - K |Z|^2 / (2N).
#include <cstdint>
#include <memory>
#include <vector>

#include "dynamics/cuda/sparse_ensemble.hpp"
#include "dynamics/splitting_coefficients.hpp"

namespace hmfnet::cuda {

/// Where a launch keeps the replicas' angles and momenta (complete_graph_resident.cu says why).
enum class StatePlace {
  global_memory,  ///< read and written at every stage
  shared_memory,  ///< in the replica's blocks for the whole launch, with their [cos, sin] where
                  ///< those fit, else formed again from the angles at each stage
};

struct CompleteGraphSystem {
  std::int64_t n = 0;
  int replicas = 1;
  double K = 1.0;
  std::int64_t record_every = 1;  ///< steps per record
  std::int64_t records = 0;       ///< records kept (later ones are dropped)
};

/// One system's records, replica-major: value[b * records + i].
struct CompleteGraphRecords {
  std::int64_t written = 0;  ///< records completed so far
  std::vector<double> R_mean, energy;
};

class CompleteGraphEnsembles {
 public:
  /// Throws DeviceError where no device can run this build, when memory does not suffice
  /// (checked before allocating), or for N < 1 or N > 2^31 - 1. cluster_blocks: the thread
  /// blocks each replica is spread over (a cluster, 1 to 8; 0: as many as keep every
  /// multiprocessor busy). The results depend on neither.
  explicit CompleteGraphEnsembles(std::vector<CompleteGraphSystem> systems,
                                  int threads_per_block = 512, int cluster_blocks = 0);
  ~CompleteGraphEnsembles();
  CompleteGraphEnsembles(const CompleteGraphEnsembles&) = delete;
  CompleteGraphEnsembles& operator=(const CompleteGraphEnsembles&) = delete;

  std::size_t systems() const;
  /// A system's state in the CPU's layout, rows x replicas (k = n * replicas + b).
  void set_state(std::size_t system, const std::vector<double>& theta,
                 const std::vector<double>& p);
  void get_state(std::size_t system, std::vector<double>& theta, std::vector<double>& p) const;
  /// Advances each system by steps[s] steps (0 leaves it as it is), in one launch.
  void advance(const SplittingCoefficients& splitting, double h,
               const std::vector<std::int64_t>& steps);
  /// Continues a system from a run stopped at a record's end: its state (as set_state), the
  /// steps it had done (a multiple of record_every) and its records as records() gave them. The
  /// run goes on with the bits it would have had uninterrupted: at a record's end the open
  /// interval's sum of R is empty and Z, [cos, sin] are functions of the angles alone.
  void resume(std::size_t system, std::int64_t steps_done, const std::vector<double>& theta,
              const std::vector<double>& p, const CompleteGraphRecords& records);
  /// Steps done so far by a system.
  std::int64_t steps_done(std::size_t system) const;
  CompleteGraphRecords records(std::size_t system) const;
  /// Z of each replica of a system at its current state, [Re, Im] per replica.
  std::vector<double> order_sums(std::size_t system) const;
  void synchronize() const;
  /// The blocks per replica chosen.
  int cluster_blocks() const;
  /// Rotors a thread loads together before updating them: 1, 4 (the default) or 8. The results
  /// do not depend on it; the benchmark measures each.
  void set_batch(int rotors);
  int batch() const;
  /// Where the state is kept from the next launch on; the results do not depend on it. Shared
  /// memory needs threads per block a power of two up to 512 and each replica's rotors in its
  /// blocks' shared memory (about 16 N / blocks bytes a block): with automatic blocks per replica,
  /// the fewest that hold them (then more while multiprocessors are idle); throws DeviceError
  /// naming the bytes a block needs and the device's limit where they do not fit.
  void set_state_place(StatePlace place);
  StatePlace state_place() const;
  /// Whether the shared-memory stepper keeps the [cos, sin] of the angles (else forms them again).
  bool keeps_phases() const;
  /// Replicas' clusters the device runs at once in the current place (the rest wait for them).
  int active_clusters() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace hmfnet::cuda

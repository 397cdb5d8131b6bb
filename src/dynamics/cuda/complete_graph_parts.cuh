#pragma once
// What the complete graph's two steppers share (complete_graph_ensembles.hpp): the state in global
// memory (complete_graph_ensembles.cu) and in shared memory (complete_graph_resident.cu). The
// systems' table, the splitting's coefficients, the arrays, one rotor's stage and the cluster a
// replica runs on. Compiled with --fmad=false (kernel_arithmetic.hpp says why).
#include <cooperative_groups.h>

#include <cstddef>
#include <cstdint>

#include "dynamics/cuda/device_buffer.cuh"
#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet::cuda::complete_graph {

// The most blocks a replica's cluster takes (the portable cluster size of sm_90).
constexpr int k_max_cluster = 8;
// Z's tiles: min(N, k_max_tiles) per replica, rotor m in tile m mod tiles (neighbouring threads
// touch neighbouring rotors: coalesced), so that their sums fit shared memory (32 KiB).
constexpr std::int64_t k_max_tiles = 2048;
// Stages of the longest splitting held (blanes_moan: 6 drifts, 7 kicks).
constexpr int k_max_stages = 8;

struct SystemInfo {
  std::int64_t n;
  int replicas;
  double K;
  std::int64_t tiles;
  std::int64_t state_offset;   // into theta and p (replica-major inside the system)
  std::int64_t record_offset;  // into the records
  std::int64_t record_every;
  std::int64_t records;
  std::int64_t steps_before;  // of this launch
  std::int64_t steps;         // this launch
};

struct Table {
  int stages;                     // drifts
  double kick[k_max_stages + 1];  // b_i h
  double drift[k_max_stages];     // a_i h
};

struct Arrays {
  const SystemInfo* systems;
  const int* block_system;
  const int* block_replica;
  double* theta;
  double* p;
  double* cs;      // per rotor [cos, sin] of the current angle
  double* z;       // per block [Re Z, Im Z] at the current state
  double* r_sum;   // per block: the running sum of R over the open record interval
  double* R_mean;  // records
  double* energy;  // records
};

// What a stage does to each rotor of a tile (the CPU's kick, kick-drift and sincos).
struct RotorStage {
  double inverse_n, K;
  LocalField Z;      // at the stage's start
  bool kick_first;   // the previous step's closing kick is still pending
  double last_kick;  // b_s h
  double kick;       // b_i h
  double drift;      // a_i h
};

// One rotor's stage from the [cos, sin] of its angle: y_n = Z (a = 1, diagonal kept), the kicks
// and the drift of pm and th in place, and the [cos, sin] of the new angle.
__device__ __forceinline__ void stage_cell(const RotorStage& st, double c, double s, double& pm,
                                           double& th, double& c_new, double& s_new) {
  const double g = coupling_force(st.inverse_n, c, s, st.Z);
  if (st.kick_first) pm = kicked_momentum(pm, st.last_kick, st.K, g);
  pm = kicked_momentum(pm, st.kick, st.K, g);
  th = drifted_angle(th, st.drift, pm);
  sincos_one(th, c_new, s_new);
}

// A replica's cluster of blocks (cg::this_cluster(): 1 to k_max_cluster blocks, consecutive in x):
// block `rank` of the cluster owns the tiles t with (t / blockDim) mod blocks == rank, and each
// rotor m belongs to tile m mod tiles, so a rotor is only ever touched by its tile's thread
// (tile_tree.hpp: TileLayout).
struct Cluster {
  int rank, blocks;
  // The first tile of this thread, and the stride to its next.
  __device__ int first_tile() const {
    return rank * static_cast<int>(blockDim.x) + static_cast<int>(threadIdx.x);
  }
  __device__ int tile_stride() const { return blocks * static_cast<int>(blockDim.x); }
};

// A launch of `clusters` clusters of `cluster` blocks of `threads` threads with `shared_bytes` of
// dynamic shared memory each: the configuration of cudaLaunchKernelEx and
// cudaOccupancyMaxActiveClusters. `attribute` must outlive `config`.
inline void cluster_config(cudaLaunchConfig_t& config, cudaLaunchAttribute& attribute, int clusters,
                           int cluster, int threads, std::size_t shared_bytes) {
  config = cudaLaunchConfig_t{};
  config.gridDim = dim3(static_cast<unsigned>(clusters * cluster));
  config.blockDim = dim3(static_cast<unsigned>(threads));
  config.dynamicSmemBytes = shared_bytes;
  attribute = cudaLaunchAttribute{};
  attribute.id = cudaLaunchAttributeClusterDimension;
  attribute.val.clusterDim.x = static_cast<unsigned>(cluster);
  attribute.val.clusterDim.y = 1;
  attribute.val.clusterDim.z = 1;
  config.attrs = &attribute;
  config.numAttrs = 1;
}

/// The resident stepper's most threads per block: its kernel may then take 128 registers a thread
/// (64 under 1024 threads), which its batches of rotors use.
constexpr int k_max_resident_threads = 512;

/// The resident stepper (complete_graph_resident.cu): each replica's theta and p (and their
/// [cos, sin] where keep_phases) in its blocks' shared memory for the whole launch.
struct ResidentLaunch {
  int clusters = 0;  // replicas over all systems
  int cluster = 1;   // blocks per replica
  int threads = 0;   // per block, a power of two
  int batch = 4;     // rotors loaded together: 1, 4 or 8
  bool keep_phases = false;
};

/// Shared memory a block of a system's replica needs in the resident stepper.
std::size_t resident_bytes(const SystemInfo& system, int cluster, int threads, bool keep_phases);

/// Runs `table`'s stages for each system's `steps` from its state in `a`, and writes the state,
/// Z, the open interval's sum of R and the records back: what complete_graph_ensembles.cu's
/// kernel leaves, bit for bit. `shared_bytes`: the largest resident_bytes of the systems.
void launch_resident(const Arrays& a, const Table& table, const ResidentLaunch& shape,
                     std::size_t shared_bytes);

/// Clusters of `shape` that the device holds at once with `shared_bytes` each (0: none fits).
int resident_active_clusters(const ResidentLaunch& shape, std::size_t shared_bytes);

}  // namespace hmfnet::cuda::complete_graph

// The complete graph's stepper with its state in shared memory (complete_graph_ensembles.hpp,
// StatePlace::shared_memory). The stepper whose state stays in global memory reads and writes
// theta, p and [cos, sin] of every rotor at every stage, 64 bytes a rotor and step: at N = 10^5
// with 16 replicas (51 MB, near the H200's 60 MB L2) its step took 46 us, 2.2 TB/s, and twice the
// multiprocessors gave nothing more (docs/gpu.md). Here a launch loads each replica's theta and p
// into its cluster's shared memory once, steps there, and writes them back at its end; the
// [cos, sin] of the angles stay in shared memory too where they fit, and are otherwise formed
// again from the angles at each stage (sincos_one of the same angle: the same bits). The tile sums
// are the same, in the same order, and Z's tree is the same additions, taken chunk by chunk and
// then over the chunks' heads (tile_tree.hpp: chunked_tree_sum), so the results are the global
// stepper's, bit for bit (tests/gpu/test_complete_graph_ensembles.cpp).
#include <cooperative_groups.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "dynamics/cuda/complete_graph_parts.cuh"
#include "dynamics/tile_tree.hpp"

namespace hmfnet::cuda::complete_graph {

namespace {

namespace cg = cooperative_groups;

// Chunk heads of a replica: ceil(tiles / threads) <= 2048 / 32.
constexpr int k_max_heads = 64;
static_assert(k_max_tiles / 32 <= k_max_heads,
              "a replica's chunks of 32 tiles or more fit the heads");
// Doubles of the heads' arrays: this block's heads in two buffers (a stage's and the next's, so
// that one cluster barrier a reduction suffices) of [cos, sin], and all heads gathered.
constexpr int k_heads_doubles = 2 * 2 * k_max_heads + 2 * k_max_heads;

// This block's part of its replica's shared memory, carved from the dynamic allocation.
struct ResidentState {
  double* theta;
  double* p;
  double* c;  // [cos, sin] of the angles: only where keep_phases
  double* s;
  double* sums_c;  // tile sums, by local tile
  double* sums_s;
  double* heads;      // [buffer][cos, sin][chunk]: this block's chunks' totals
  double* all_heads;  // [cos, sin][chunk]: every chunk's, gathered
};

__device__ ResidentState carve(double* shared, const TileLayout& layout, bool keep_phases) {
  const std::int64_t slots = layout.slots();
  ResidentState r{};
  r.theta = shared;
  r.p = r.theta + slots;
  double* next = r.p + slots;
  if (keep_phases) {
    r.c = next;
    r.s = r.c + slots;
    next = r.s + slots;
  }
  r.sums_c = next;
  r.sums_s = r.sums_c + layout.local_tiles();
  r.heads = r.sums_s + layout.local_tiles();
  r.all_heads = r.heads + 4 * k_max_heads;
  return r;
}

// Z (or, for a record, [sum p^2 / 2, 0]) of the replica from this block's tile sums: the levels
// inside its chunks here, its chunks' heads shared through the cluster (one barrier; `buffer`
// alternates, so a block that runs ahead writes the other buffer), then the tree over all heads.
// Every thread gets the total. The same additions as tree_sum over all tiles (tile_tree.hpp).
__device__ LocalField reduce_tiles(cg::cluster_group& cluster, const Cluster& me,
                                   const TileLayout& layout, const ResidentState& r, int buffer) {
  const int bd = static_cast<int>(blockDim.x);
  const int tid = static_cast<int>(threadIdx.x);
  const int local_chunks = layout.local_tiles() / bd;
  __syncthreads();
  for (int stride = 1; stride < bd; stride *= 2) {
    for (int j = 0; j < local_chunks; ++j) {
      const int base = (me.rank + j * me.blocks) * bd;
      if (base < layout.tiles && tree_adds_into(tid, stride, layout.tiles - base)) {
        r.sums_c[j * bd + tid] += r.sums_c[j * bd + tid + stride];
        r.sums_s[j * bd + tid] += r.sums_s[j * bd + tid + stride];
      }
    }
    __syncthreads();
  }
  double* own = r.heads + buffer * 2 * k_max_heads;
  for (int j = tid; j < local_chunks; j += bd) {
    const int q = me.rank + j * me.blocks;
    if (q * bd >= layout.tiles) continue;
    own[q] = r.sums_c[j * bd];
    own[k_max_heads + q] = r.sums_s[j * bd];
  }
  cluster.sync();
  const int chunks = layout.chunks();
  for (int q = tid; q < chunks; q += bd) {
    const int owner = q % me.blocks;
    const double* from = owner == me.rank ? own : cluster.map_shared_rank(own, owner);
    r.all_heads[q] = from[q];
    r.all_heads[k_max_heads + q] = from[k_max_heads + q];
  }
  __syncthreads();
  if (tid == 0) {
    tree_levels(r.all_heads, chunks, chunks);
    tree_levels(r.all_heads + k_max_heads, chunks, chunks);
  }
  __syncthreads();
  return LocalField{r.all_heads[0], r.all_heads[k_max_heads]};
}

// The [cos, sin] of the rotor at `slot`: kept, or formed again from its angle.
template <bool KeepPhases>
__device__ __forceinline__ void phase_at(const ResidentState& r, std::int64_t slot, double& c,
                                         double& s) {
  if constexpr (KeepPhases) {
    c = r.c[slot];
    s = r.s[slot];
  } else {
    sincos_one(r.theta[slot], c, s);
  }
}

// A stage of local tile L's rotors (tile t), their new phases summed in m's order: the global
// stepper's stage_tile, on shared memory.
template <int Batch, bool KeepPhases>
__device__ __forceinline__ void stage_tile(const RotorStage& st, const TileLayout& layout, int L,
                                           int t, const ResidentState& r, double& zc, double& zs) {
  const std::int64_t n = layout.n;
  const int tiles = layout.tiles;
  std::int64_t m = t;
  int k = 0;
  for (; m + (Batch - 1) * static_cast<std::int64_t>(tiles) < n; m += Batch * tiles, k += Batch) {
    double c[Batch], s[Batch], pm[Batch], th[Batch];
#pragma unroll
    for (int u = 0; u < Batch; ++u) {
      const std::int64_t slot = layout.slot(L, k + u);
      phase_at<KeepPhases>(r, slot, c[u], s[u]);
      pm[u] = r.p[slot];
      th[u] = r.theta[slot];
    }
#pragma unroll
    for (int u = 0; u < Batch; ++u) {
      const std::int64_t slot = layout.slot(L, k + u);
      double c_new = 0.0, s_new = 0.0;
      stage_cell(st, c[u], s[u], pm[u], th[u], c_new, s_new);
      r.p[slot] = pm[u];
      r.theta[slot] = th[u];
      if constexpr (KeepPhases) {
        r.c[slot] = c_new;
        r.s[slot] = s_new;
      }
      zc += c_new;
      zs += s_new;
    }
  }
  for (; m < n; m += tiles, ++k) {
    const std::int64_t slot = layout.slot(L, k);
    double c = 0.0, s = 0.0, c_new = 0.0, s_new = 0.0;
    phase_at<KeepPhases>(r, slot, c, s);
    double pm = r.p[slot], th = r.theta[slot];
    stage_cell(st, c, s, pm, th, c_new, s_new);
    r.p[slot] = pm;
    r.theta[slot] = th;
    if constexpr (KeepPhases) {
      r.c[slot] = c_new;
      r.s[slot] = s_new;
    }
    zc += c_new;
    zs += s_new;
  }
}

// The pending closing kick of every rotor of this thread's tiles; with `kinetic`, each tile's
// sum p^2 / 2 (in m's order) into its sums, as the global stepper's record does.
template <bool KeepPhases>
__device__ void closing_kick(const Cluster& me, const TileLayout& layout, const ResidentState& r,
                             double inverse_n, double K, double last_kick, LocalField Z,
                             bool kinetic) {
  for (int j = 0; layout.tile(me.rank, static_cast<int>(threadIdx.x), j) < layout.tiles; ++j) {
    const int t = layout.tile(me.rank, static_cast<int>(threadIdx.x), j);
    const int L = layout.local_tile(static_cast<int>(threadIdx.x), j);
    double sum = 0.0;
    int k = 0;
    for (std::int64_t m = t; m < layout.n; m += layout.tiles, ++k) {
      const std::int64_t slot = layout.slot(L, k);
      double c = 0.0, s = 0.0;
      phase_at<KeepPhases>(r, slot, c, s);
      const double g = coupling_force(inverse_n, c, s, Z);
      const double pm = kicked_momentum(r.p[slot], last_kick, K, g);
      r.p[slot] = pm;
      sum += 0.5 * pm * pm;
    }
    if (kinetic) {
      r.sums_c[L] = sum;
      r.sums_s[L] = 0.0;
    }
  }
}

// Moves this thread's rotors between the global arrays and shared memory: `load` at the launch's
// start (the [cos, sin] too where kept), else back at its end ([cos, sin] always, which the global
// stepper's next launch reads).
template <bool KeepPhases>
__device__ void move_state(const Cluster& me, const TileLayout& layout, const ResidentState& r,
                           double* theta, double* p, double* cs, bool load) {
  for (int j = 0; layout.tile(me.rank, static_cast<int>(threadIdx.x), j) < layout.tiles; ++j) {
    const int t = layout.tile(me.rank, static_cast<int>(threadIdx.x), j);
    const int L = layout.local_tile(static_cast<int>(threadIdx.x), j);
    int k = 0;
    for (std::int64_t m = t; m < layout.n; m += layout.tiles, ++k) {
      const std::int64_t slot = layout.slot(L, k);
      if (load) {
        r.theta[slot] = theta[m];
        r.p[slot] = p[m];
        if constexpr (KeepPhases) {
          r.c[slot] = cs[2 * m];
          r.s[slot] = cs[2 * m + 1];
        }
      } else {
        theta[m] = r.theta[slot];
        p[m] = r.p[slot];
        phase_at<KeepPhases>(r, slot, cs[2 * m], cs[2 * m + 1]);
      }
    }
  }
}

template <int Batch, bool KeepPhases>
__global__ void __launch_bounds__(k_max_resident_threads) resident_kernel(Arrays a, Table table) {
  extern __shared__ double shared[];
  cg::cluster_group cluster = cg::this_cluster();
  const Cluster me{static_cast<int>(cluster.block_rank()), static_cast<int>(cluster.num_blocks())};
  const auto replica_block = static_cast<int>(blockIdx.x) / me.blocks;
  const bool lead = me.rank == 0 && threadIdx.x == 0;
  const SystemInfo sys = a.systems[a.block_system[replica_block]];
  const int b = a.block_replica[replica_block];
  const std::int64_t n = sys.n;
  const TileLayout layout{n, static_cast<int>(sys.tiles), me.blocks, static_cast<int>(blockDim.x)};
  const ResidentState r = carve(shared, layout, KeepPhases);
  double* theta = a.theta + sys.state_offset + b * n;
  double* p = a.p + sys.state_offset + b * n;
  double* cs = a.cs + 2 * (sys.state_offset + b * n);
  const double inverse_n = 1.0 / static_cast<double>(n);
  const double K = sys.K;
  // A rotor is only ever touched by its tile's thread: no barrier between the load and the steps.
  move_state<KeepPhases>(me, layout, r, theta, p, cs, true);

  LocalField Z{a.z[2 * replica_block], a.z[2 * replica_block + 1]};
  double r_sum = a.r_sum[replica_block];
  const double last_kick = table.kick[table.stages];
  bool pending = false;
  int buffer = 0;
  for (std::int64_t step = 0; step < sys.steps; ++step) {
    for (int i = 0; i < table.stages; ++i) {
      const RotorStage st{inverse_n,     K, Z, pending && i == 0, last_kick, table.kick[i],
                          table.drift[i]};
      for (int j = 0; layout.tile(me.rank, static_cast<int>(threadIdx.x), j) < layout.tiles; ++j) {
        const int L = layout.local_tile(static_cast<int>(threadIdx.x), j);
        double zc = 0.0, zs = 0.0;
        stage_tile<Batch, KeepPhases>(
            st, layout, L, layout.tile(me.rank, static_cast<int>(threadIdx.x), j), r, zc, zs);
        r.sums_c[L] = zc;
        r.sums_s[L] = zs;
      }
      Z = reduce_tiles(cluster, me, layout, r, buffer);
      buffer ^= 1;
    }
    pending = true;
    const double modulus = std::sqrt(Z.re * Z.re + Z.im * Z.im);
    r_sum += modulus * inverse_n;
    const std::int64_t done = sys.steps_before + step + 1;
    if (done % sys.record_every != 0) continue;
    // A record: the pending kick applied, then sum p^2 / 2 by the same tiles and tree.
    closing_kick<KeepPhases>(me, layout, r, inverse_n, K, last_kick, Z, true);
    pending = false;
    const double kinetic = reduce_tiles(cluster, me, layout, r, buffer).re;
    buffer ^= 1;
    const std::int64_t record = done / sys.record_every - 1;
    if (lead && record < sys.records) {
      const std::int64_t at = sys.record_offset + b * sys.records + record;
      a.R_mean[at] = r_sum / static_cast<double>(sys.record_every);
      a.energy[at] = kinetic - K * (Z.re * Z.re + Z.im * Z.im) * (0.5 * inverse_n);
    }
    r_sum = 0.0;
  }
  if (pending) closing_kick<KeepPhases>(me, layout, r, inverse_n, K, last_kick, Z, false);
  move_state<KeepPhases>(me, layout, r, theta, p, cs, false);
  if (lead) {
    a.z[2 * replica_block] = Z.re;
    a.z[2 * replica_block + 1] = Z.im;
    a.r_sum[replica_block] = r_sum;
  }
  // No block leaves while another may still read its heads (the last reduction's copies).
  cluster.sync();
}

// The kernel of a batch and of keep_phases, allowed its shared memory, and its launch's
// configuration (`attribute` must outlive `config`).
template <int Batch>
auto prepared_kernel(const ResidentLaunch& shape, std::size_t shared_bytes,
                     cudaLaunchConfig_t& config, cudaLaunchAttribute& attribute) {
  const auto kernel =
      shape.keep_phases ? resident_kernel<Batch, true> : resident_kernel<Batch, false>;
  check(cudaFuncSetAttribute(kernel, cudaFuncAttributeMaxDynamicSharedMemorySize,
                             static_cast<int>(shared_bytes)),
        "the complete graph's shared memory");
  cluster_config(config, attribute, shape.clusters, shape.cluster, shape.threads, shared_bytes);
  return kernel;
}

template <int Batch>
void launch_batch(const Arrays& a, const Table& table, const ResidentLaunch& shape,
                  std::size_t shared_bytes) {
  cudaLaunchConfig_t config{};
  cudaLaunchAttribute attribute{};
  const auto kernel = prepared_kernel<Batch>(shape, shared_bytes, config, attribute);
  check(cudaLaunchKernelEx(&config, kernel, a, table), "complete graph kernel (shared memory)");
}

}  // namespace

std::size_t resident_bytes(const SystemInfo& system, int cluster, int threads, bool keep_phases) {
  const TileLayout layout{system.n, static_cast<int>(system.tiles), cluster, threads};
  const auto values = static_cast<std::size_t>(layout.slots()) * (keep_phases ? 4U : 2U) +
                      2 * static_cast<std::size_t>(layout.local_tiles()) + k_heads_doubles;
  return values * sizeof(double);
}

void launch_resident(const Arrays& a, const Table& table, const ResidentLaunch& shape,
                     std::size_t shared_bytes) {
  if (shape.batch == 1) {
    launch_batch<1>(a, table, shape, shared_bytes);
  } else if (shape.batch == 8) {
    launch_batch<8>(a, table, shape, shared_bytes);
  } else {
    launch_batch<4>(a, table, shape, shared_bytes);
  }
}

int resident_active_clusters(const ResidentLaunch& shape, std::size_t shared_bytes) {
  cudaLaunchConfig_t config{};
  cudaLaunchAttribute attribute{};
  const auto kernel = prepared_kernel<4>(shape, shared_bytes, config, attribute);
  int count = 0;
  check(cudaOccupancyMaxActiveClusters(&count, kernel, &config), "cudaOccupancyMaxActiveClusters");
  return count;
}

}  // namespace hmfnet::cuda::complete_graph

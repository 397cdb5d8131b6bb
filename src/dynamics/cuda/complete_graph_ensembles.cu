// The complete graph's block-per-replica stepper (complete_graph_ensembles.hpp). Compiled with
// --fmad=false (kernel_arithmetic.hpp says why).
#include <cooperative_groups.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/cuda/complete_graph_ensembles.hpp"
#include "dynamics/cuda/complete_graph_parts.cuh"
#include "dynamics/cuda/device_bounds.hpp"
#include "dynamics/cuda/device_buffer.cuh"
#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet::cuda {

namespace {

namespace cg = cooperative_groups;
using namespace complete_graph;

std::int64_t tile_count(std::int64_t n) { return n < k_max_tiles ? n : k_max_tiles; }

// The fixed pairwise tree over `tiles` sums (stride 1, 2, 4, ...), leaving the total in
// sums[0]; the same additions whatever blockDim is.
__device__ void tree_sum(double* sums_c, double* sums_s, int tiles) {
  __syncthreads();
  for (int stride = 1; stride < tiles; stride *= 2) {
    for (int i = 2 * stride * static_cast<int>(threadIdx.x); i + stride < tiles;
         i += 2 * stride * static_cast<int>(blockDim.x)) {
      sums_c[i] += sums_c[i + stride];
      sums_s[i] += sums_s[i + stride];
    }
    __syncthreads();
  }
}

// Rotor m's new angle: its [cos, sin] stored for the next evaluation and added to the tile's Z.
__device__ __forceinline__ void store_phase(double theta, std::int64_t m, double* __restrict__ cs,
                                            double& zc, double& zs) {
  double c = 0.0, s = 0.0;
  sincos_one(theta, c, s);
  cs[2 * m] = c;
  cs[2 * m + 1] = s;
  zc += c;
  zs += s;
}

// One rotor's stage from its loaded [cos, sin], p and theta (stage_cell), the new phase stored
// and added to the tile's sums.
__device__ __forceinline__ void stage_rotor(const RotorStage& st, double c, double s, double pm,
                                            double th, std::int64_t m, double* __restrict__ theta,
                                            double* __restrict__ p, double* __restrict__ cs,
                                            double& zc, double& zs) {
  double c_new = 0.0, s_new = 0.0;
  stage_cell(st, c, s, pm, th, c_new, s_new);
  p[m] = pm;
  theta[m] = th;
  cs[2 * m] = c_new;
  cs[2 * m + 1] = s_new;
  zc += c_new;
  zs += s_new;
}

// Rotors a thread loads before it updates any of them (stage_tile): 4 measured (1.15x one on an
// H200); 1 and 8 kept for the benchmark (set_batch).
constexpr int k_default_batch = 4;

// A stage of tile t's rotors m = t, t + tiles, ..., their new phases summed in m's order. One
// tile a thread caps a replica at 2048 threads, and one rotor at a time made each thread wait on
// memory once per rotor (the step ran at a third of its sincos bound, as fast on 128
// multiprocessors as on 64: measured on an H200). So the loads of Batch rotors go out
// together before any of them is updated; each rotor's arithmetic and the sums' order are
// unchanged: the same bits.
template <int Batch>
__device__ __forceinline__ void stage_tile(const RotorStage& st, int t, int tiles, std::int64_t n,
                                           double* __restrict__ theta, double* __restrict__ p,
                                           double* __restrict__ cs, double& zc, double& zs) {
  std::int64_t m = t;
  for (; m + (Batch - 1) * static_cast<std::int64_t>(tiles) < n; m += Batch * tiles) {
    double c[Batch], s[Batch], pm[Batch], th[Batch];
#pragma unroll
    for (int u = 0; u < Batch; ++u) {
      const std::int64_t q = m + static_cast<std::int64_t>(u) * tiles;
      c[u] = cs[2 * q];
      s[u] = cs[2 * q + 1];
      pm[u] = p[q];
      th[u] = theta[q];
    }
#pragma unroll
    for (int u = 0; u < Batch; ++u) {
      stage_rotor(st, c[u], s[u], pm[u], th[u], m + static_cast<std::int64_t>(u) * tiles, theta, p,
                  cs, zc, zs);
    }
  }
  for (; m < n; m += tiles)
    stage_rotor(st, cs[2 * m], cs[2 * m + 1], p[m], theta[m], m, theta, p, cs, zc, zs);
}

// Every block of the cluster gets all the tile sums: its own are in place; the others' are read
// from their owners' shared memory between two cluster barriers (the first: every tile written;
// the second: every copy read before any block's tree overwrites its array).
__device__ void gather_tiles(cg::cluster_group& cluster, const Cluster& me, double* sums_c,
                             double* sums_s, int tiles) {
  cluster.sync();
  if (me.blocks > 1) {
    for (int t = static_cast<int>(threadIdx.x); t < tiles; t += static_cast<int>(blockDim.x)) {
      const int owner = (t / static_cast<int>(blockDim.x)) % me.blocks;
      if (owner == me.rank) continue;
      sums_c[t] = cluster.map_shared_rank(sums_c, owner)[t];
      sums_s[t] = cluster.map_shared_rank(sums_s, owner)[t];
    }
  }
  cluster.sync();
}

template <int Batch>
__global__ void __launch_bounds__(1024)
    complete_graph_kernel(Arrays a, Table table, bool evaluate_only) {
  extern __shared__ double shared[];
  cg::cluster_group cluster = cg::this_cluster();
  const Cluster me{static_cast<int>(cluster.block_rank()), static_cast<int>(cluster.num_blocks())};
  const auto replica_block = static_cast<int>(blockIdx.x) / me.blocks;  // this cluster's replica
  const bool lead = me.rank == 0 && threadIdx.x == 0;
  const SystemInfo sys = a.systems[a.block_system[replica_block]];
  const int b = a.block_replica[replica_block];
  const std::int64_t n = sys.n;
  const int tiles = static_cast<int>(sys.tiles);
  double* sums_c = shared;
  double* sums_s = shared + k_max_tiles;
  double* __restrict__ theta = a.theta + sys.state_offset + b * n;
  double* __restrict__ p = a.p + sys.state_offset + b * n;
  double* __restrict__ cs = a.cs + 2 * (sys.state_offset + b * n);
  const double inverse_n = 1.0 / static_cast<double>(n);
  const double K = sys.K;

  // Z of the current angles: [cos, sin] formed and summed tile by tile.
  if (evaluate_only) {
    for (int t = me.first_tile(); t < tiles; t += me.tile_stride()) {
      double zc = 0.0, zs = 0.0;
      for (std::int64_t m = t; m < n; m += tiles) store_phase(theta[m], m, cs, zc, zs);
      sums_c[t] = zc;
      sums_s[t] = zs;
    }
    gather_tiles(cluster, me, sums_c, sums_s, tiles);
    tree_sum(sums_c, sums_s, tiles);
    if (lead) {
      a.z[2 * replica_block] = sums_c[0];
      a.z[2 * replica_block + 1] = sums_s[0];
    }
    return;
  }

  LocalField Z{a.z[2 * replica_block], a.z[2 * replica_block + 1]};
  double r_sum = a.r_sum[replica_block];
  const double last_kick = table.kick[table.stages];
  bool pending = false;
  for (std::int64_t step = 0; step < sys.steps; ++step) {
    for (int i = 0; i < table.stages; ++i) {
      const RotorStage st{inverse_n,     K, Z, pending && i == 0, last_kick, table.kick[i],
                          table.drift[i]};
      for (int t = me.first_tile(); t < tiles; t += me.tile_stride()) {
        double zc = 0.0, zs = 0.0;
        stage_tile<Batch>(st, t, tiles, n, theta, p, cs, zc, zs);
        sums_c[t] = zc;
        sums_s[t] = zs;
      }
      gather_tiles(cluster, me, sums_c, sums_s, tiles);
      tree_sum(sums_c, sums_s, tiles);
      Z = LocalField{sums_c[0], sums_s[0]};
      __syncthreads();  // every thread has read Z before the tiles are written again
    }
    pending = true;
    const double modulus = std::sqrt(Z.re * Z.re + Z.im * Z.im);
    r_sum += modulus * inverse_n;
    const std::int64_t done = sys.steps_before + step + 1;
    if (done % sys.record_every != 0) continue;
    // A record: the pending kick applied (the CPU's separate kick, the same bits), then
    // sum p^2 / 2 by the same tiles and tree.
    for (int t = me.first_tile(); t < tiles; t += me.tile_stride()) {
      double kinetic = 0.0;
      for (std::int64_t m = t; m < n; m += tiles) {
        const double g = coupling_force(inverse_n, cs[2 * m], cs[2 * m + 1], Z);
        const double pm = kicked_momentum(p[m], last_kick, K, g);
        p[m] = pm;
        kinetic += 0.5 * pm * pm;
      }
      sums_c[t] = kinetic;
      sums_s[t] = 0.0;
    }
    pending = false;
    gather_tiles(cluster, me, sums_c, sums_s, tiles);
    tree_sum(sums_c, sums_s, tiles);
    const std::int64_t record = done / sys.record_every - 1;
    if (lead && record < sys.records) {
      const std::int64_t at = sys.record_offset + b * sys.records + record;
      a.R_mean[at] = r_sum / static_cast<double>(sys.record_every);
      a.energy[at] = sums_c[0] - K * (Z.re * Z.re + Z.im * Z.im) * (0.5 * inverse_n);
    }
    r_sum = 0.0;
    __syncthreads();
  }
  if (pending) {
    for (int t = me.first_tile(); t < tiles; t += me.tile_stride()) {
      for (std::int64_t m = t; m < n; m += tiles) {
        const double g = coupling_force(inverse_n, cs[2 * m], cs[2 * m + 1], Z);
        p[m] = kicked_momentum(p[m], last_kick, K, g);
      }
    }
  }
  if (lead) {
    a.z[2 * replica_block] = Z.re;
    a.z[2 * replica_block + 1] = Z.im;
    a.r_sum[replica_block] = r_sum;
  }
  // No block leaves while another may still read its shared memory (the last gather's copies
  // are complete at its second barrier, before any block gets here).
}

}  // namespace

namespace {

// The global stepper's kernel for a batch of 1, 4 or 8 rotors.
auto global_kernel(int batch) {
  return batch == 1   ? complete_graph_kernel<1>
         : batch == 8 ? complete_graph_kernel<8>
                      : complete_graph_kernel<k_default_batch>;
}

// Blocks per replica: as many as leave no multiprocessor idle (a power of two up to
// k_max_cluster), but no more than the largest system's tiles fill; never fewer than `least`.
int automatic_cluster(int replicas, std::int64_t max_tiles, int threads, int least = 1) {
  int c = least;
  while (2 * c <= k_max_cluster && 2 * c * replicas <= multiprocessors() &&
         static_cast<std::int64_t>(c) * threads < max_tiles)
    c *= 2;
  return c;
}

// The most dynamic shared memory a block of the current device may take.
std::size_t shared_memory_limit() {
  int device = 0, bytes = 0;
  check(cudaGetDevice(&device), "cudaGetDevice");
  check(cudaDeviceGetAttribute(&bytes, cudaDevAttrMaxSharedMemoryPerBlockOptin, device),
        "cudaDeviceGetAttribute");
  return static_cast<std::size_t>(bytes);
}

}  // namespace

struct CompleteGraphEnsembles::Impl {
  std::vector<CompleteGraphSystem> systems;
  std::vector<SystemInfo> info;
  std::vector<std::int64_t> done;
  int threads = 512;
  int blocks = 0;         // replicas over all systems: one cluster each
  int asked_cluster = 0;  // blocks per replica as constructed (0: automatic)
  int cluster = 1;        // blocks per cluster of the global stepper
  int batch = k_default_batch;
  StatePlace place = StatePlace::global_memory;
  ResidentLaunch resident;  // the shared-memory stepper's shape, where place says so
  std::size_t resident_shared = 0;
  DeviceBuffer<SystemInfo> d_info;
  DeviceBuffer<int> block_system, block_replica;
  DeviceBuffer<double> theta, p, cs, z, r_sum, R_mean, energy;

  Arrays arrays() const {
    return {
        d_info.data(), block_system.data(), block_replica.data(), theta.data(), p.data(), cs.data(),
        z.data(),      r_sum.data(),        R_mean.data(),        energy.data()};
  }

  std::int64_t max_tiles() const {
    std::int64_t most = 1;
    for (const SystemInfo& s : info) most = std::max(most, s.tiles);
    return most;
  }

  // The largest shared memory a block of any system takes in the resident stepper.
  std::size_t resident_bytes_of(int blocks_per_replica, bool keep_phases) const {
    std::size_t most = 0;
    for (const SystemInfo& s : info) {
      most = std::max(most, resident_bytes(s, blocks_per_replica, threads, keep_phases));
    }
    return most;
  }

  void launch(const Table& table, bool evaluate_only) {
    d_info.upload(info.data(), info.size());
    if (place == StatePlace::shared_memory && !evaluate_only) {
      resident.batch = batch;
      launch_resident(arrays(), table, resident, resident_shared);
      return;
    }
    cudaLaunchConfig_t config{};
    cudaLaunchAttribute attribute{};
    cluster_config(config, attribute, blocks, cluster, threads, 2 * k_max_tiles * sizeof(double));
    check(cudaLaunchKernelEx(&config, global_kernel(batch), arrays(), table, evaluate_only),
          "complete graph kernel");
  }

  // The resident stepper's shape: blocks per replica as asked, or the fewest whose shared memory
  // holds a replica's theta and p, then more while multiprocessors are idle; the [cos, sin] kept
  // where they fit too.
  void choose_resident() {
    if ((threads & (threads - 1)) != 0 || threads > k_max_resident_threads) {
      throw DeviceError(
          "complete graph ensembles: the state in shared memory needs threads per block a power "
          "of two up to " +
          std::to_string(k_max_resident_threads) + ", not " + std::to_string(threads));
    }
    const std::size_t limit = shared_memory_limit();
    int c = asked_cluster;
    if (c == 0) {
      c = 1;
      while (c < k_max_cluster && resident_bytes_of(c, false) > limit) c *= 2;
      c = automatic_cluster(blocks, max_tiles(), threads, c);
    }
    const std::size_t needed = resident_bytes_of(c, false);
    if (needed > limit) {
      throw DeviceError("complete graph ensembles: the state in shared memory needs " +
                        std::to_string(needed) + " bytes a block on " + std::to_string(c) +
                        " blocks of " + std::to_string(threads) +
                        " threads a replica; the device allows " + std::to_string(limit));
    }
    const std::size_t keeping = resident_bytes_of(c, true);
    resident = ResidentLaunch{blocks, c, threads, batch, keeping <= limit};
    resident_shared = resident.keep_phases ? keeping : needed;
    if (resident_active_clusters(resident, resident_shared) < 1) {
      throw DeviceError("complete graph ensembles: no cluster of " + std::to_string(c) +
                        " blocks with " + std::to_string(resident_shared) +
                        " bytes of shared memory each fits this device");
    }
  }
};

CompleteGraphEnsembles::CompleteGraphEnsembles(std::vector<CompleteGraphSystem> systems,
                                               int threads_per_block, int cluster_blocks) {
  if (threads_per_block < 32 || threads_per_block > 1024 || threads_per_block % 32 != 0) {
    throw DeviceError("complete graph ensembles: threads per block " +
                      std::to_string(threads_per_block) + " is not a multiple of 32 in [32, 1024]");
  }
  if (cluster_blocks < 0 || cluster_blocks > k_max_cluster) {
    throw DeviceError("complete graph ensembles: blocks per replica " +
                      std::to_string(cluster_blocks) + " outside [1, 8] (0: automatic)");
  }
  if (systems.empty()) throw DeviceError("complete graph ensembles: no system given");
  std::int64_t state = 0, records = 0;
  int blocks = 0;
  std::vector<SystemInfo> info;
  for (const auto& s : systems) {
    if (s.n < 1 || s.n > INT32_MAX || s.replicas < 1 || s.record_every < 1 || s.records < 0) {
      throw DeviceError(
          "complete graph ensembles: a system needs 1 <= N < 2^31, replicas >= 1 "
          "and record_every >= 1");
    }
    info.push_back(
        {s.n, s.replicas, s.K, tile_count(s.n), state, records, s.record_every, s.records, 0, 0});
    state += s.n * s.replicas;
    records += s.records * s.replicas;
    blocks += s.replicas;
  }
  require_device();
  const auto bytes = static_cast<std::size_t>(state) * 4 * sizeof(double) +
                     static_cast<std::size_t>(records) * 2 * sizeof(double) +
                     static_cast<std::size_t>(blocks) * (3 * sizeof(double) + 2 * sizeof(int));
  require_memory(bytes, "the complete graph ensembles");
  m_impl = std::make_unique<Impl>();
  Impl& e = *m_impl;
  e.systems = std::move(systems);
  e.info = std::move(info);
  e.done.assign(e.systems.size(), 0);
  e.threads = threads_per_block;
  e.blocks = blocks;
  e.asked_cluster = cluster_blocks;
  e.cluster = cluster_blocks > 0 ? cluster_blocks
                                 : automatic_cluster(blocks, e.max_tiles(), threads_per_block);
  std::vector<int> bs, br;
  for (std::size_t s = 0; s < e.systems.size(); ++s) {
    for (int b = 0; b < e.systems[s].replicas; ++b) {
      bs.push_back(static_cast<int>(s));
      br.push_back(b);
    }
  }
  e.block_system.upload(bs.data(), bs.size());
  e.block_replica.upload(br.data(), br.size());
  const auto st = static_cast<std::size_t>(state);
  e.theta.allocate(st);
  e.p.allocate(st);
  e.cs.allocate(2 * st);
  e.z.allocate(2 * static_cast<std::size_t>(blocks));
  const std::vector<double> zeros(static_cast<std::size_t>(blocks), 0.0);
  e.r_sum.upload(zeros.data(), zeros.size());
  const std::vector<double> nan_records(static_cast<std::size_t>(records), NAN);
  e.R_mean.upload(nan_records.data(), nan_records.size());
  e.energy.upload(nan_records.data(), nan_records.size());
}

CompleteGraphEnsembles::~CompleteGraphEnsembles() = default;

std::size_t CompleteGraphEnsembles::systems() const { return m_impl->systems.size(); }

void CompleteGraphEnsembles::set_state(std::size_t system, const std::vector<double>& theta,
                                       const std::vector<double>& p) {
  Impl& e = *m_impl;
  const SystemInfo& s = e.info.at(system);
  const auto cells = static_cast<std::size_t>(s.n * s.replicas);
  if (theta.size() != cells || p.size() != cells) {
    throw DeviceError("complete graph ensembles: the state must hold N x replicas values");
  }
  // The CPU's node-major layout to the blocks' replica-major one.
  std::vector<double> t(cells), q(cells);
  for (std::int64_t m = 0; m < s.n; ++m) {
    for (int b = 0; b < s.replicas; ++b) {
      t[static_cast<std::size_t>(b * s.n + m)] =
          theta[static_cast<std::size_t>(m * s.replicas + b)];
      q[static_cast<std::size_t>(b * s.n + m)] = p[static_cast<std::size_t>(m * s.replicas + b)];
    }
  }
  check(cudaMemcpy(e.theta.data() + s.state_offset, t.data(), cells * sizeof(double),
                   cudaMemcpyHostToDevice),
        "cudaMemcpy to the device");
  check(cudaMemcpy(e.p.data() + s.state_offset, q.data(), cells * sizeof(double),
                   cudaMemcpyHostToDevice),
        "cudaMemcpy to the device");
  // Z of every system at its current angles (systems not set yet compute garbage harmlessly:
  // their Z is formed again when they are set).
  e.launch(Table{}, true);
}

void CompleteGraphEnsembles::get_state(std::size_t system, std::vector<double>& theta,
                                       std::vector<double>& p) const {
  const Impl& e = *m_impl;
  const SystemInfo& s = e.info.at(system);
  const auto cells = static_cast<std::size_t>(s.n * s.replicas);
  std::vector<double> t(cells), q(cells);
  check(cudaMemcpy(t.data(), e.theta.data() + s.state_offset, cells * sizeof(double),
                   cudaMemcpyDeviceToHost),
        "cudaMemcpy to the host");
  check(cudaMemcpy(q.data(), e.p.data() + s.state_offset, cells * sizeof(double),
                   cudaMemcpyDeviceToHost),
        "cudaMemcpy to the host");
  theta.resize(cells);
  p.resize(cells);
  for (std::int64_t m = 0; m < s.n; ++m) {
    for (int b = 0; b < s.replicas; ++b) {
      theta[static_cast<std::size_t>(m * s.replicas + b)] =
          t[static_cast<std::size_t>(b * s.n + m)];
      p[static_cast<std::size_t>(m * s.replicas + b)] = q[static_cast<std::size_t>(b * s.n + m)];
    }
  }
}

void CompleteGraphEnsembles::advance(const SplittingCoefficients& splitting, double h,
                                     const std::vector<std::int64_t>& steps) {
  Impl& e = *m_impl;
  const auto& kicks = splitting.kicks;
  const auto& drifts = splitting.drifts;
  if (drifts.empty() || kicks.size() != drifts.size() + 1 ||
      drifts.size() > static_cast<std::size_t>(k_max_stages)) {
    throw DeviceError("complete graph ensembles: a splitting of 1 to 8 drifts and one more kick");
  }
  if (steps.size() != e.systems.size()) {
    throw DeviceError("complete graph ensembles: one step count per system");
  }
  Table table{};
  table.stages = static_cast<int>(drifts.size());
  for (std::size_t i = 0; i < drifts.size(); ++i) table.drift[i] = drifts[i] * h;
  for (std::size_t i = 0; i < kicks.size(); ++i) table.kick[i] = kicks[i] * h;
  for (std::size_t s = 0; s < e.systems.size(); ++s) {
    e.info[s].steps_before = e.done[s];
    e.info[s].steps = std::max<std::int64_t>(0, steps[s]);
  }
  e.launch(table, false);
  for (std::size_t s = 0; s < e.systems.size(); ++s) e.done[s] += e.info[s].steps;
}

void CompleteGraphEnsembles::resume(std::size_t system, std::int64_t steps_done,
                                    const std::vector<double>& theta, const std::vector<double>& p,
                                    const CompleteGraphRecords& records) {
  Impl& e = *m_impl;
  const SystemInfo& s = e.info.at(system);
  if (steps_done < 0 || steps_done % s.record_every != 0) {
    throw DeviceError("complete graph ensembles: a run resumes at a record's end, not after " +
                      std::to_string(steps_done) + " steps (records every " +
                      std::to_string(s.record_every) + ")");
  }
  const auto count = static_cast<std::size_t>(s.records * s.replicas);
  if (records.R_mean.size() != count || records.energy.size() != count) {
    throw DeviceError("complete graph ensembles: the records to resume must hold " +
                      std::to_string(count) + " values (records x replicas)");
  }
  set_state(system, theta, p);
  if (count > 0) {
    check(cudaMemcpy(e.R_mean.data() + s.record_offset, records.R_mean.data(),
                     count * sizeof(double), cudaMemcpyHostToDevice),
          "cudaMemcpy to the device");
    check(cudaMemcpy(e.energy.data() + s.record_offset, records.energy.data(),
                     count * sizeof(double), cudaMemcpyHostToDevice),
          "cudaMemcpy to the device");
  }
  int first = 0;
  for (std::size_t q = 0; q < system; ++q) first += e.systems[q].replicas;
  check(
      cudaMemset(e.r_sum.data() + first, 0, static_cast<std::size_t>(s.replicas) * sizeof(double)),
      "cudaMemset");
  e.done[system] = steps_done;
}

std::int64_t CompleteGraphEnsembles::steps_done(std::size_t system) const {
  return m_impl->done.at(system);
}

CompleteGraphRecords CompleteGraphEnsembles::records(std::size_t system) const {
  const Impl& e = *m_impl;
  const SystemInfo& s = e.info.at(system);
  CompleteGraphRecords r;
  r.written = std::min(s.records, e.done[system] / s.record_every);
  const auto count = static_cast<std::size_t>(s.records * s.replicas);
  r.R_mean.resize(count);
  r.energy.resize(count);
  if (count > 0) {
    check(cudaMemcpy(r.R_mean.data(), e.R_mean.data() + s.record_offset, count * sizeof(double),
                     cudaMemcpyDeviceToHost),
          "cudaMemcpy to the host");
    check(cudaMemcpy(r.energy.data(), e.energy.data() + s.record_offset, count * sizeof(double),
                     cudaMemcpyDeviceToHost),
          "cudaMemcpy to the host");
  }
  return r;
}

std::vector<double> CompleteGraphEnsembles::order_sums(std::size_t system) const {
  const Impl& e = *m_impl;
  int first = 0;
  for (std::size_t s = 0; s < system; ++s) first += e.systems[s].replicas;
  std::vector<double> z(2 * static_cast<std::size_t>(e.systems.at(system).replicas));
  check(cudaMemcpy(z.data(), e.z.data() + 2 * first, z.size() * sizeof(double),
                   cudaMemcpyDeviceToHost),
        "cudaMemcpy to the host");
  return z;
}

void CompleteGraphEnsembles::synchronize() const {
  check(cudaDeviceSynchronize(), "complete graph ensembles");
}

int CompleteGraphEnsembles::cluster_blocks() const {
  return m_impl->place == StatePlace::shared_memory ? m_impl->resident.cluster : m_impl->cluster;
}

void CompleteGraphEnsembles::set_batch(int rotors) {
  if (rotors != 1 && rotors != k_default_batch && rotors != 8) {
    throw DeviceError("complete graph ensembles: a batch of " + std::to_string(rotors) +
                      " rotors is not 1, 4 or 8");
  }
  m_impl->batch = rotors;
}

int CompleteGraphEnsembles::batch() const { return m_impl->batch; }

void CompleteGraphEnsembles::set_state_place(StatePlace place) {
  if (place == StatePlace::shared_memory) m_impl->choose_resident();
  m_impl->place = place;
}

StatePlace CompleteGraphEnsembles::state_place() const { return m_impl->place; }

bool CompleteGraphEnsembles::keeps_phases() const {
  return m_impl->place == StatePlace::shared_memory && m_impl->resident.keep_phases;
}

int CompleteGraphEnsembles::active_clusters() const {
  const Impl& e = *m_impl;
  if (e.place == StatePlace::shared_memory) {
    return resident_active_clusters(e.resident, e.resident_shared);
  }
  cudaLaunchConfig_t config{};
  cudaLaunchAttribute attribute{};
  cluster_config(config, attribute, e.blocks, e.cluster, e.threads,
                 2 * k_max_tiles * sizeof(double));
  int count = 0;
  check(cudaOccupancyMaxActiveClusters(&count, global_kernel(e.batch), &config),
        "cudaOccupancyMaxActiveClusters");
  return count;
}

}  // namespace hmfnet::cuda

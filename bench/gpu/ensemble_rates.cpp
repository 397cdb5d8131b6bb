// The device's step rates beside the bounds measured in the same run (device_bounds.hpp):
//   sparse, directed ER G(N, p = d / N), d = 100: stored entries x replicas x steps / s, with
//   1 or 4 threads summing a row ("r1", "r4": sparse_ensemble.hpp);
//   the complete graph (block per replica): rotors x replicas x steps / s, and the per-step
//   time of a tiny N (the launch-independent cost: the block's syncs and Z's tree).
// Each rate is the fastest of 3 timed runs after a warm-up (host clock around a synchronised
// advance). The bound of a sparse row: the step's time is at least the largest of
//   gathers:  entries / (the measured random-gather rate of the row's record, 2 B sizeof(T)
//             bytes, from a table of N records, the [cos, sin] table of all replicas, or of
//             16 MB where that table is larger: the best case, every record from a table the
//             L2 (50-60 MB) holds whole, so that no kernel runs above it),
//   stream:   bytes the step must move once (columns 4 B per entry, 2 passes over the cells'
//             state: theta, p, g and [cos, sin] read and written) / the copy bandwidth,
//   sincos:   cells / the measured sincos rate,
//   launches: 2 x the time of an empty kernel launched back to back;
// its model (not a bound) takes the gather from the table at its own size, of which the L2 holds
// a share that varies run to run (measured: 39.1 and 43.0 G 128-byte records/s from 128 MB on
// two H200s, where the step ran at 41.0), and names the row's limit,
// and of a complete-graph row: cells / (sincos rate x min(1, blocks / multiprocessors)) (a
// replica's cluster of blocks uses one multiprocessor a block). The rank-one rows are the stepper
// of `simulate --device cuda` on K_N (rank_one_ensemble.hpp: the CPU's bits), with each step's
// order sums as a run's time average asks; their bound is the largest of the cells' stream
// (~12 doubles a cell and step), the sincos and 6 launches a step.
//
//   hmfnet_gpu_ensemble_rates [--quick] [--out FILE.csv]
// Prints the table; --out also writes it as CSV. Exit 77 where no device can run this build.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "dynamics/cuda/complete_graph_ensembles.hpp"
#include "dynamics/cuda/device.hpp"
#include "dynamics/cuda/device_bounds.hpp"
#include "dynamics/cuda/rank_one_ensemble.hpp"
#include "dynamics/cuda/sparse_ensemble.hpp"

using namespace hmfnet;

namespace {

constexpr int k_skipped = 77;

struct Row {
  std::string kind, precision, limit;
  std::int64_t n = 0;
  int replicas = 1;
  double rate = 0.0, bound = 0.0, memory_mb = 0.0, step_us = 0.0;
  double model = 0.0;  // sparse rows: the rate of the model, 0 where there is none
};

// Records of a table the L2 holds whole, with room to spare (60 MB on the H200, 50 on the H100).
constexpr std::int64_t k_resident_table_bytes = std::int64_t{16} << 20;

template <typename Advance>
double best_seconds(Advance&& advance, int runs = 3) {
  advance();  // warm-up
  double best = 1e30;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    advance();
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

void random_state(std::size_t cells, std::vector<double>& theta, std::vector<double>& p) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  std::uniform_real_distribution<double> momentum(-1.0, 1.0);
  theta.resize(cells);
  p.resize(cells);
  for (std::size_t k = 0; k < cells; ++k) {
    theta[k] = angle(rng);
    p[k] = momentum(rng);
  }
}

struct Ceilings {
  double copy = 0.0, sincos = 0.0, launch = 0.0;
  int sms = 1;
};

// per_row: threads summing a cell's row (sparse_ensemble.hpp), 0: the stepper's own choice.
Row sparse_row(const Ceilings& c, std::int64_t n, int replicas, cuda::DevicePrecision precision,
               std::int64_t steps, int per_row = 0) {
  cuda::SparseEnsemble e = cuda::SparseEnsemble::directed_er(n, 100.0, 1, replicas, precision);
  if (per_row > 0) e.set_threads_per_row(per_row);
  const auto cells = static_cast<std::size_t>(n) * static_cast<std::size_t>(replicas);
  std::vector<double> theta, p;
  random_state(cells, theta, p);
  e.set_state(theta, p);
  const auto lf = leap_frog_coefficients();
  const double s = best_seconds([&] {
    e.advance(lf, 0.01, steps);
    e.synchronize();
  });
  Row r;
  r.kind = "sparse ER d=100 r" + std::to_string(e.threads_per_row());
  r.precision = precision == cuda::DevicePrecision::float64 ? "float64" : "float32";
  r.n = n;
  r.replicas = replicas;
  const double entries = static_cast<double>(e.entries());
  r.rate = entries * replicas * static_cast<double>(steps) / s;
  r.step_us = s / static_cast<double>(steps) * 1e6;
  r.memory_mb = static_cast<double>(
                    cuda::SparseEnsemble::memory(n, e.entries(), replicas, precision).needed) /
                1e6;
  const int value_bytes = precision == cuda::DevicePrecision::float64 ? 8 : 4;
  const int record = 2 * replicas * value_bytes;
  const std::int64_t resident = std::min(n, k_resident_table_bytes / record);
  const double t_gather = entries / cuda::gather_rate(resident, record);
  const double t_table = resident == n ? t_gather : entries / cuda::gather_rate(n, record);
  // theta, p, g (8 B each, read and written in the stage; g written by the force) and the
  // [cos, sin] written once and read by the row's own cell: ~ 10 doubles per cell and step.
  const double t_stream = (entries * 4.0 + static_cast<double>(cells) * 80.0 +
                           (value_bytes == 4 ? static_cast<double>(cells) * 8.0 : 0.0)) /
                          c.copy;
  const double t_sincos = static_cast<double>(cells) / c.sincos;
  // Two launches a step (the stage, the force).
  const double t_launch = 2.0 * c.launch;
  r.bound = entries * replicas / std::max({t_gather, t_stream, t_sincos, t_launch});
  const double t = std::max({t_table, t_stream, t_sincos, t_launch});
  r.model = entries * replicas / t;
  r.limit = t == t_table ? "gather " + std::to_string(record) + " B" +
                               (resident == n ? "" : " (table over 16 MB)")
            : t == t_stream ? "stream"
            : t == t_sincos ? "sincos"
                            : "launches";
  return r;
}

// threads: per block; with few replicas, 256 lets a replica's 2048 tiles spread over a cluster of
// 8 blocks (one tile a thread), 512 over 4 (complete_graph_ensembles.cu: automatic_cluster).
// place: where the state is kept (complete_graph_ensembles.hpp). The bound: the sincos of every
// rotor and stage (twice where the shared-memory stepper forms the [cos, sin] again) on the
// multiprocessors the replicas' blocks occupy; the model of the global stepper: its 64 bytes a
// rotor and step (theta, p, [cos, sin] read and written) at the copy bandwidth, which an L2 that
// holds the state may beat, so a model, not a bound.
Row complete_row(const Ceilings& c, std::int64_t n, int replicas, std::int64_t steps,
                 int threads = 512, int batch = 0,
                 cuda::StatePlace place = cuda::StatePlace::global_memory) {
  cuda::CompleteGraphEnsembles e({{n, replicas, 1.0, steps * 10, 0}}, threads);
  if (batch > 0) e.set_batch(batch);
  e.set_state_place(place);
  const bool shared = place == cuda::StatePlace::shared_memory;
  const auto cells = static_cast<std::size_t>(n) * static_cast<std::size_t>(replicas);
  std::vector<double> theta, p;
  random_state(cells, theta, p);
  e.set_state(0, theta, p);
  const auto lf = leap_frog_coefficients();
  const double s = best_seconds([&] {
    e.advance(lf, 0.1, {steps});
    e.synchronize();
  });
  Row r;
  r.kind = std::string(shared ? "cg shared" : "complete graph") + " t" + std::to_string(threads) +
           " b" + std::to_string(e.batch());
  r.precision = "float64";
  r.n = n;
  r.replicas = replicas;
  r.rate = static_cast<double>(cells) * static_cast<double>(steps) / s;
  r.step_us = s / static_cast<double>(steps) * 1e6;
  r.memory_mb = static_cast<double>(cells) * 32.0 / 1e6;
  const int blocks = replicas * e.cluster_blocks();
  const double share = std::min(1.0, static_cast<double>(blocks) / c.sms);
  const double sincos_per_rotor = shared && !e.keeps_phases() ? 2.0 : 1.0;
  r.bound = c.sincos * share / sincos_per_rotor;
  if (!shared) r.model = std::min(r.bound, c.copy / 64.0);
  r.limit = "sincos" + std::string(sincos_per_rotor > 1.0 ? " x2" : "") + " on " +
            std::to_string(std::min(blocks, c.sms)) + " of " + std::to_string(c.sms) + " SMs (" +
            std::to_string(e.cluster_blocks()) + " a replica, " +
            std::to_string(e.active_clusters()) + " of " + std::to_string(replicas) +
            " clusters at once)" +
            (r.model > 0.0 && r.model < r.bound ? "; model: stream 64 B" : "");
  return r;
}

Row rank_one_row(const Ceilings& c, std::int64_t n, int replicas, std::int64_t steps) {
  cuda::RankOneEnsemble e(std::vector<double>(static_cast<std::size_t>(n), 1.0), false, replicas);
  const auto cells = static_cast<std::size_t>(n) * static_cast<std::size_t>(replicas);
  std::vector<double> theta, p, order;
  random_state(cells, theta, p);
  e.set_state(theta, p);
  const auto lf = leap_frog_coefficients();
  const double s = best_seconds([&] {
    order.clear();
    e.advance(lf, 0.1, steps, &order);
    e.synchronize();
  });
  Row r;
  r.kind = "rank-one (sim)";
  r.precision = "float64";
  r.n = n;
  r.replicas = replicas;
  r.rate = static_cast<double>(cells) * static_cast<double>(steps) / s;
  r.step_us = s / static_cast<double>(steps) * 1e6;
  r.memory_mb = static_cast<double>(cuda::RankOneEnsemble::memory(n, replicas).needed) / 1e6;
  // Stage: theta, p, g read, theta, p, [cos, sin] written (8 doubles); Z: [cos, sin] read (2);
  // field: [cos, sin] read, g and the two terms written (5); the terms' block sums (2).
  const double t_stream = static_cast<double>(cells) * 17.0 * 8.0 / c.copy;
  const double t_sincos = static_cast<double>(cells) / c.sincos;
  const double t_launch = 6.0 * c.launch;
  const double t = std::max({t_stream, t_sincos, t_launch});
  r.bound = static_cast<double>(cells) / t;
  r.limit = t == t_stream ? "stream" : t == t_sincos ? "sincos" : "launches";
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string out;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
      out = argv[++i];
    } else {
      std::fprintf(
          stderr,
          "hmfnet_gpu_ensemble_rates: unknown argument %s (usage: [--quick] [--out F.csv])\n",
          argv[i]);
      return 2;
    }
  }
  std::string why;
  if (!cuda::device_usable(why)) {
    std::printf("hmfnet_gpu_ensemble_rates: skipped: %s\n", why.c_str());
    return k_skipped;
  }
  try {
    std::printf("device: %s\n", cuda::device_description().c_str());
    Ceilings c;
    c.copy = cuda::copy_bandwidth(std::size_t{1} << 30);
    c.sincos = cuda::sincos_rate();
    c.sms = cuda::multiprocessors();
    c.launch = cuda::launch_seconds();
    std::printf(
        "copy bandwidth (read + write) %.0f GB/s; sincos %.1f G angles/s; %d SMs; "
        "launch %.2f us\n",
        c.copy / 1e9, c.sincos / 1e9, c.sms, c.launch * 1e6);
    for (const int bytes : {8, 16, 64, 128}) {
      std::printf("random gather of %3d-byte records: table 16 MB %.1f G/s, 1 GB %.1f G/s\n", bytes,
                  cuda::gather_rate((std::int64_t{16} << 20) / bytes, bytes) / 1e9,
                  cuda::gather_rate((std::int64_t{1} << 30) / bytes, bytes) / 1e9);
    }
    std::fflush(stdout);
    using P = cuda::DevicePrecision;
    std::vector<Row> rows;
    const std::int64_t scale = quick ? 10 : 1;
    rows.push_back(sparse_row(c, 10000, 1, P::float64, 4000 / scale));
    rows.push_back(sparse_row(c, 1000000, 1, P::float64, 400 / scale));
    rows.push_back(sparse_row(c, 1000000, 8, P::float64, 100 / scale));
    rows.push_back(sparse_row(c, 1000000, 1, P::float32, 400 / scale));
    rows.push_back(sparse_row(c, 1000000, 8, P::float32, 100 / scale));
    if (!quick) rows.push_back(sparse_row(c, 10000000, 1, P::float64, 30));
    // The other threads-a-row choice of the rows above, in the same run.
    rows.push_back(sparse_row(c, 10000, 1, P::float64, 4000 / scale, 1));
    rows.push_back(sparse_row(c, 1000000, 1, P::float64, 400 / scale, 1));
    rows.push_back(sparse_row(c, 1000000, 1, P::float32, 400 / scale, 1));
    rows.push_back(sparse_row(c, 1000000, 8, P::float64, 100 / scale, 4));
    rows.push_back(complete_row(c, 100000, 16, 2000 / scale));
    rows.push_back(complete_row(c, 100000, 16, 2000 / scale, 256));
    // The other batches of rotors loaded together (complete_graph_ensembles.hpp), same run.
    rows.push_back(complete_row(c, 100000, 16, 2000 / scale, 512, 1));
    rows.push_back(complete_row(c, 100000, 16, 2000 / scale, 512, 8));
    rows.push_back(complete_row(c, 20000, 64, 10000 / scale));
    // The state in shared memory (complete_graph_resident.cu), same run: N = 10^5 on 8 blocks of
    // 256 a replica (the [cos, sin] formed again), N = 2 10^4 x 64 on 2 blocks of 512 and of 256
    // (formed again), and the QSS campaign's 2 10^4 x 32 beside the global stepper (4 blocks of
    // 512, the [cos, sin] kept).
    rows.push_back(
        complete_row(c, 100000, 16, 2000 / scale, 256, 0, cuda::StatePlace::shared_memory));
    rows.push_back(
        complete_row(c, 20000, 64, 10000 / scale, 512, 0, cuda::StatePlace::shared_memory));
    rows.push_back(
        complete_row(c, 20000, 64, 10000 / scale, 256, 0, cuda::StatePlace::shared_memory));
    rows.push_back(complete_row(c, 20000, 32, 10000 / scale));
    rows.push_back(
        complete_row(c, 20000, 32, 10000 / scale, 512, 0, cuda::StatePlace::shared_memory));
    rows.push_back(complete_row(c, 64, 64, 20000 / scale));
    rows.push_back(rank_one_row(c, 100000, 16, 2000 / scale));
    rows.push_back(rank_one_row(c, 20000, 64, 2000 / scale));
    rows.push_back(rank_one_row(c, 1000, 32, 2000 / scale));
    std::printf("\n%-22s %-8s %9s %3s %12s %12s %6s %12s %6s %10s %9s  %s\n", "kind", "prec", "N",
                "B", "rate (G/s)", "bound (G/s)", "frac", "model (G/s)", "/model", "step (us)",
                "mem (MB)", "limit (the model's where it has one)");
    std::ofstream csv;
    if (!out.empty()) {
      csv.open(out);
      csv << "kind,precision,N,replicas,rate,bound,fraction,model,model_fraction,step_us,"
             "memory_mb,limit\n";
    }
    for (const Row& r : rows) {
      char model[32] = "           -", of_model[16] = "     -";
      if (r.model > 0.0) {
        std::snprintf(model, sizeof model, "%12.3f", r.model / 1e9);
        std::snprintf(of_model, sizeof of_model, "%5.0f%%", 100.0 * r.rate / r.model);
      }
      std::printf("%-22s %-8s %9lld %3d %12.3f %12.3f %5.0f%% %s %s %10.2f %9.1f  %s\n",
                  r.kind.c_str(), r.precision.c_str(), static_cast<long long>(r.n), r.replicas,
                  r.rate / 1e9, r.bound / 1e9, 100.0 * r.rate / r.bound, model, of_model, r.step_us,
                  r.memory_mb, r.limit.c_str());
      if (csv) {
        csv << r.kind << ',' << r.precision << ',' << r.n << ',' << r.replicas << ',' << r.rate
            << ',' << r.bound << ',' << r.rate / r.bound << ',' << r.model << ','
            << (r.model > 0.0 ? r.rate / r.model : 0.0) << ',' << r.step_us << ',' << r.memory_mb
            << ',' << r.limit << '\n';
      }
    }
  } catch (const cuda::DeviceError& e) {
    std::fprintf(stderr, "hmfnet_gpu_ensemble_rates: %s\n", e.what());
    return 1;
  }
  return 0;
}

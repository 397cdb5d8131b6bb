// The QSS lifetime campaign of qss_lifetime.cpp carried to the literature's sizes on a CUDA
// device: K_N with self-loops at K = 1, the homogeneous water-bag at U = 0.69 (the driver's
// start, its seeds 7000 + 100 N + b, rotor_state.cpp's draw), leap-frog h = 0.1, every size and
// replica side by side (complete_graph_ensembles.hpp). Records: each replica's R averaged over
// every record interval and its energy at the interval's end, 4000 records over T(N).
//   T(N) = lives x 26313 (N / 1600)^1.39: `lives` times the life the CPU's full scale measured
//   at N = 1600, carried with its fitted exponent (paper/full/beyond/: 1.39 +- 0.11).
// The run advances all sizes in launches of about `chunk` steps (whole record intervals) until
// each reaches T(N) or the wall budget is spent; a size that stops early is marked (its series
// ends there: the analysis treats a life not seen as censored, never as measured) and saved to
// DIR/qss_gpu_resume.bin, from which `--resume` goes on with the bits of an uninterrupted run
// (a size the file holds continues, a finished one stays finished, the others start afresh;
// the file's sizes this run does not step are kept in the file it writes).
//
//   hmfnet_gpu_qss_lifetime [--sizes 1000,2000,...] [--replicas 32] [--lives 3]
//                           [--budget-s 200] [--out DIR] [--resume FILE] [--chunks K]
//                           [--batch 4] [--state global|shared]
// (--chunks: stop after K launches, budget or not; for tests. --batch: rotors a thread loads
// together, 1, 4 or 8, CompleteGraphEnsembles::set_batch; --state: where a launch keeps the
// state, CompleteGraphEnsembles::set_state_place; the same bits whichever.) Writes
// DIR/qss_gpu.json (parameters, per size the steps done and the records written, the device, the
// wall time), DIR/qss_gpu.f64 (per size in order: R_mean then energy, each replicas x records,
// little-endian doubles) and, while a size is unfinished, DIR/qss_gpu_resume.bin
// (qss_resume_file.hpp). paper/scripts/qss_lifetime_gpu.py turns the first two into
// paper/full/beyond/data/qss_lifetime_gpu.h5 and the figure. Exit 77 without a usable device.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "dynamics/cuda/complete_graph_ensembles.hpp"
#include "dynamics/cuda/device.hpp"
#include "qss_resume_file.hpp"

using namespace hmfnet;

namespace {

constexpr int k_skipped = 77;
constexpr double k_h = 0.1;
constexpr double k_U = 0.69;
constexpr std::int64_t k_records = 4000;

std::vector<std::int64_t> parse_sizes(const std::string& text) {
  std::vector<std::int64_t> sizes;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) sizes.push_back(std::stoll(item));
  return sizes;
}

// qss_lifetime.cpp's start: replica b of size n from seed 7000 + 100 n + b, row r from stream r.
void start(std::int64_t n, int replicas, std::vector<double>& theta, std::vector<double>& p) {
  const double half_width = std::sqrt(3.0) * std::sqrt(2.0 * k_U - 1.0);
  const auto cells = static_cast<std::size_t>(n) * static_cast<std::size_t>(replicas);
  theta.assign(cells, 0.0);
  p.assign(cells, 0.0);
  for (int b = 0; b < replicas; ++b) {
    const auto seed = static_cast<std::uint64_t>(7000 + 100 * n + b);
    for (std::int64_t r = 0; r < n; ++r) {
      Rng rng(seed, static_cast<std::uint64_t>(r));
      const std::size_t k = static_cast<std::size_t>(r) * static_cast<std::size_t>(replicas) +
                            static_cast<std::size_t>(b);
      theta[k] = 6.283185307179586476925286766559 * rng.uniform();
      p[k] = half_width * (2.0 * rng.uniform() - 1.0);
    }
  }
}

// Sizes the resume file holds go on from it (a finished one stays finished), after their
// parameters are checked against this run's; the others start afresh. Returns the file's sizes
// this run does not step, so that the file written at its end keeps them. Throws
// std::runtime_error naming a size that differs.
std::vector<verification::QssResumeSize> resume_from(
    const std::string& path, const std::vector<cuda::CompleteGraphSystem>& systems,
    const std::vector<std::int64_t>& total, cuda::CompleteGraphEnsembles& e) {
  std::vector<verification::QssResumeSize> others;
  for (verification::QssResumeSize& saved : verification::read_qss_resume(path)) {
    bool stepped = false;
    for (std::size_t s = 0; s < systems.size(); ++s) {
      const cuda::CompleteGraphSystem& sys = systems[s];
      if (sys.n != saved.n) continue;
      if (saved.replicas != sys.replicas || saved.record_every != sys.record_every ||
          saved.records != sys.records || saved.steps_planned != total[s]) {
        throw std::runtime_error(
            path + ": N = " + std::to_string(sys.n) + " was run with " +
            std::to_string(saved.replicas) + " replicas, a record every " +
            std::to_string(saved.record_every) + " steps, " + std::to_string(saved.steps_planned) +
            " steps planned; this run has " + std::to_string(sys.replicas) + ", " +
            std::to_string(sys.record_every) + ", " + std::to_string(total[s]) +
            " (--replicas and --lives must be the first run's)");
      }
      cuda::CompleteGraphRecords records;
      records.R_mean = std::move(saved.R_mean);
      records.energy = std::move(saved.energy);
      e.resume(s, saved.steps_done, saved.theta, saved.p, records);
      stepped = true;
      std::printf("N = %6lld: resumed at step %lld from %s\n", static_cast<long long>(sys.n),
                  static_cast<long long>(saved.steps_done), path.c_str());
    }
    if (!stepped) {
      std::printf("N = %6lld: in %s, not in --sizes: kept as it is\n",
                  static_cast<long long>(saved.n), path.c_str());
      others.push_back(std::move(saved));
    }
  }
  return others;
}

// Every size's state, steps and records (and the resume file's sizes this run did not step) to
// DIR/qss_gpu_resume.bin while any is unfinished, so that --resume continues the whole campaign
// and its records come out whole; all finished: no file (an older one is removed, so that the
// folder never offers a resume its data do not continue).
void save_state(const std::string& out, const std::vector<cuda::CompleteGraphSystem>& systems,
                const std::vector<std::int64_t>& total, const cuda::CompleteGraphEnsembles& e,
                std::vector<verification::QssResumeSize> others) {
  bool unfinished = false;
  for (const verification::QssResumeSize& o : others) unfinished |= o.steps_done < o.steps_planned;
  std::vector<verification::QssResumeSize> saved;
  for (std::size_t s = 0; s < systems.size(); ++s) {
    unfinished |= e.steps_done(s) < total[s];
    verification::QssResumeSize r;
    r.n = systems[s].n;
    r.replicas = systems[s].replicas;
    r.record_every = systems[s].record_every;
    r.records = systems[s].records;
    r.steps_planned = total[s];
    r.steps_done = e.steps_done(s);
    cuda::CompleteGraphRecords records = e.records(s);
    r.R_mean = std::move(records.R_mean);
    r.energy = std::move(records.energy);
    e.get_state(s, r.theta, r.p);
    saved.push_back(std::move(r));
  }
  for (verification::QssResumeSize& o : others) saved.push_back(std::move(o));
  const std::string path = out + "/qss_gpu_resume.bin";
  if (!unfinished) {
    std::remove(path.c_str());
  } else {
    verification::write_qss_resume(path, saved);
  }
}

// Quotes and backslashes escaped for a JSON string.
std::string json_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes{20000, 10000, 5000, 2000, 1000};
  int replicas = 32;
  double lives = 3.0, budget = 200.0;
  std::int64_t chunk = 100000, chunks = 0;
  int batch = 4;
  std::string out = ".", resume, state = "global";
  if (argc % 2 == 0) {
    std::fprintf(stderr, "hmfnet_gpu_qss_lifetime: option %s has no value\n", argv[argc - 1]);
    return 2;
  }
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--sizes") {
      sizes = parse_sizes(value);
    } else if (key == "--replicas") {
      replicas = std::stoi(value);
    } else if (key == "--lives") {
      lives = std::stod(value);
    } else if (key == "--budget-s") {
      budget = std::stod(value);
    } else if (key == "--chunk") {
      chunk = std::stoll(value);
    } else if (key == "--out") {
      out = value;
    } else if (key == "--resume") {
      resume = value;
    } else if (key == "--chunks") {
      chunks = std::stoll(value);
    } else if (key == "--batch") {
      batch = std::stoi(value);
    } else if (key == "--state") {
      state = value;
    } else {
      std::fprintf(stderr, "hmfnet_gpu_qss_lifetime: unknown option %s\n", key.c_str());
      return 2;
    }
  }
  if (replicas < 1 || !(lives > 0.0) || chunk < 1 || chunks < 0 || sizes.empty() ||
      (batch != 1 && batch != 4 && batch != 8) || (state != "global" && state != "shared")) {
    std::fprintf(stderr,
                 "hmfnet_gpu_qss_lifetime: --replicas and --chunk must be >= 1, --lives > 0, "
                 "--chunks >= 0, --batch 1, 4 or 8, --state global or shared and --sizes not "
                 "empty\n");
    return 2;
  }
  std::string why;
  if (!cuda::device_usable(why)) {
    std::printf("hmfnet_gpu_qss_lifetime: skipped: %s\n", why.c_str());
    return k_skipped;
  }
  try {
    // The largest sizes first: their blocks are scheduled first, one per multiprocessor.
    std::sort(sizes.rbegin(), sizes.rend());
    std::vector<cuda::CompleteGraphSystem> systems;
    std::vector<std::int64_t> total;
    for (const std::int64_t n : sizes) {
      const double T = lives * 26313.0 * std::pow(static_cast<double>(n) / 1600.0, 1.39);
      const auto steps = static_cast<std::int64_t>(std::ceil(T / k_h / k_records)) * k_records;
      total.push_back(steps);
      systems.push_back({n, replicas, 1.0, steps / k_records, k_records});
    }
    cuda::CompleteGraphEnsembles e(systems);
    e.set_batch(batch);
    e.set_state_place(state == "shared" ? cuda::StatePlace::shared_memory
                                        : cuda::StatePlace::global_memory);
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      std::vector<double> theta, p;
      start(sizes[s], replicas, theta, p);
      e.set_state(s, theta, p);
    }
    std::vector<verification::QssResumeSize> others;
    if (!resume.empty()) others = resume_from(resume, systems, total, e);
    const auto t0 = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    const auto lf = leap_frog_coefficients();
    for (std::int64_t launches = 0; chunks == 0 || launches < chunks; ++launches) {
      std::vector<std::int64_t> steps;
      bool any = false;
      for (std::size_t s = 0; s < sizes.size(); ++s) {
        // Whole record intervals, so that a run stopped between launches resumes exactly.
        const std::int64_t every = systems[s].record_every;
        steps.push_back(
            std::min(std::max(every, chunk / every * every), total[s] - e.steps_done(s)));
        any = any || steps.back() > 0;
      }
      if (!any) break;
      e.advance(lf, k_h, steps);
      e.synchronize();
      if (elapsed() > budget) break;
    }
    const double wall = elapsed();
    std::ofstream data(out + "/qss_gpu.f64", std::ios::binary);
    std::ofstream meta(out + "/qss_gpu.json");
    meta << "{\n  \"device\": \"" << cuda::device_description() << "\",\n"
         << "  \"h\": " << k_h << ",\n  \"U\": " << k_U << ",\n  \"K\": 1,\n"
         << "  \"replicas\": " << replicas << ",\n  \"lives\": " << lives << ",\n"
         << "  \"budget_s\": " << budget << ",\n  \"wall_s\": " << wall << ",\n"
         << "  \"batch\": " << batch << ",\n"
         << "  \"state\": \"" << state << "\",\n"
         << "  \"resumed_from\": \"" << json_escaped(resume) << "\",\n"
         << "  \"records\": " << k_records << ",\n"
         << "  \"seeds\": \"7000 + 100 N + replica (rotor_state.cpp draw)\",\n  \"sizes\": [\n";
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      const cuda::CompleteGraphRecords r = e.records(s);
      data.write(reinterpret_cast<const char*>(r.R_mean.data()),
                 static_cast<std::streamsize>(r.R_mean.size() * sizeof(double)));
      data.write(reinterpret_cast<const char*>(r.energy.data()),
                 static_cast<std::streamsize>(r.energy.size() * sizeof(double)));
      meta << "    {\"N\": " << sizes[s] << ", \"record_every\": " << systems[s].record_every
           << ", \"steps_planned\": " << total[s] << ", \"steps_done\": " << e.steps_done(s)
           << ", \"records_written\": " << r.written << "}" << (s + 1 < sizes.size() ? "," : "")
           << "\n";
      std::printf("N = %6lld: %lld of %lld steps (T = %.0f of %.0f), %lld records\n",
                  static_cast<long long>(sizes[s]), static_cast<long long>(e.steps_done(s)),
                  static_cast<long long>(total[s]), static_cast<double>(e.steps_done(s)) * k_h,
                  static_cast<double>(total[s]) * k_h, static_cast<long long>(r.written));
    }
    meta << "  ]\n}\n";
    save_state(out, systems, total, e, std::move(others));
    std::printf("wall %.1f s\n", wall);
  } catch (const std::exception& err) {
    std::fprintf(stderr, "hmfnet_gpu_qss_lifetime: %s\n", err.what());
    return 1;
  }
  return 0;
}

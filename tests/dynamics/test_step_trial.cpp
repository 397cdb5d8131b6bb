// The trial of the run's first steps (step_trial.hpp): its protocol with given times, never with
// measured ones, and runs that switch thread counts or column segments during it giving the bits
// of one thread and of the unblocked rows.
#include <omp.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/simulation.hpp"
#include "dynamics/step_trial.hpp"
#include "dynamics/thread_choice.hpp"
#include "network/complete_graph.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "support/bit_difference.hpp"
#include "support/simulation_runs.hpp"

using namespace hmfnet;

namespace {

/// Runs the trial to its end with whole samples, `seconds_a_step[i]` for candidate i's steps;
/// returns the counts it asked for, one per sample.
std::vector<int> run_trial(StepTrial& trial, const std::vector<double>& seconds_a_step,
                           const std::vector<int>& candidates) {
  std::vector<int> asked;
  while (trial.active()) {
    const int threads = trial.candidate();
    asked.push_back(threads);
    const std::int64_t steps = trial.chunk_limit();
    std::size_t i = 0;
    while (candidates[i] != threads) ++i;
    trial.add(steps, seconds_a_step[i] * static_cast<double>(steps), 0);
  }
  return asked;
}

}  // namespace

TEST_CASE("The trial times the counts in turn, each after one untimed step, and keeps the fastest",
          "[threads][thread_trial]") {
  StepTrial trial({2, 1}, 5, 3);
  REQUIRE(trial.active());
  CHECK(trial.chunk_limit() == k_trial_warm_steps);
  CHECK(trial.steps() == 2 * 3 * (5 + k_trial_warm_steps));
  CHECK(trial.chosen() == 2);  // the rule's count until the trial ends
  const std::vector<int> asked = run_trial(trial, {2e-6, 1e-6}, {2, 1});
  CHECK(asked == std::vector<int>{2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1, 1});
  CHECK_FALSE(trial.active());
  CHECK(trial.chosen() == 1);
  CHECK(trial.summary() == "2: 2 us, 1: 1 us -> 1");
  CHECK(trial.chunk_limit() == std::numeric_limits<std::int64_t>::max());
  CHECK(trial.candidate() == 1);
}

TEST_CASE("The rule's count stays unless another beats it by the margin",
          "[threads][thread_trial]") {
  const double rule = 1e-5;
  StepTrial within({2, 1}, 3, 2);
  run_trial(within, {rule, (1.0 - 0.5 * k_trial_margin) * rule}, {2, 1});
  CHECK(within.chosen() == 2);
  StepTrial beyond({2, 1}, 3, 2);
  run_trial(beyond, {rule, (1.0 - 2.0 * k_trial_margin) * rule}, {2, 1});
  CHECK(beyond.chosen() == 1);
  StepTrial three({1, 2, 4}, 1, 1);
  CHECK(run_trial(three, {3e-6, 2e-6, 2.5e-6}, {1, 2, 4}) == std::vector<int>{1, 1, 2, 2, 4, 4});
  CHECK(three.chosen() == 2);
}

TEST_CASE("A slow spell of the machine as long as a count's samples cannot decide the trial",
          "[threads][thread_trial]") {
  // 2 threads take 1 us a step, 1 thread 1.4 us; a spell makes `samples` timed samples in a row
  // 1.6x slower. Taken one count after the other, some spell would cover every sample of 2 and
  // keep 1; in rounds, each count has a sample outside any such spell.
  const int samples = 3;
  for (int spell = 0; spell + samples <= 2 * samples; ++spell) {
    INFO("the spell starts at timed sample " << spell);
    StepTrial trial({1, 2}, 4, samples);
    int timed = 0;
    while (trial.active()) {
      const std::int64_t steps = trial.chunk_limit();
      double seconds = (trial.candidate() == 1 ? 1.4e-6 : 1e-6) * static_cast<double>(steps);
      if (steps == k_trial_warm_steps) {
        trial.add(steps, seconds, 0);
        continue;
      }
      if (timed >= spell && timed < spell + samples) seconds *= 1.6;
      trial.add(steps, seconds, 0);
      ++timed;
    }
    CHECK(timed == 2 * samples);
    CHECK(trial.chosen() == 2);
  }
}

TEST_CASE("A sample is the fastest of its chunks' sums, the untimed steps never count",
          "[threads][thread_trial]") {
  StepTrial trial({1, 2}, 4, 2);
  // Round 1, count 1: an untimed step that is very fast, then a sample of 4 steps in chunks of
  // 3 + 1.
  CHECK_THROWS_AS(trial.add(2, 1e-9, 0), std::invalid_argument);  // the untimed step is one
  trial.add(1, 1e-9, 0);
  CHECK(trial.chunk_limit() == 4);
  trial.add(3, 3e-6, 0);
  CHECK(trial.chunk_limit() == 1);
  CHECK_THROWS_AS(trial.add(2, 1e-6, 0), std::invalid_argument);
  trial.add(1, 5e-6, 0);  // 8 us over 4 steps: 2 us a step
  CHECK(trial.candidate() == 2);
  trial.add(1, 1e-9, 0);
  trial.add(4, 7.84e-6, 0);  // 1.96 us a step: within the margin of 2
  // Round 2.
  CHECK(trial.candidate() == 1);
  trial.add(1, 1e-9, 0);
  trial.add(4, 12e-6, 0);  // 3 us a step: the slower sample is not kept
  trial.add(1, 1e-9, 0);
  trial.add(4, 9e-6, 0);
  CHECK_FALSE(trial.active());
  CHECK(trial.chosen() == 1);
  CHECK(trial.summary() == "1: 2 us, 2: 1.96 us -> 1");
}

TEST_CASE("A change of the steps' kind starts the trial again, a few times at most",
          "[threads][thread_trial]") {
  StepTrial trial({2, 1}, 2, 1);
  trial.add(1, 1e-6, 0);
  trial.add(2, 1e-6, 0);
  CHECK(trial.candidate() == 1);  // candidate 1 now
  trial.add(1, 1e-6, 1);          // another kind: the trial starts again, this chunk uncounted
  CHECK(trial.candidate() == 2);
  CHECK(trial.chunk_limit() == k_trial_warm_steps);
  trial.add(1, 1e-6, 1);  // the same kind: the untimed step
  CHECK(trial.chunk_limit() == 2);
  for (int i = 1; i < k_trial_restarts; ++i) trial.add(1, 1e-6, 1 + i);
  CHECK(trial.active());
  trial.add(1, 1e-6, 1 + k_trial_restarts);  // one change too many
  CHECK_FALSE(trial.active());
  CHECK(trial.chosen() == 2);
  CHECK(trial.summary().rfind("no choice: the kind of step changed", 0) == 0);
}

TEST_CASE("A count far slower than the fastest so far takes no more samples",
          "[threads][thread_trial]") {
  StepTrial trial({1, 4, 2}, 1, 3);
  const std::vector<int> asked =
      run_trial(trial, {1e-6, (k_trial_abandon + 0.5) * 1e-6, 0.5e-6}, {1, 4, 2});
  CHECK(asked == std::vector<int>{1, 1, 4, 4, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2});
  CHECK(trial.chosen() == 2);
  CHECK(trial.summary() == "1: 1 us, 4: 2.5 us, 2: 0.5 us -> 2");
  StepTrial kept({1, 2}, 1, 3);  // within the factor: every sample taken
  CHECK(run_trial(kept, {1e-6, 0.9 * k_trial_abandon * 1e-6}, {1, 2}).size() == 12);
  // Once the others are dropped, the first count's samples follow each other with no untimed
  // step between them: its team is already running.
  StepTrial alone({1, 2}, 1, 3);
  const std::vector<int> alone_asked =
      run_trial(alone, {1e-6, (k_trial_abandon + 1.0) * 1e-6}, {1, 2});
  CHECK(alone_asked == std::vector<int>{1, 1, 2, 2, 1, 1, 1});
  CHECK(alone.chosen() == 1);
}

TEST_CASE("A count far slower is dropped as soon as its time passes what its whole sample may take",
          "[threads][thread_trial]") {
  // Steps the trial runs at each count, 1 us a step at 1 thread and `slow` us at 2, in the chunks
  // it asks for.
  const auto steps_at = [](double slow, StepTrial& trial) {
    std::vector<std::int64_t> steps(3, 0);
    while (trial.active()) {
      const int threads = trial.candidate();
      const std::int64_t n = trial.chunk_limit();
      steps[static_cast<std::size_t>(threads)] += n;
      trial.add(n, (threads == 1 ? 1e-6 : slow * 1e-6) * static_cast<double>(n), 0);
    }
    return steps;
  };
  // 160x slower (K_N N = 100 under PASSIVE): dropped after the untimed step and chunks of 1, 1,
  // 2, 4, 8 steps, whose 16 x 160 us pass the 2 x 1000 x 1 us a whole sample may take.
  StepTrial far({1, 2}, 1000, 3);
  const std::vector<std::int64_t> far_steps = steps_at(160.0, far);
  CHECK(far_steps[2] == k_trial_warm_steps + 16);
  // Count 1: its samples, the untimed step before the first and the one back from 2 threads.
  CHECK(far_steps[1] == 3 * 1000 + 2 * k_trial_warm_steps);
  CHECK(far.chosen() == 1);
  CHECK(far.summary() == "1: 1 us, 2: 160 us -> 1");
  // The decision is the whole sample's: 1.9x slower takes every sample (its first step within the
  // limit, the rest in one chunk), 2.1x is dropped only once its sample is whole (the sum passes
  // 2000 us at its 953rd step, in the chunk that ends it).
  StepTrial near({1, 2}, 1000, 3);
  CHECK(steps_at(1.9, near)[2] == 3 * (1000 + k_trial_warm_steps));
  CHECK(near.chosen() == 1);
  StepTrial past({1, 2}, 1000, 3);
  CHECK(steps_at(2.1, past)[2] == 1000 + k_trial_warm_steps);
  CHECK(past.chosen() == 1);
  // A count whose first step is slow (a sleeping team's wake) and the rest fast takes its whole
  // sample, in doubling chunks, and is chosen.
  StepTrial woken({1, 2}, 1000, 1);
  woken.add(1, 1e-9, 0);
  woken.add(1000, 1e-3, 0);  // count 1: 1 us a step
  woken.add(1, 1e-9, 0);     // count 2's untimed step
  CHECK(woken.chunk_limit() == 1);
  woken.add(1, 50e-6, 0);  // 50 us: past 2 x 1 us, so the sample is split
  // Split while the steps so far are past the limit (50 + 0.5 k us against 2 k us), then the rest
  // in one chunk once they are within it (at 64 steps: 81.5 against 128 us).
  std::vector<std::int64_t> chunks;
  while (woken.active()) {
    const std::int64_t n = woken.chunk_limit();
    chunks.push_back(n);
    woken.add(n, 0.5e-6 * static_cast<double>(n), 0);
  }
  CHECK(chunks == std::vector<std::int64_t>{1, 2, 4, 8, 16, 32, 936});
  CHECK(woken.chosen() == 2);
  // The first chunk of a sample of k_trial_split_steps steps is one step; a sample shorter than
  // that runs whole (its steps are large), at the first count as at the others.
  for (const std::int64_t sample : {k_trial_split_steps, k_trial_split_steps - 1}) {
    StepTrial trial({1, 2}, sample, 1);
    trial.add(1, 1e-9, 0);
    CHECK(trial.chunk_limit() == sample);
    trial.add(sample, 1e-6, 0);
    trial.add(1, 1e-9, 0);
    CHECK(trial.candidate() == 2);
    CHECK(trial.chunk_limit() == (sample == k_trial_split_steps ? 1 : sample));
  }
}

TEST_CASE("A trial of one candidate makes no choice, and bad candidates are refused",
          "[threads][thread_trial]") {
  const StepTrial none;
  CHECK_FALSE(none.active());
  CHECK(none.summary().empty());
  const StepTrial one({3}, 4, 2);
  CHECK_FALSE(one.active());
  CHECK(one.candidate() == 3);
  CHECK(one.summary().empty());
  StepTrial unfinished({1, 2}, 4, 2);
  unfinished.add(1, 1e-6, 0);
  CHECK(unfinished.summary() == "no choice: the run ended during the trial");
  CHECK_THROWS_AS(StepTrial({}, 4, 2), std::invalid_argument);
  CHECK_THROWS_AS(StepTrial({1, 1}, 4, 2), std::invalid_argument);
  CHECK_THROWS_AS(StepTrial({1, 2}, 0, 2), std::invalid_argument);
  CHECK_THROWS_AS(StepTrial({1, 2}, 4, 2, {"unsegmented"}), std::invalid_argument);
}

TEST_CASE("A trial's summary names its candidates by their labels", "[thread_trial]") {
  StepTrial trial({0, 1}, 1, 1, {"unsegmented", "16 segments"});
  CHECK(trial.candidate() == 0);
  trial.add(1, 9.0, 0);  // untimed
  trial.add(1, 2e-6, 0);
  CHECK(trial.candidate() == 1);
  trial.add(1, 9.0, 0);  // untimed: the candidate changed
  trial.add(1, 1e-6, 0);
  CHECK_FALSE(trial.active());
  CHECK(trial.chosen() == 1);
  CHECK(trial.summary() == "unsegmented: 2 us, 16 segments: 1 us -> 16 segments");
}

TEST_CASE("A trial by candidate takes each candidate's samples back to back, one untimed step each",
          "[thread_trial]") {
  StepTrial trial({0, 1}, 4, 3, {"unsegmented", "4 segments"}, SampleOrder::by_candidate);
  CHECK(trial.steps() == 2 * (3 * 4 + 1));
  std::vector<int> asked;
  std::vector<std::int64_t> chunks;
  while (trial.active()) {
    asked.push_back(trial.candidate());
    chunks.push_back(trial.chunk_limit());
    // Candidate 1 is 1.5x faster, its first sample slower (a slow spell, under k_trial_abandon).
    const double a_step = trial.candidate() == 0 ? 3e-6 : (asked.size() == 6 ? 5e-6 : 2e-6);
    trial.add(chunks.back(), a_step * static_cast<double>(chunks.back()), 0);
  }
  CHECK(asked == std::vector<int>{0, 0, 0, 0, 1, 1, 1, 1});
  CHECK(chunks == std::vector<std::int64_t>{1, 4, 4, 4, 1, 4, 4, 4});
  CHECK(trial.chosen() == 1);
  CHECK(trial.summary() == "unsegmented: 3 us, 4 segments: 2 us -> 4 segments");
  // A candidate far slower in its first sample takes no more.
  StepTrial far({0, 1}, 4, 3, {}, SampleOrder::by_candidate);
  asked.clear();
  while (far.active()) {
    asked.push_back(far.candidate());
    const std::int64_t n = far.chunk_limit();
    far.add(n, (far.candidate() == 0 ? 1e-6 : 5e-6) * static_cast<double>(n), 0);
  }
  CHECK(asked == std::vector<int>{0, 0, 0, 0, 1, 1});
  CHECK(far.chosen() == 0);
  // A chunk of another kind during the second candidate's samples starts again at the first,
  // with its untimed step.
  StepTrial kinds({0, 1}, 4, 2, {}, SampleOrder::by_candidate);
  kinds.add(1, 1e-6, 0);
  kinds.add(4, 4e-6, 0);
  kinds.add(4, 4e-6, 0);
  REQUIRE(kinds.candidate() == 1);
  kinds.add(1, 1e-6, 0);  // its untimed step
  kinds.add(4, 4e-6, 1);  // sampled steps now
  CHECK(kinds.active());
  CHECK(kinds.candidate() == 0);
  CHECK(kinds.chunk_limit() == 1);
}

namespace {

/// `p` run with the default count, two threads offered, against the same run on one thread:
/// the same bits, and a trial run to its choice, the same on every rank.
void check_trial_keeps_bits(const DistributedNetwork& d, const std::vector<double>& degrees,
                            CouplingForce& force, SimulationParameters p) {
  const ThreadCountScope offered(2);
  p.threads = 0;
  const SimulationResult tried = simulate(d, degrees, force, p);
  CHECK(omp_get_max_threads() == 2);  // restored after the run
  p.threads = 1;
  const SimulationResult one = simulate(d, degrees, force, p);
  CHECK(one.thread_trial.empty());  // a count given: no trial
  INFO(tried.thread_trial);
  const std::size_t arrow = tried.thread_trial.find("-> ");
  REQUIRE(arrow != std::string::npos);  // it ran to its choice, and went on at it
  CHECK(tried.threads == std::stoi(tried.thread_trial.substr(arrow + 3)));
  // Every rank was told the slowest rank's times: the same samples, the same choice.
  std::string first_rank = tried.thread_trial;
  ParallelSession::broadcast(first_rank, 0);
  CHECK(tried.thread_trial == first_rank);
  REQUIRE(tried.steps == one.steps);
  CHECK(tried.series.R == one.series.R);
  CHECK(tried.series.energy == one.series.energy);
  CHECK(tried.series.momentum == one.series.momentum);
  REQUIRE(tried.points.size() == one.points.size());
  for (std::size_t k = 0; k < one.points.size(); ++k) {
    CHECK(tried.points[k].R_mean == one.points[k].R_mean);
    CHECK(tried.points[k].energy_rel_error_max == one.points[k].energy_rel_error_max);
  }
}

/// The sparse cases' network: ER N = 2 10^4, mean degree 5, seed 3.
Network sparse_network() { return erdos_renyi({20000, 5.0 / 20000.0, 3}); }

/// The sparse cases' run: 3 K of 1500 steps each, a transient of 25 steps.
SimulationParameters sparse_run() {
  SimulationParameters p = test::short_run();
  p.h = 0.04;
  p.duration = 60.0;
  p.transient = 1.0;
  p.record_stride = 50;
  return p;
}

}  // namespace

TEST_CASE("A sparse run whose default count is tried on its first steps gives one thread's bits",
          "[threads][thread_trial]") {
  // ER N = 2 10^4, degree ~5: ~5 10^5 units of the rule's work a step (10^5 stored entries and
  // 2 10^4 rows of k_row_work), so samples of 8 steps and 2 x 3 x (8 + 1) = 54 trial steps; on 2
  // ranks the heaviest rank's 2.5 10^5 units, samples of 16 steps and 102 trial steps; under 1/40
  // of the 4500 steps of sparse_run() either way (simulation.cpp: thread_trial). The transient ends
  // after 25 steps, inside the trial, which then starts again on sampled steps.
  const Network net = sparse_network();
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = sparse_run();
  check_trial_keeps_bits(d, net.degrees(), force, p);
}

TEST_CASE("A rank-one run whose default count is tried gives one thread's bits",
          "[threads][thread_trial]") {
  // K_N N = 2000, 16 replicas: 4.8 10^5 units a step, samples of 9 steps, 60 trial steps of the
  // 4500 below (on 2 ranks: 2.4 10^5 units, samples of 17 steps, 108 trial steps). One block of the
  // ordered sums (2048 rows): one thread takes the fused pass, two the separate passes
  // (rank_one_fused.cpp), so the trial switches between the two.
  const CompleteGraph graph = CompleteGraph::make(2000, false);
  const DistributedNetwork d(graph);
  RankOneForce force(complete_graph_structure(graph), d.first_row(), d.local_size());
  SimulationParameters p = test::short_run();
  p.K = {1.0, 2.0};  // K lambda / N = 1, 2: the all-to-all HMF's scale
  p.replicas.clear();
  for (std::uint64_t seed = 11; seed < 27; ++seed) p.replicas.push_back({6.0, 1.0, seed});
  p.h = 0.04;
  p.duration = 90.0;
  p.transient = 1.0;
  p.record_stride = 50;
  check_trial_keeps_bits(d, std::vector<double>(std::size_t{2000}, graph.degree()), force, p);
}

TEST_CASE("A count given to one rank keeps every rank from a trial", "[threads][thread_trial]") {
  // A trial on some ranks only would reduce its chunk times on those alone and leave the others
  // waiting in another collective. The run of the sparse case above, with a count given to the
  // last rank (as OMP_NUM_THREADS set for one rank only would give it): no rank makes a trial,
  // and the bits are one thread's. On one rank the default count is tried as above.
  const Network net = sparse_network();
  const DistributedNetwork d(net);
  NetworkForce force(d);
  const ThreadCountScope offered(2);
  SimulationParameters p = sparse_run();
  const bool several = ParallelSession::ranks() > 1;
  p.threads = several && ParallelSession::rank() == ParallelSession::ranks() - 1 ? 2 : 0;
  const SimulationResult mixed = simulate(d, net.degrees(), force, p);
  INFO(mixed.thread_trial);
  CHECK(mixed.thread_trial.empty() == several);
  p.threads = 1;
  const SimulationResult one = simulate(d, net.degrees(), force, p);
  REQUIRE(mixed.steps == one.steps);
  CHECK(mixed.series.R == one.series.R);
  CHECK(mixed.series.energy == one.series.energy);
}

TEST_CASE("A resumed run tries the default count only where its trial fits the steps left",
          "[threads][thread_trial][checkpoint]") {
  // The network and run of the sparse case above: trials of 54 steps on one rank and 102 on two,
  // 54 x 40 = 2160 and 102 x 40 = 4080 of the 4500 steps (simulation.cpp: trial_fits). Stopped
  // after 100 steps, 4400 are left and the resumed run tries again; stopped after 3000, 1500 are
  // left, under 40 trials on either, and it keeps the rule's count.
  const Network net = sparse_network();
  const DistributedNetwork d(net);
  NetworkForce force(d);
  const ThreadCountScope offered(2);
  SimulationParameters p = sparse_run();
  p.threads = 0;
  p.checkpoint_path = test::temp_path("hmfnet_test_trial_resume");
  p.checkpoint_seconds = 0.0;
  for (const std::int64_t stop : {std::int64_t{100}, std::int64_t{3000}}) {
    INFO("stopped after " << stop << " steps");
    test::remove_on_root(p.checkpoint_path);
    p.resume = false;
    p.stop_after_steps = stop;
    const SimulationResult first = simulate(d, net.degrees(), force, p);
    REQUIRE(first.steps == stop);
    // The first run makes its trial; begun again where the 25-step transient ends, it ends
    // within 100 steps on one rank (by step 81), after them on two (by step 101 at the earliest).
    INFO(first.thread_trial);
    CHECK_FALSE(first.thread_trial.empty());
    if (stop == 3000 || ParallelSession::ranks() == 1)
      CHECK(first.thread_trial.find("-> ") != std::string::npos);
    p.resume = true;
    p.stop_after_steps = 0;
    const SimulationResult resumed = simulate(d, net.degrees(), force, p);
    REQUIRE(resumed.resumed);
    REQUIRE(resumed.steps == 4500);
    INFO(resumed.thread_trial);
    const bool tried = resumed.thread_trial.find("-> ") != std::string::npos;
    CHECK(tried == (stop == 100));
    if (!tried) CHECK(resumed.thread_trial.empty());
  }
  test::remove_on_root(p.checkpoint_path);
}

namespace {

/// ER N = 2000, mean degree 27, seed 5, float64 with 4 replicas (64-byte records, a table of
/// 128 KB), its force reading caches of 8 KiB L2 and a 32 KiB core complex's L3: slices of 16
/// KiB a thread would be 8, capped at floor(27 / 6) = 4 segments (on either rank of 2 too), whose
/// carried sums (4 x 8 x 64 = 2048 B a row) exceed the lines they save (27 x 64 = 1728 B), so
/// the rule leaves the rows unblocked and the trial tries 4 segments of 500 columns
/// (column_segments.hpp: trial_segment_width).
struct SegmentTrialCase {
  Network net = erdos_renyi({2000, 27.0 / 2000.0, 5});
  DistributedNetwork d{net};
  static CacheSizes caches() { return {std::size_t{8} << 10, std::size_t{32} << 10, 1, true}; }
};

/// A sparse force that records the segment counts a run asks it for.
class RecordingForce : public NetworkForce {
 public:
  using NetworkForce::NetworkForce;
  void use_segments(int count) override {
    asked.push_back(count);
    NetworkForce::use_segments(count);
  }
  std::vector<int> asked;
};

/// One K of 10,000 steps with 4 replicas: a step is ~2.2 10^5 stored entries x lanes (on 2 ranks
/// the heavier rank's ~1.1 10^5), so samples of 19 steps (38 on 2 ranks) and 2 x (3 x 19 + 1) =
/// 116 trial steps (230), under 1/40 of the 10,000 (simulation.cpp: consider_segment_trial).
SimulationParameters segment_trial_run() {
  SimulationParameters p = test::short_run();
  p.h = 0.04;
  p.duration = 400.0;
  // No transient and one record: the run's first chunk would otherwise be the whole run.
  p.transient = 0.0;
  p.K = {40.0};
  p.record_stride = 1'000'000;
  p.replicas = {{6.0, 1.0, 11}, {6.0, 1.0, 12}, {6.0, 1.0, 13}, {6.0, 1.0, 14}};
  p.threads = 1;
  return p;
}

}  // namespace

TEST_CASE("A sparse force offers the segments its rule left for the carry alone, and runs them",
          "[column_segments][thread_trial]") {
  const ThreadCountScope one(1);
  SegmentTrialCase c;
  NetworkForce force(c.d);
  force.read_caches_as(SegmentTrialCase::caches());
  RotorState state = initial_state(c.d.first_row(), c.d.local_size(), segment_trial_run().replicas);
  std::vector<double> g, g_cut;
  ForceSums sums, sums_cut;
  force.evaluate(state, g, sums);
  CHECK(force.segments() == 1);
  const std::vector<int> candidates = force.segment_candidates();
  REQUIRE(candidates.size() == 2);
  CHECK(candidates[0] == 1);
  CHECK(candidates[1] == 4);
  force.use_segments(4);
  force.evaluate(state, g_cut, sums_cut);
  CHECK(force.segments() == 4);
  CHECK(test::bit_difference(g_cut, g) == "");  // the same additions in the same order
  CHECK(test::bit_difference(sums_cut.order, sums.order) == "");
  CHECK(test::bit_difference(sums_cut.coupling, sums.coupling) == "");
  force.use_segments(1);
  force.evaluate(state, g_cut, sums_cut);
  CHECK(force.segments() == 1);
  CHECK(test::bit_difference(g_cut, g) == "");
  // One replica (16-byte records) is segmented by the rule itself: nothing to try.
  RotorState single = initial_state(c.d.first_row(), c.d.local_size(), {{6.0, 1.0, 11}});
  force.evaluate(single, g, sums);
  CHECK(force.segments() > 1);
  CHECK(force.segment_candidates().empty());
  // A width given: no choice.
  NetworkForce given(c.d, ForcePrecision::float64, k_unsegmented);
  given.read_caches_as(SegmentTrialCase::caches());
  given.evaluate(state, g, sums);
  CHECK(given.segment_candidates().empty());
}

TEST_CASE(
    "A sparse run whose column segments are tried on its first steps gives the unblocked bits",
    "[column_segments][thread_trial]") {
  SegmentTrialCase c;
  RecordingForce force(c.d);
  force.read_caches_as(SegmentTrialCase::caches());
  NetworkForce unblocked(c.d, ForcePrecision::float64, k_unsegmented);
  const SimulationParameters p = segment_trial_run();
  const SimulationResult tried = simulate(c.d, c.net.degrees(), force, p);
  const SimulationResult plain = simulate(c.d, c.net.degrees(), unblocked, p);
  CHECK(plain.segment_trial.empty());
  CHECK(tried.thread_trial.empty());  // a count given
  INFO(tried.segment_trial);
  // It ran to its choice (every rank told the slowest rank's times: the same choice).
  CHECK(tried.segment_trial.find("unsegmented: ") == 0);
  CHECK(tried.segment_trial.find(", 4 segments: ") != std::string::npos);
  const bool cut = tried.segment_trial.find("-> 4 segments") != std::string::npos;
  CHECK((cut || tried.segment_trial.find("-> unsegmented") != std::string::npos));
  CHECK(force.segments() == (cut ? 4 : 1));  // and went on at it
  // The rule's choice first (an earlier run's is not this one's), the slices' samples in 4
  // segments, the choice last.
  REQUIRE(force.asked.size() >= 3);
  CHECK(force.asked.front() == 1);
  CHECK(std::count(force.asked.begin(), force.asked.end(), 4) >= 1);
  CHECK(force.asked.back() == (cut ? 4 : 1));
  std::string first_rank = tried.segment_trial;
  ParallelSession::broadcast(first_rank, 0);
  CHECK(tried.segment_trial.substr(tried.segment_trial.find("->")) ==
        first_rank.substr(first_rank.find("->")));
  REQUIRE(tried.steps == plain.steps);
  CHECK(tried.series.R == plain.series.R);
  CHECK(tried.series.energy == plain.series.energy);
  CHECK(tried.series.momentum == plain.series.momentum);
  REQUIRE(tried.points.size() == plain.points.size());
  for (std::size_t k = 0; k < plain.points.size(); ++k)
    CHECK(tried.points[k].R_mean == plain.points[k].R_mean);
}

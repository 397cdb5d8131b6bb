#pragma once
// A choice among settings that give the same bits, made by timing the run's own first steps at
// each: the default thread count, and the column segments of the sparse force where its rule
// cannot tell from what the machine reports which runs faster (NetworkForce::
// segment_candidates). Results are bit-identical for any thread count and any segment width, so
// a run can take its first steps at each candidate, time them, and go on at the fastest: the
// steps are the run's own, none is repeated and no result changes.
// Why threads: the rule in work units (thread_choice.hpp) stands for two costs of the machine,
// what a second thread adds to a step (its barriers and wake-ups) and the time a unit of work
// takes. Measured on two machines they differ by ~8x and ~3x (docs/performance.md, "The thread
// rule on the AMD EPYC"), so no constant serves both. Why segments: 64-byte records at N = 10^6
// ran 1.5-2.3x faster in L3 slices than unblocked on one AMD EPYC guest and 1.2-2.2x slower on
// another that reports the same caches (docs/performance.md, "64-byte records on the AMD EPYC
// family 25 model 17").
//
// The protocol (a pure function of the steps it is told of, so it is tested with given times): in
// `samples` rounds, each candidate in order takes one step untimed where the candidate changes (a
// team starts or wakes, a force cuts its segments again: NetworkForce::prepare_segments), then
// a timed sample of `sample_steps`; once every other candidate is dropped, the first one's samples
// run back to back. The rounds interleave the candidates, so a slow spell of the machine (a
// VM's neighbour, a clock change) that lasts a few samples slows samples of every candidate, not
// all of one (on the AMD EPYC, one trial's three consecutive samples of 2 threads all ran ~40%
// slower than their usual, and a benchmark row kept 1 thread where 2 ran 1.40x faster:
// docs/performance.md, "The thread trial in rounds"). The candidate whose fastest sample (per step)
// is fastest is kept, the first candidate (the rule's) unless another is faster by more than
// k_trial_margin. A candidate whose sample in the first round is slower than k_trial_abandon times
// the fastest before it takes no more samples. A sample is made of whole chunks (the caller limits
// each chunk to chunk_limit()) of one kind, a number the caller gives to steps of one cost (a
// segment's integrator and step; sampled steps form the order sums, transient ones do not): a chunk
// of another kind starts the trial again, itself uncounted (it ran at whatever candidate was
// being tried), at most k_trial_restarts times; after that, or if the run ends first, the first
// candidate stays.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace hmfnet {

/// A candidate must beat the first candidate's fastest sample by this fraction to be chosen: a
/// VM's run-to-run spread of a few per cent must not move a run off the rule's choice for nothing.
inline constexpr double k_trial_margin = 0.03;
/// How often a change of the chunks' kind may start the trial again before it gives up.
inline constexpr int k_trial_restarts = 2;
/// Untimed steps before a candidate's sample where the candidate changes, and before the first
/// candidate's first sample (the step at which the trial starts may not be of its kind).
inline constexpr std::int64_t k_trial_warm_steps = 1;
/// A candidate this much slower than the fastest before it, in the first round, is dropped:
/// an all-cores team that sleeps at every barrier may run many times slower than one thread.
inline constexpr double k_trial_abandon = 2.0;
/// A first-round sample of at least this many steps, of a candidate that may be dropped, starts
/// with a chunk of one step. Where that step took more than k_trial_abandon times the fastest
/// count's step, the sample goes on in chunks of 1, 2, 4, ... steps and the candidate is dropped
/// at the first chunk whose sum passes k_trial_abandon times the fastest count's whole sample: a
/// sum that can only grow, so the whole sample would have dropped it too. Otherwise the rest runs
/// in one chunk, as a whole sample. Each chunk adds its start (the integrator's preparation, a
/// sleeping team's wake) to the sum, at most ~13 of them: it could drop a count that the whole
/// sample keeps only where those starts outweigh the fastest count's whole sample. Without the
/// split a count X times slower paid X of those samples: on K_N N = 100 under
/// OMP_WAIT_POLICY=PASSIVE (2 threads ~160x slower a step than 1, 2667-step samples) the trial's
/// sample at 2 threads cost ~0.35 s of a ~2 s run, which then ran at 0.66 of one thread's rate
/// (the 2-core Intel Xeon family 6 model 106, `bash bench/thread_rule.sh build complete`); now
/// about 4 of the fastest count's samples at most. Samples under 16 steps (steps of more than
/// ~270,000 units) stay whole: a second thread's cost is then a fraction of a step.
inline constexpr std::int64_t k_trial_split_steps = 16;

/// The order of the samples: in rounds (every candidate once a round, the protocol above), or
/// each candidate's samples back to back, the candidates in order: where a change of candidate
/// costs what rounds would pay several times (the segments' switch from the slices back to the
/// unblocked rows rebuilds the network's column indices beside the slices' copy: +21% peak RSS
/// at ER N = 10^6, degree 100, float32 with 8 replicas, docs/performance.md, "A trial of the
/// column segments").
enum class SampleOrder { rounds, by_candidate };

class StepTrial {
 public:
  /// No trial: active() is false and the setting stays what the caller set.
  StepTrial() = default;
  /// `candidates`: distinct settings (thread counts, or the caller's numbers for its choices),
  /// the rule's first; `sample_steps` >= 1; `samples` >= 1; `labels`: what summary() calls each
  /// candidate (empty: its number).
  StepTrial(std::vector<int> candidates, std::int64_t sample_steps, int samples,
            std::vector<std::string> labels = {}, SampleOrder order = SampleOrder::rounds);

  bool active() const { return m_active; }
  /// The candidate the next chunk runs at (while active).
  int candidate() const;
  /// Steps the next chunk may take: k_trial_warm_steps for the untimed step before a sample, else
  /// what is left of the current sample, or less where a first-round sample is split
  /// (k_trial_split_steps); no limit when inactive.
  std::int64_t chunk_limit() const;
  /// A chunk of `steps` (<= chunk_limit()) that took `seconds` at candidate(); `kind`: its cost
  /// class (steps of one kind cost the same at a given candidate).
  void add(std::int64_t steps, double seconds, std::int64_t kind);
  /// Steps of one whole trial with every sample taken: candidates x samples x (sample steps +
  /// k_trial_warm_steps) in rounds, candidates x (samples x sample steps + k_trial_warm_steps)
  /// by candidate.
  std::int64_t steps() const;
  /// The candidate chosen once the trial ended; the first candidate before that or if it gave up.
  int chosen() const { return m_chosen; }
  /// Each candidate's fastest sample in microseconds a step (of a candidate dropped before its
  /// first sample ended, the steps it took), and the choice: "1: 81.2 us, 2: 47.9 us -> 2" (with
  /// labels: "unsegmented: 81.2 us, 16 segments: 47.9 us -> 16 segments"), or why
  /// there was no choice; empty where no trial was made.
  std::string summary() const;

 private:
  void restart();
  void advance();
  void finish();
  /// Whether the sample being taken is the first round's of a candidate that may be dropped.
  bool may_drop() const { return m_round == 0 && m_candidate > 0; }
  /// The fastest sample so far of the candidates before the current one, seconds a step.
  double fastest_before() const;

  std::vector<int> m_candidates;
  std::vector<std::string> m_labels;  ///< one a candidate
  std::int64_t m_sample_steps = 0;
  int m_samples = 0;
  SampleOrder m_order = SampleOrder::rounds;
  bool m_active = false;
  int m_chosen = 0;
  int m_restarts = 0;
  std::int64_t m_kind = 0;  ///< the kind of the trial's chunks, fixed by its first chunk
  bool m_kind_known = false;
  std::size_t m_candidate = 0;  ///< index of the candidate being timed
  int m_round = 0;              ///< 0..samples - 1
  bool m_warm = false;          ///< the next chunk is the untimed step before a sample
  std::vector<bool> m_dropped;  ///< candidates that take no more samples
  std::int64_t m_steps_in_sample = 0;
  double m_seconds_in_sample = 0.0;
  /// Each candidate's fastest sample, seconds a step (a dropped one's: the steps it took).
  std::vector<double> m_best;
  std::string m_gave_up;  ///< why the trial ended without a choice
};

}  // namespace hmfnet

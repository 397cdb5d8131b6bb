// The rank-one force's fused pass (CouplingForce::kick_drift_evaluate, rank_one_fused.hpp) must
// give the bits of the kick-drift pass followed by an evaluation: theta, p, g, the sums and the
// local fields, for one, two and three groups of 8 replicas (AVX-512, AVX2 or baseline lanes),
// with and without the diagonal, non-uniform a, one and two kicks a pass, one and two threads,
// several blocks of the ordered sums; after a force_only pass too (whose g the next pass forms
// again); with angles beyond the sincos's reduced range; in every instruction set this CPU runs;
// and through the splittings' steps(), where a count that is no multiple of 8 keeps the
// separate passes.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "dynamics/integrator.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/rank_one_fused.hpp"
#include "dynamics/team.hpp"
#include "dynamics/thread_choice.hpp"
#include "support/bit_difference.hpp"

using namespace hmfnet;

namespace {

RotorState replicas(NodeIndex rows, int count, NodeIndex first_row = 0) {
  std::vector<InitialCondition> ic;
  ic.reserve(static_cast<std::size_t>(count));
  for (int b = 0; b < count; ++b)
    ic.push_back({1.0 + 0.5 * b, 0.4 + 0.1 * b, static_cast<std::uint64_t>(80 + b)});
  return initial_state(first_row, rows, ic);
}

// a_n = 0.5 .. 1.1: a weighted rank-one network (the disordered HMF), so that a_n and a_n^2
// multiply something other than 1 (the pass leaves the products out where every a_n is 1).
RankOneStructure weighted(NodeIndex n, bool diagonal) {
  std::vector<double> a(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = 0.5 + 0.1 * static_cast<double>(i % 7);
  return {a, diagonal};
}

std::vector<double> couplings(int count) {
  std::vector<double> K;
  K.reserve(static_cast<std::size_t>(count));
  for (int b = 0; b < count; ++b) K.push_back(3.0 + 0.25 * b);
  return K;
}

// The same force, never fused: the integrators then take the kick-drift pass and evaluate().
class SeparatePasses : public CouplingForce {
 public:
  explicit SeparatePasses(CouplingForce& force) : m_force(&force) {}
  void prepare(const RotorState& state, std::vector<double>& g, ForceSums& sums) override {
    m_force->prepare(state, g, sums);
  }
  EdgeOffset work_per_evaluation() const override { return m_force->work_per_evaluation(); }
  const char* name() const override { return "separate passes"; }
  const std::vector<double>& local_fields() const override { return m_force->local_fields(); }

 private:
  void compute(const RotorState& state, std::vector<double>& g, ForceSums& sums,
               ForceOutputs outputs) override {
    m_force->evaluate(state, g, sums, outputs);
  }
  CouplingForce* m_force;
};

// The pass `c` then an evaluation, separately: a kick per coefficient, then the kick-drift pass
// (the joined pass's operations in its order: kick_drift_lanes.hpp).
void separate(RotorState& s, const std::vector<double>& K, const KickDriftCoefficients& c,
              RankOneForce& force, std::vector<double>& g, ForceSums& sums, ForceOutputs outputs) {
  in_team([&] {
    if (c.kick_count == 2) kick(s, c.kicks[0], K, g);
    kick_drift(s, c.kicks[c.kick_count - 1], K, g, c.drift);
    force.evaluate(s, g, sums, outputs);
  });
}

struct Run {
  RotorState state;
  std::vector<double> g;
  ForceSums sums;
};

// Rows [first_row, first_row + rows) of a network of structure.a.size() nodes (a rank's rows).
struct Rows {
  NodeIndex first_row;
  NodeIndex rows;
};

// Whether `force` fuses a pass on `state`, asked inside a team of the current thread count.
bool fuses_in_team(const RankOneForce& force, const RotorState& state) {
  bool fuses = false;
  in_team([&] {
    const bool here = force.fuses_kick_drift(state);
#pragma omp master
    fuses = here;
  });
  return fuses;
}

// Two passes from the same start, the first force_only, the second with the sums, fused and
// separate: every output the same bits. Every 97th angle times `spread`.
void check_fused(const RankOneStructure& structure, Rows rows, int count, int threads,
                 double spread) {
  const ThreadCountScope scope(threads);
  const std::vector<double> K = couplings(count);
  const KickDriftCoefficients first{{0.05, 0.0}, 1, 0.1};
  const KickDriftCoefficients joined{{0.05, 0.05}, 2, 0.1};
  Run fused{replicas(rows.rows, count, rows.first_row), {}, {}};
  for (std::size_t k = 0; k < fused.state.theta.size(); k += 97) fused.state.theta[k] *= spread;
  Run apart = fused;
  RankOneForce fusing(structure, rows.first_row, rows.rows);
  RankOneForce plain(structure, rows.first_row, rows.rows);
  fusing.prepare(fused.state, fused.g, fused.sums);
  plain.prepare(apart.state, apart.g, apart.sums);
  in_team([&] { fusing.evaluate(fused.state, fused.g, fused.sums); });
  in_team([&] { plain.evaluate(apart.state, apart.g, apart.sums); });
  REQUIRE(test::bit_difference(fused.g, apart.g) == "");
  REQUIRE(fuses_in_team(fusing, fused.state));
  // One pass `c` both ways, then the same state.
  const auto pass = [&](const KickDriftCoefficients& c, ForceOutputs outputs) {
    in_team([&] { fusing.kick_drift_evaluate(fused.state, K, c, fused.g, fused.sums, outputs); });
    separate(apart.state, K, c, plain, apart.g, apart.sums, outputs);
    CHECK(test::bit_difference(fused.state.theta, apart.state.theta) == "");
    CHECK(test::bit_difference(fused.state.p, apart.state.p) == "");
  };
  pass(first, ForceOutputs::force_only);
  pass(joined, ForceOutputs::force_and_sums);
  CHECK(test::bit_difference(fused.g, apart.g) == "");
  CHECK(test::bit_difference(fused.sums.order, apart.sums.order) == "");
  CHECK(test::bit_difference(fused.sums.coupling, apart.sums.coupling) == "");
  CHECK(test::bit_difference(fusing.local_fields(), plain.local_fields()) == "");
}

// `name`'s 17 steps on the rank-one force, fused where it fuses (`fuses`, asked inside the team),
// against the same force behind SeparatePasses; with `record`, every step's order and coupling
// sums as after_step reads them (fused, each formed by the next step's first pass).
void check_steps(const std::string& name, NodeIndex n, int count, int threads, bool record,
                 bool fuses, bool ones = false) {
  const ThreadCountScope scope(threads);
  const auto method = make_integrator(name);
  const std::vector<double> K = couplings(count);
  const RankOneStructure structure =
      ones ? RankOneStructure{std::vector<double>(static_cast<std::size_t>(n), 1.0), false}
           : weighted(n, false);
  RankOneForce fusing(structure, 0, n), inner(structure, 0, n);
  SeparatePasses plain(inner);
  RotorState a = replicas(n, count), b = a;
  ForceEvaluation fa(fusing), fb(plain);
  fa.update(a);
  fb.update(b);
  CHECK(fuses_in_team(fusing, a) == fuses);
  std::vector<double> order_a, order_b;  // and the coupling sums
  const auto after = [&](ForceEvaluation& f, std::vector<double>& order) {
    return record ? std::function<void()>([&] {
      order.insert(order.end(), f.sums().order.begin(), f.sums().order.end());
      order.insert(order.end(), f.sums().coupling.begin(), f.sums().coupling.end());
    })
                  : std::function<void()>();
  };
  method->steps(a, 0.05, K, fa, 17, after(fa, order_a));
  method->steps(b, 0.05, K, fb, 17, after(fb, order_b));
  CHECK(test::bit_difference(a.theta, b.theta) == "");
  CHECK(test::bit_difference(a.p, b.p) == "");
  CHECK(test::bit_difference(fa.g(), fb.g()) == "");
  CHECK(test::bit_difference(order_a, order_b) == "");
  CHECK(test::bit_difference(fa.sums().order, fb.sums().order) == "");
  CHECK(test::bit_difference(fa.sums().coupling, fb.sums().coupling) == "");
  CHECK(fa.count() == fb.count());
}

}  // namespace

TEST_CASE("The rank-one fused pass has the bits of the kick-drift pass and an evaluation",
          "[rank_one_fused]") {
  // 6500 rows: four blocks of the ordered sums (2048 rows), so that 2 threads fuse (4, 8 and 12
  // items of a block and 8 replicas).
  const NodeIndex n = 6500;
  for (const bool diagonal : {true, false}) {
    for (const int count : {8, 16, 24}) {
      for (const int threads : {1, 2}) {
        INFO((diagonal ? "with" : "without")
             << " the diagonal, " << count << " replicas, " << threads << " threads");
        check_fused(weighted(n, diagonal), {0, n}, count, threads, 1.0);
      }
    }
  }
  SECTION("a = 1 (the complete graph), whose products by a_n the pass leaves out") {
    for (const bool diagonal : {true, false}) {
      for (const int threads : {1, 2}) {
        INFO((diagonal ? "with" : "without") << " the diagonal, " << threads << " threads");
        check_fused({std::vector<double>(static_cast<std::size_t>(n), 1.0), diagonal}, {0, n}, 16,
                    threads, 1.0);
      }
    }
  }
  SECTION("a rank's rows: a offset by its first row") {
    check_fused(weighted(7000, false), {700, 6200}, 16, 1, 1.0);
    check_fused(weighted(7000, true), {700, 6200}, 8, 2, 1.0);
  }
}

TEST_CASE("The rank-one fused pass takes angles beyond the reduced range from the C library",
          "[rank_one_fused]") {
  // Every 97th angle times 10^9: beyond k_reduced_range (sincos.hpp), where the vector lanes
  // compute a meaningless value that the C library's must replace before Z sums it.
  for (const int threads : {1, 2}) {
    for (const int count : {8, 16}) {
      INFO(count << " replicas, " << threads << " threads");
      check_fused(weighted(6500, false), {0, 6500}, count, threads, 1e9);
    }
  }
}

TEST_CASE("The rank-one fused pass has the same bits in every instruction set and grouping",
          "[rank_one_fused]") {
  const NodeIndex n = 53;
  const int count = 16;
  const std::vector<double> K = couplings(count);
  for (const bool ones : {false, true}) {
    for (const bool diagonal : {true, false}) {
      for (const int kicks : {1, 2}) {
        INFO((diagonal ? "with" : "without")
             << " the diagonal, " << kicks << " kicks, " << (ones ? "a = 1" : "weighted"));
        const RankOneStructure structure =
            ones ? RankOneStructure{std::vector<double>(static_cast<std::size_t>(n), 1.0), diagonal}
                 : weighted(n, diagonal);
        RotorState start = replicas(n, count);
        start.theta[37] = 3e8;  // beyond the reduced range: the C library's [cos, sin]
        std::vector<double> cs(2 * start.theta.size()), z(2 * static_cast<std::size_t>(count));
        for (std::size_t k = 0; k < start.theta.size(); ++k) {
          cs[2 * k] = std::cos(start.theta[k]);
          cs[2 * k + 1] = std::sin(start.theta[k]);
        }
        for (std::size_t b = 0; b < z.size(); ++b) z[b] = 10.0 + static_cast<double>(b);
        const KickDriftCoefficients c{{0.05, 0.07}, kicks, 0.1};
        // A stored g (ReadG) in place of the field where kicks == 2: the same in every set too.
        const bool read_g = kicks == 2;
        std::vector<double> g_formed(start.theta.size());
        for (std::size_t k = 0; k < g_formed.size(); ++k)
          g_formed[k] = std::sin(0.1 * static_cast<double>(k));
        // One call a group, or (whole) all the groups in one call, their stages side by side;
        // with a = 1, the products by a_n left out (unit_a) everywhere but in the baseline run.
        const auto run = [&](SincosIsa isa, bool whole = false, bool plain = false) {
          const bool unit_a = ones && !plain;
          Run out{start, cs, {}};
          std::vector<double> z_out(z.size());
          const RankOneFusedCells cells{structure.a.data(),
                                        out.g.data(),
                                        z.data(),
                                        read_g ? g_formed.data() : nullptr,
                                        1.0 / n,
                                        diagonal,
                                        out.state.p.data(),
                                        out.state.theta.data(),
                                        K.data(),
                                        static_cast<std::size_t>(count),
                                        unit_a};
          const std::size_t step = whole ? static_cast<std::size_t>(count) : k_fused_group;
          for (std::size_t b0 = 0; b0 < static_cast<std::size_t>(count); b0 += step)
            rank_one_fused_groups(isa, cells, c, 0, static_cast<std::size_t>(n), b0, b0 + step,
                                  z_out.data());
          out.sums.order = z_out;
          return out;
        };
        const Run baseline = run(SincosIsa::baseline, false, true);
        for (const SincosIsa isa : {SincosIsa::avx2, SincosIsa::avx512}) {
          if (!sincos_isa_available(isa)) continue;
          INFO(sincos_isa_name(isa));
          const Run wide = run(isa);
          CHECK(test::bit_difference(wide.state.theta, baseline.state.theta) == "");
          CHECK(test::bit_difference(wide.state.p, baseline.state.p) == "");
          CHECK(test::bit_difference(wide.g, baseline.g) == "");  // the new [cos, sin]
          CHECK(test::bit_difference(wide.sums.order, baseline.sums.order) == "");  // the groups' Z
          INFO("all the groups in one call");
          const Run joined = run(isa, true);
          CHECK(test::bit_difference(joined.state.theta, baseline.state.theta) == "");
          CHECK(test::bit_difference(joined.state.p, baseline.state.p) == "");
          CHECK(test::bit_difference(joined.g, baseline.g) == "");
          CHECK(test::bit_difference(joined.sums.order, baseline.sums.order) == "");
        }
        const Run joined = run(SincosIsa::baseline, true);
        CHECK(test::bit_difference(joined.state.theta, baseline.state.theta) == "");
        CHECK(test::bit_difference(joined.sums.order, baseline.sums.order) == "");
      }
    }
  }
}

TEST_CASE("The splittings' steps on the rank-one force: fused, the bits of the separate passes",
          "[rank_one_fused]") {
  for (const std::string name : {"leapfrog", "yoshida4", "blanes_moan"}) {
    for (const bool record : {false, true}) {
      for (const int count : {8, 9, 16}) {
        INFO(name << ", " << count << " replicas, 1 thread, " << (record ? "" : "no ")
                  << "record a step");
        check_steps(name, 700, count, 1, record, count % 8 == 0);
      }
      // Two threads: 4500 rows are three blocks, 6 items of 8 replicas, 3 a thread.
      INFO(name << ", 16 replicas, 2 threads, " << (record ? "" : "no ") << "record a step");
      check_steps(name, 4500, 16, 2, record, true);
      INFO("a = 1 (the complete graph)");
      check_steps(name, 700, 16, 1, record, true, true);
    }
  }
}

TEST_CASE("The rank-one force fuses only where its last evaluation was at the state's phases",
          "[rank_one_fused]") {
  // Two states on one force: after the second's evaluation the first's steps must take the
  // separate passes (with its own g), since the force's [cos, sin] and Z are the second's.
  const NodeIndex n = 300;
  const ThreadCountScope scope(1);
  const std::vector<double> K = couplings(8);
  RankOneForce shared(weighted(n, false), 0, n), alone(weighted(n, false), 0, n);
  RotorState s1 = replicas(n, 8), s2 = replicas(n, 8), expected = s1;
  for (double& theta : s2.theta) theta += 1.0;
  ForceEvaluation f1(shared), f2(shared), f_expected(alone);
  f1.update(s1);
  f_expected.update(expected);
  CHECK(shared.fuses_kick_drift(s1));
  f2.update(s2);
  CHECK_FALSE(shared.fuses_kick_drift(s1));
  LeapFrog().steps(s1, 0.05, K, f1, 5, {});
  LeapFrog().steps(expected, 0.05, K, f_expected, 5, {});
  CHECK(test::bit_difference(s1.theta, expected.theta) == "");
  CHECK(test::bit_difference(s1.p, expected.p) == "");
  CHECK(test::bit_difference(f1.g(), f_expected.g()) == "");
}

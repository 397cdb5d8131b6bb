// The blow-up guard (dynamics/blow_up_guard.hpp): silent within the tolerance, and otherwise one
// message that names the K, the time, the replica, the error and the largest stable step
// h < limit / sqrt(K max_n R_n).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "dynamics/blow_up_guard.hpp"

using namespace hmfnet;

namespace {

struct Fixture {
  std::vector<double> K{2.0, 2.0, 8.0, 8.0};  // two K across two replicas each
  std::vector<double> errors{1e-4, 1e-4, 1e-4, 1e-4};
  Observables observed;
  int order_calls = 0;

  RunRecord record() {
    RunRecord r;
    r.K = &K;
    r.segment_step = 30;
    r.segment_steps = 100;
    r.h = 0.1;
    r.observed = &observed;
    r.energy_errors = &errors;
    r.integrator = "leapfrog";
    r.stability_limit = 2.0;
    r.max_node_order = [this] {
      ++order_calls;
      return 0.5;
    };
    return r;
  }
};

}  // namespace

TEST_CASE("The blow-up guard is silent within the tolerance and asks for no collective",
          "[blow_up]") {
  Fixture f;
  BlowUpGuard guard(1e-2, 2);
  REQUIRE_NOTHROW(guard.on_record(f.record()));
  REQUIRE(f.order_calls == 0);
}

TEST_CASE("The blow-up message names the replica of its K and the stable step", "[blow_up]") {
  Fixture f;
  BlowUpGuard guard(1e-2, 2);
  f.errors[3] = 0.5;
  // omega_max = sqrt(8 x 0.5) = 2, so h < 2 / 2 = 1; lane 3 is replica 1 of K = 8.
  REQUIRE_THROWS_WITH(guard.on_record(f.record()),
                      "K = 8, t = 3 (replica 1 of this K): relative energy error 0.5 exceeds the "
                      "tolerance 0.01; the step h = 0.1 is likely too large for this K: leapfrog "
                      "is stable for h * omega_max < 2 with omega_max = sqrt(K max_n R_n) = 2, "
                      "i.e. h < 1");
  f.errors[3] = 1e-4;
  f.errors[0] = std::nan("");
  REQUIRE_THROWS_WITH(guard.on_record(f.record()),
                      Catch::Contains("(replica 0 of this K): energy is NaN or infinite"));
}

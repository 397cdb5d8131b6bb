// The paper pipeline's step rule (verification/support/pipeline_step.hpp): the table of the
// full-scale work-precision run, the sigma0 scaling and whole numbers of steps per segment.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "support/pipeline_step.hpp"

using hmfnet::StepChoice;
using hmfnet::verification::pipeline_step;
using hmfnet::verification::whole_steps;

namespace {

// T and T1 in steps of h are whole numbers (to 1e-9: the simulation rounds T / h).
bool whole(double time, double h) { return std::abs(time / h - std::round(time / h)) < 1e-9; }

}  // namespace

TEST_CASE("Pipeline step: the work-precision table at sigma0 = 0.35", "[pipeline_step]") {
  // T = 1280, T1 = 640 are whole numbers of every tabulated step: the table itself.
  REQUIRE(pipeline_step(0.0, 0.35, 1280, 640) == StepChoice{"leapfrog", 0.32});
  REQUIRE(pipeline_step(0.5, 0.35, 1280, 640) == StepChoice{"leapfrog", 0.32});
  REQUIRE(pipeline_step(0.9, 0.35, 1280, 640) == StepChoice{"leapfrog", 0.16});
  REQUIRE(pipeline_step(1.5, 0.35, 1280, 640) == StepChoice{"leapfrog", 0.16});
  REQUIRE(pipeline_step(2.0, 0.35, 1280, 640) == StepChoice{"blanes_moan", 0.16});
  REQUIRE(pipeline_step(3.0, 0.35, 1280, 640) == StepChoice{"blanes_moan", 0.16});
  REQUIRE(pipeline_step(4.0, 0.35, 1280, 640) == StepChoice{"blanes_moan", 0.08});
}

TEST_CASE("Pipeline step: larger sigma0 halves the step / smaller keeps it", "[pipeline_step]") {
  REQUIRE(pipeline_step(1.2, 0.7, 1280, 640).h == 0.08);  // omega_max x 2
  REQUIRE(pipeline_step(1.2, 0.5, 1280, 640).h == 0.08);  // x 1.43: halved once
  REQUIRE(pipeline_step(1.2, 0.2, 1280, 640).h == 0.16);  // never enlarged
  REQUIRE(pipeline_step(1.2, 1.4, 1280, 640).h == 0.04);  // x 4: halved twice
}

TEST_CASE("Pipeline step: T and T1 are whole numbers of steps", "[pipeline_step]") {
  for (const double T : {300.0, 1000.0, 400.0, 100.0})
    for (const double T1 : {150.0, 500.0, 50.0, 0.0})
      for (const double x : {0.0, 1.2, 2.0, 4.0}) {
        const double h = pipeline_step(x, 0.35, T, T1).h;
        REQUIRE(whole(T, h));
        REQUIRE(whole(T1, h));
        REQUIRE(h <= pipeline_step(x, 0.35, 1280, 640).h);       // never above the table
        REQUIRE(h > 0.9 * pipeline_step(x, 0.35, 1280, 640).h);  // and close to it
      }
  REQUIRE(whole_steps(0.32, 300, 150) == Approx(150.0 / 469.0).epsilon(1e-15));
  REQUIRE(whole_steps(0.32, 300.5, 150) == 0.32);  // not whole time units: unchanged
}

TEST_CASE("Pipeline step: outside the measured range is refused", "[pipeline_step]") {
  REQUIRE_THROWS_AS(pipeline_step(7.0, 0.35, 100, 50), std::invalid_argument);
  REQUIRE_THROWS_AS(pipeline_step(NAN, 0.35, 100, 50), std::invalid_argument);
  REQUIRE_THROWS_AS(pipeline_step(1.0, 0.0, 100, 50), std::invalid_argument);
}

TEST_CASE("Pipeline step: the scale-free scene's choice", "[pipeline_step]") {
  using hmfnet::verification::SceneFamily;
  REQUIRE(pipeline_step(1.2, 0.35, 1280, 640, SceneFamily::scale_free) ==
          StepChoice{"leapfrog", 0.32});
  REQUIRE(pipeline_step(3.0, 0.35, 1280, 640, SceneFamily::scale_free) ==
          StepChoice{"leapfrog", 0.32});
  REQUIRE(pipeline_step(4.0, 0.35, 1280, 640, SceneFamily::scale_free) ==
          StepChoice{"leapfrog", 0.16});
  // sigma0 = 1 (Fig. R_vs_K_theoretical b): omega_max x 2.86, two halvings.
  REQUIRE(pipeline_step(3.0, 1.0, 1280, 640, SceneFamily::scale_free).h == 0.08);
}

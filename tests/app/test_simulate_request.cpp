// The simulate request's one check (app/simulate_request.hpp): every value out of range is refused
// in the words the CLI grammar used (tests/cli/option_ranges.txt has the same rows from the
// command line, but for the --seed that wraps with --replicas: its rows run one replica),
// whether the request came from the CLI or from Python.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <string>

#include "app/option_checks.hpp"
#include "app/simulate_request.hpp"
#include "core/error.hpp"
#include "dynamics/simulation_parameters.hpp"

using namespace hmfnet;
using app::SimulateRequest;

namespace {

SimulateRequest valid() {
  SimulateRequest r;
  r.input = "net.mtx";
  r.K = {1.0};
  return r;
}

std::string refusal(const std::function<void(SimulateRequest&)>& change) {
  SimulateRequest r = valid();
  change(r);
  try {
    app::validate(r);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("A valid request passes and gives the CLI's parameters", "[app]") {
  SimulateRequest r = valid();
  r.replicas = 3;
  r.seed = 7;
  r.K_over_Kc = {2.0};
  r.K.clear();
  REQUIRE_NOTHROW(app::validate(r));
  const SimulationParameters p = app::simulation_parameters(r, 0.5);
  REQUIRE(p.K == std::vector<double>{1.0});
  REQUIRE(p.replicas.size() == 3);
  REQUIRE(p.replicas[2].seed == 9);
  REQUIRE(p.continue_state);
}

TEST_CASE("Every value out of range is refused in the CLI's words", "[app]") {
  using R = SimulateRequest;
  CHECK(refusal([](R& r) { r.sigma0 = std::nan(""); }) ==
        "--sigma0: value nan is not allowed (allowed: > 0)");
  CHECK(refusal([](R& r) { r.omega = INFINITY; }) ==
        "--omega: value inf is not allowed (allowed: finite)");
  CHECK(refusal([](R& r) { r.momenta = "lorentz"; }) ==
        "--momenta: lorentz not in {gaussian,waterbag}");
  CHECK(refusal([](R& r) { r.K = {-1.0}; }) == "--K: value -1 is not allowed (allowed: >= 0)");
  CHECK(refusal([](R& r) { r.K = {}; }) == "one of --K, --K-over-Kc or --K-sweep is required");
  CHECK(refusal([](R& r) { r.sweep = "0:1:0.5"; }) ==
        "--K, --K-over-Kc and --K-sweep exclude each other: give one of them");
  CHECK(refusal([](R& r) { r.h = 0.0; }) == "--h: value 0 is not allowed (allowed: > 0)");
  CHECK(refusal([](R& r) { r.h = -0.1; }) == "--h: value -0.1 is not allowed (allowed: > 0)");
  CHECK(refusal([](R& r) { r.T = -1.0; }) == "--T: value -1 is not allowed (allowed: > 0)");
  CHECK(refusal([](R& r) { r.transient = -1.0; }) ==
        "--transient: value -1 is not allowed (allowed: >= 0)");
  CHECK(refusal([](R& r) { r.replicas = 65; }) == "--replicas: Value 65 not in range 1 to 64");
  CHECK(refusal([](R& r) { r.threads = 1025; }) == "--threads: Value 1025 not in range 1 to 1024");
  CHECK(refusal([](R& r) { r.resume = true; }) == "--checkpoint with --resume is required");
  CHECK(refusal([](R& r) { r.rotor_node = -1; }) ==
        "--rotor-node: value -1 is not allowed (allowed: >= 0)");
  CHECK(refusal([](R& r) { r.phase_bins = 0; }) ==
        "--phase-bins: Value 0 not in range 1 to 100000");
  CHECK(refusal([](R& r) { r.record_stride = 0; }) ==
        "--record-stride: Value 0 not in range 1 to 1000000000");
  CHECK(refusal([](R& r) { r.energy_tolerance = 0.0; }) ==
        "--energy-tolerance: value 0 is not allowed (allowed: > 0)");
  CHECK(refusal([](R& r) { r.integrator = "euler"; }) ==
        "integrator: euler (allowed: leapfrog, yoshida4, blanes_moan, rk4)");
  CHECK(refusal([](R& r) { r.force = "dense"; }) == "--force: dense not in {auto,sparse,rank-one}");
  CHECK(refusal([](R& r) { r.precision = "half"; }) ==
        "--precision: half not in {float64,float32}");
  CHECK(refusal([](R& r) { r.transient = 2000.0; }).find("transient") != std::string::npos);
  CHECK(refusal([](R& r) {
          r.seed = 18446744073709551615ULL;
          r.replicas = 2;
        }) ==
        "--seed: value 18446744073709551615 is not allowed (allowed: <= 2^64 - 2 = "
        "18446744073709551614 with --replicas 2; the replicas take seeds seed..seed+B-1)");
}

TEST_CASE("The last replica's seed may be 2^64 - 1 and no seed wraps", "[app]") {
  SimulateRequest r = valid();
  r.replicas = 64;
  r.seed = 18446744073709551615ULL - 63;
  REQUIRE_NOTHROW(app::validate(r));
  const SimulationParameters p = app::simulation_parameters(r, 1.0);
  REQUIRE(p.replicas.front().seed == r.seed);
  REQUIRE(p.replicas.back().seed == 18446744073709551615ULL);
  r.replicas = 1;
  r.seed = 18446744073709551615ULL;
  REQUIRE_NOTHROW(app::validate(r));
}

TEST_CASE("A sweep expands to its values, and one too long or not of three parts is refused",
          "[app]") {
  REQUIRE(app::parse_sweep("1:2:0.5") == std::vector<double>{1.0, 1.5, 2.0});
  REQUIRE_THROWS_WITH(app::parse_sweep("0:1:1e-300"),
                      "--K-sweep: 0:1:1e-300 gives 1e+300 K values (allowed: at most 10000 K "
                      "values per run)");
  REQUIRE_THROWS_WITH(app::parse_sweep("1:2"), Catch::Contains("START:STOP:STEP"));
  // A fourth part, even an empty one, is not the grammar (a trailing ':' once read as 1:2:0.5).
  REQUIRE_THROWS_WITH(app::parse_sweep("1:2:0.5:"), Catch::Contains("START:STOP:STEP"));
  REQUIRE_THROWS_WITH(app::parse_sweep("1:2:0.5:1"), Catch::Contains("START:STOP:STEP"));
}

TEST_CASE("A value is shown as the shortest text that reads back to it", "[app]") {
  REQUIRE(app::shortest_text(0.1) == "0.1");
  REQUIRE(app::shortest_text(-0.1) == "-0.1");
  REQUIRE(app::shortest_text(1e-300) == "1e-300");
  REQUIRE(app::shortest_text(0.30000000000000004) == "0.30000000000000004");
  REQUIRE(app::shortest_text(std::nan("")) == "nan");
  // Fixed for 1e-4 <= |x| < 1e4, as printf's %g; elsewhere the shorter notation.
  REQUIRE(app::shortest_text(100.0) == "100");
  REQUIRE(app::shortest_text(-0.0001) == "-0.0001");
  REQUIRE(app::shortest_text(0.0005) == "0.0005");
  REQUIRE(app::shortest_text(9999.5) == "9999.5");
  REQUIRE(app::shortest_text(1e-5) == "1e-05");
  REQUIRE(app::shortest_text(120000.0) == "120000");
  REQUIRE(app::shortest_text(1e6) == "1e+06");
  REQUIRE(app::shortest_text(1e300) == "1e+300");
  REQUIRE(app::shortest_text(-HUGE_VAL) == "-inf");
}

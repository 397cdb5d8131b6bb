// The theory request's check (app/theory_request.hpp), in the words of
// tests/cli/option_ranges.txt.
#include <catch2/catch.hpp>
#include <cmath>

#include "app/theory_request.hpp"
#include "support/request_refusal.hpp"

using namespace hmfnet;
using app::TheoryRequest;
using test::refusal;

TEST_CASE("A theory request out of range is refused in the CLI's words", "[app]") {
  using R = TheoryRequest;
  R valid;
  valid.sigma0 = 0.35;
  valid.K = {1.0, 2.0};
  CHECK(refusal<R>(valid, [](R&) {}) == "accepted");
  CHECK(refusal<R>(valid, [](R& r) { r.sigma0 = -0.35; }) ==
        "--sigma0: value -0.35 is not allowed (allowed: > 0)");
  CHECK(refusal<R>(valid, [](R& r) { r.momenta = "lorentz"; }) ==
        "--momenta: lorentz not in {gaussian,waterbag}");
  CHECK(refusal<R>(valid, [](R& r) {
          r.K = {1.0, 0.0};
        }) == "--K: value 0 is not allowed (allowed: > 0)");
  CHECK(refusal<R>(valid, [](R& r) {
          r.K = {1.0, std::nan("")};
        }) == "--K: value nan is not allowed (allowed: > 0)");
  CHECK(refusal<R>(valid, [](R& r) { r.K = {}, r.K_over_Kc = {INFINITY}; }) ==
        "--K-over-Kc: value inf is not allowed (allowed: > 0)");
  CHECK(refusal<R>(valid, [](R& r) { r.K_over_Kc = {2.0}; }) == "--K excludes --K-over-Kc");
  CHECK(refusal<R>(valid, [](R& r) { r.K = {}; }) ==
        "--K / --K-over-Kc: neither given (allowed: one of them, a list of values)");
  CHECK(refusal<R>(valid, [](R& r) { r.tolerance = 0.0; }) ==
        "--tolerance: value 0 is not allowed (allowed: 1e-14 <= x <= 0.01)");
}

// The spectrum request's check (app/spectrum_request.hpp), in the words of
// tests/cli/option_ranges.txt.
#include <catch2/catch.hpp>
#include <cmath>

#include "app/spectrum_request.hpp"
#include "support/request_refusal.hpp"

using namespace hmfnet;
using app::SpectrumRequest;
using test::refusal;

TEST_CASE("A spectrum request out of range is refused in the CLI's words", "[app]") {
  using R = SpectrumRequest;
  const R valid;
  CHECK(refusal<R>(valid, [](R&) {}) == "accepted");
  CHECK(refusal<R>(valid, [](R& r) { r.sigma0 = 0.35; }) == "accepted");
  CHECK(refusal<R>(valid, [](R& r) { r.sigma0 = 0.0; }) ==
        "--sigma0: value 0 is not allowed (allowed: > 0)");
  CHECK(refusal<R>(valid, [](R& r) { r.tolerance = std::nan(""); }) ==
        "--tolerance: value nan is not allowed (allowed: 1e-15 <= x <= 0.01)");
  CHECK(refusal<R>(valid, [](R& r) { r.tolerance = 0.1; }) ==
        "--tolerance: value 0.1 is not allowed (allowed: 1e-15 <= x <= 0.01)");
  CHECK(refusal<R>(valid, [](R& r) { r.tolerance = 1e-15; }) == "accepted");
  CHECK(refusal<R>(valid, [](R& r) { r.lambda2 = "exact"; }) ==
        "--lambda2: exact not in {auto,converged,bound}");
}

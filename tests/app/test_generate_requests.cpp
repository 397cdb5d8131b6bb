// The generators' checks (app/generate_requests.hpp), in the words of
// tests/cli/option_ranges.txt: ranges, options that set one quantity two ways, and parameters
// that can draw no edge.
#include <catch2/catch.hpp>
#include <cmath>

#include "app/generate_requests.hpp"
#include "support/request_refusal.hpp"

using namespace hmfnet;
using test::refusal;

TEST_CASE("An Erdos-Renyi request is refused in the CLI's words", "[app]") {
  using R = app::ErRequest;
  R valid;
  valid.n = 50;
  valid.q = 0.1;
  CHECK(refusal<R>(valid, [](R&) {}) == "accepted");
  CHECK(refusal<R>(valid, [](R& r) { r.n = 0; }) == "--n: Value 0 not in range 1 to 2147483647");
  CHECK(refusal<R>(valid, [](R& r) {
          r.n = 1;
        }).rfind("--n: value 1 is not allowed (allowed: >= 2;", 0) == 0);
  CHECK(refusal<R>(valid, [](R& r) { r.q = std::nan(""); }) ==
        "--q: value nan is not allowed (allowed: 0 <= q <= 1)");
  CHECK(refusal<R>(valid, [](R& r) { r.q = 1.5; }) ==
        "--q: value 1.5 is not allowed (allowed: 0 <= q <= 1)");
  CHECK(refusal<R>(valid, [](R& r) {
          r.q = 0.0;
        }).rfind("--q: value 0 is not allowed (allowed: 0 < q <= 1; it links no pair", 0) == 0);
  CHECK(refusal<R>(valid, [](R& r) { r.q.reset(), r.mean_degree = -1.0; }) ==
        "--mean-degree: value -1 is not allowed (allowed: >= 0)");
  CHECK(refusal<R>(valid, [](R& r) { r.mean_degree = 3.0; }) == "--q excludes --mean-degree");
  CHECK(refusal<R>(valid, [](R& r) { r.q.reset(); }) == "one of --q or --mean-degree is required");
  // A node has at most n - 1 neighbours: n - 1 is the complete graph, anything above is refused.
  CHECK(refusal<R>(valid, [](R& r) { r.q.reset(), r.mean_degree = 49.0; }) == "accepted");
  CHECK(refusal<R>(valid, [](R& r) { r.q.reset(), r.mean_degree = 49.5; }) ==
        "--mean-degree: value 49.5 is not allowed (allowed: <= n - 1 = 49 with --n 50; a node has "
        "at most n - 1 neighbours)");
}

TEST_CASE("A scale-free request is refused in the CLI's words", "[app]") {
  using R = app::SfRequest;
  R valid;
  valid.n = 100;
  valid.alpha = 2.5;
  valid.d_min = 3.0;
  CHECK(refusal<R>(valid, [](R&) {}) == "accepted");
  CHECK(refusal<R>(valid, [](R& r) { r.alpha = 2.0; }) ==
        "--alpha: value 2 is not allowed (allowed: > 2)");
  CHECK(refusal<R>(valid, [](R& r) { r.d_min = 0.0; }) ==
        "--dmin: value 0 is not allowed (allowed: > 0)");
  CHECK(refusal<R>(valid, [](R& r) { r.cutoff = 0.0; }) ==
        "--cutoff: value 0 is not allowed (allowed: > 0, or inf)");
  CHECK(refusal<R>(valid, [](R& r) { r.link = "linear"; }) ==
        "--link: linear not in {capped,poisson,odds}");
  CHECK(refusal<R>(valid, [](R& r) { r.mean_degree = 4.0; }) == "--dmin excludes --mean-degree");
  CHECK(refusal<R>(valid, [](R& r) { r.d_min.reset(); }) ==
        "one of --dmin or --mean-degree is required");
  // A degree above n - 1 cannot be drawn; for --dmin, the targets' mean d_min (alpha - 1) /
  // (alpha - 2) = 3 d_min at alpha = 2.5 is what must not exceed it.
  CHECK(refusal<R>(valid, [](R& r) { r.d_min.reset(), r.mean_degree = 99.0; }) == "accepted");
  CHECK(refusal<R>(valid, [](R& r) {
          r.d_min.reset(), r.mean_degree = 100.0;
        }).rfind("--mean-degree: value 100 is not allowed (allowed: <= n - 1 = 99 with", 0) == 0);
  CHECK(refusal<R>(valid, [](R& r) { r.d_min = 33.0; }) == "accepted");
  CHECK(refusal<R>(valid, [](R& r) { r.d_min = 34.0; }) ==
        "--dmin: value 34 is not allowed (allowed: a mean target degree of 102 > n - 1 = 99 with "
        "--n 100 and --alpha 2.5; a node has at most n - 1 neighbours)");
}

TEST_CASE("Block-model, complete and regular requests are refused in the CLI's words", "[app]") {
  app::SbmRequest sbm;
  sbm.half = 10;
  sbm.p_in = 0.5;
  using S = app::SbmRequest;
  CHECK(refusal<S>(sbm, [](S&) {}) == "accepted");
  CHECK(refusal<S>(sbm, [](S& r) { r.half = 0; }) ==
        "--half: Value 0 not in range 1 to 1073741823");
  CHECK(refusal<S>(sbm, [](S& r) { r.p_in = 1.5; }) ==
        "--p-in: value 1.5 is not allowed (allowed: 0 <= q <= 1)");
  CHECK(refusal<S>(sbm, [](S& r) {
          r.p_in = 0.0;
        }).rfind("--p-in, --p-out: values 0 and 0 are not allowed", 0) == 0);
  using C = app::CompleteRequest;
  C complete;
  complete.n = 2;
  CHECK(refusal<C>(complete, [](C&) {}) == "accepted");
  CHECK(refusal<C>(complete, [](C& r) { r.n = 1; }) == "--n: Value 1 not in range 2 to 2147483647");
  CHECK(refusal<C>(complete, [](C& r) { r.n = 2147483648; }) ==
        "--n: Value 2147483648 not in range 2 to 2147483647");
  using G = app::RegularRequest;
  G regular;
  regular.n = 51;
  regular.degree = 4;
  CHECK(refusal<G>(regular, [](G&) {}) == "accepted");
  CHECK(refusal<G>(regular, [](G& r) { r.degree = -1; }) ==
        "--degree: Value -1 not in range 0 to 2147483646");
  CHECK(refusal<G>(regular, [](G& r) {
          r.degree = 0;
        }).rfind("--degree: value 0 is not allowed (allowed: 1 <= d <= n - 1 = 50; d = 0", 0) == 0);
  CHECK(refusal<G>(regular, [](G& r) { r.degree = 50; }) == "accepted");
  CHECK(refusal<G>(regular, [](G& r) { r.degree = 51; }) ==
        "--degree: value 51 is not allowed (allowed: <= n - 1 = 50 with --n 51; a node has at "
        "most n - 1 neighbours)");
}

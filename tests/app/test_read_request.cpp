// The read request's check (app/read_request.hpp), in the words of tests/cli/option_ranges.txt,
// and the reader options it gives.
#include <catch2/catch.hpp>

#include "app/read_request.hpp"
#include "support/request_refusal.hpp"

using namespace hmfnet;
using app::ReadRequest;
using test::refusal;

TEST_CASE("A read request out of range is refused in the CLI's words", "[app]") {
  const ReadRequest valid;
  CHECK(refusal<ReadRequest>(valid, [](ReadRequest&) {}) == "accepted");
  CHECK(refusal<ReadRequest>(valid, [](ReadRequest& r) { r.index_base = 2; }) ==
        "--index-base: 2 not in {0,1}");
  CHECK(refusal<ReadRequest>(valid, [](ReadRequest& r) { r.index_base = -1; }) ==
        "--index-base: -1 not in {0,1}");
  CHECK(refusal<ReadRequest>(valid, [](ReadRequest& r) { r.nodes = -3; }) ==
        "--nodes: value -3 is not allowed (allowed: >= 0)");
}

TEST_CASE("A read request gives the readers its options", "[app]") {
  ReadRequest r;
  r.symmetrize = true;
  r.index_base = 1;
  r.nodes = 7;
  const ReadOptions o = app::read_options(r);
  CHECK(o.asymmetry == AsymmetryPolicy::symmetrize);
  CHECK(o.edge_list_base == 1);
  CHECK(o.edge_list_nodes == 7);
  CHECK(app::read_options(ReadRequest{}).asymmetry == AsymmetryPolicy::reject);
}

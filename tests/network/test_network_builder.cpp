// build_network: the checks shared by all readers (weights, duplicates, symmetry, emptiness) and
// the assembly of the CSR arrays, on entries given directly (no file parsing involved).
#include <catch2/catch.hpp>
#include <limits>

#include "network/network_builder.hpp"
#include "support/io_helpers.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;
using hmfnet::test::input_error_from;
using hmfnet::test::require_input_error;

namespace {

const std::string k_source = "entries.src";

BuildOptions general(AsymmetryPolicy policy, int base = 1) {
  return {EntrySymmetry::general, policy, base};
}

}  // namespace

TEST_CASE(
    "Network builder mirrors symmetric entries and sorts rows and keeps a self-loop once "
    "[symmetric]",
    "[network_builder]") {
  // Entries in scrambled order and orientation: {2,0}, {1,2}, {1,1}.
  const BuildResult r = build_network(k_source, 4, {{2, 0, 1, 1}, {1, 2, 1, 2}, {1, 1, 1, 3}}, {});
  CHECK(r.warnings.empty());
  CHECK(r.network.row_ptr() == std::vector<EdgeOffset>{0, 1, 3, 5, 5});
  CHECK(r.network.cols() == std::vector<NodeIndex>{2, 1, 2, 0, 1});
  CHECK_FALSE(r.network.weighted());
  CHECK(r.network.edges() == 3);
  CHECK(r.network.self_loops() == 1);
}

TEST_CASE("Network builder stores weights that are all 1 as 0/1 and others as weighted [weights]",
          "[network_builder]") {
  SECTION("all 1") {
    const BuildResult r = build_network(k_source, 2, {{0, 1, 1.0, 1}, {1, 1, 1.0, 2}}, {});
    CHECK_FALSE(r.network.weighted());
  }
  SECTION("one weight differs") {
    const BuildResult r = build_network(k_source, 2, {{0, 1, 1.0, 1}, {1, 1, 2.0, 2}}, {});
    REQUIRE(r.network.weighted());
    CHECK(r.network.weights() == std::vector<double>{1.0, 1.0, 2.0});
  }
}

TEST_CASE("Network builder rejects a NaN or infinite or negative weight at its line [bad weight]",
          "[network_builder]") {
  const auto [weight, cause] = GENERATE(table<double, std::string>({
      {std::numeric_limits<double>::quiet_NaN(), "weight is NaN"},
      {std::numeric_limits<double>::infinity(), "weight is infinite"},
      {-std::numeric_limits<double>::infinity(), "weight is infinite"},
      {-2.0, "negative weight -2.000000"},
      {-std::numeric_limits<double>::denorm_min(), "negative weight"},
      {std::numeric_limits<double>::denorm_min(), "weight 4.94e-324 is subnormal"},
      {0.5 * std::numeric_limits<double>::min(), "is subnormal"},
  }));
  INFO("weight " << weight);
  const auto e = input_error_from([&, w = weight] {
    build_network(k_source, 3, {{0, 1, 1, 4}, {1, 2, w, 9}}, {});
  });
  require_input_error(e, k_source, 9, cause);
}

TEST_CASE("Network builder reports the first bad weight in file order [two bad weights]",
          "[network_builder]") {
  const auto e = input_error_from([] {
    build_network(k_source, 3, {{0, 1, -1.0, 2}, {1, 2, std::nan(""), 5}}, {});
  });
  require_input_error(e, k_source, 2, "negative weight");
}

TEST_CASE(
    "Network builder rejects a symmetric pair given in both orientations at the later "
    "line [duplicate]",
    "[network_builder]") {
  SECTION("0-based names") {
    const auto e = input_error_from([] {
      build_network(k_source, 3, {{2, 1, 1, 7}, {0, 1, 1, 8}, {1, 2, 1, 3}}, {});
    });
    require_input_error(e, k_source, 7, "duplicate edge (1,2) (first given at line 3)");
  }
  SECTION("1-based names") {
    BuildOptions options;
    options.index_base = 1;
    const auto e = input_error_from([&] {
      build_network(k_source, 3, {{0, 0, 1, 1}, {0, 0, 2, 2}}, options);
    });
    require_input_error(e, k_source, 2, "duplicate edge (1,1) (first given at line 1)");
  }
}

TEST_CASE(
    "Network builder rejects a duplicate whose first copy is an explicit zero "
    "[duplicate / zero]",
    "[network_builder]") {
  SECTION("symmetric") {
    const auto e = input_error_from([] {
      build_network(k_source, 3, {{1, 0, 0.0, 3}, {0, 1, 2.0, 4}, {1, 2, 1, 5}}, {});
    });
    require_input_error(e, k_source, 4, "duplicate edge (0,1)");
  }
  SECTION("general") {
    const auto e = input_error_from([] {
      build_network(k_source, 2, {{0, 1, 1.0, 3}, {1, 0, 1.0, 4}, {0, 1, 0.0, 5}},
                    general(AsymmetryPolicy::reject));
    });
    require_input_error(e, k_source, 5, "duplicate entry (1,2)");
  }
}

TEST_CASE("Network builder drops explicit zeros with a warning giving their count [zeros]",
          "[network_builder]") {
  const BuildResult r =
      build_network(k_source, 3, {{0, 1, 0.0, 1}, {1, 2, 1.5, 2}, {2, 2, 0.0, 3}}, {});
  REQUIRE(r.warnings.size() == 1);
  CHECK(r.warnings.front() ==
        k_source + ": warning: 2 explicit zero entries dropped (a zero weight is no edge)");
  CHECK(r.network.cols() == std::vector<NodeIndex>{2, 1});
  CHECK(r.network.weights() == std::vector<double>{1.5, 1.5});
}

TEST_CASE("Network builder rejects an empty network naming the file without a line [empty]",
          "[network_builder]") {
  SECTION("no entries") {
    const auto e = input_error_from([] { build_network(k_source, 5, {}, {}); });
    require_input_error(e, k_source, 0, "empty network: 5 nodes and no edges");
  }
  SECTION("only zeros") {
    const auto e = input_error_from([] { build_network(k_source, 2, {{0, 1, 0.0, 1}}, {}); });
    require_input_error(e, k_source, 0, "empty network: 2 nodes and no edges");
  }
  SECTION("no nodes") {
    const auto e = input_error_from([] { build_network(k_source, 0, {}, {}); });
    require_input_error(e, k_source, 0, "empty network: 0 nodes");
  }
}

TEST_CASE(
    "Network builder accepts a general matrix equal to its transpose without warning "
    "[general / symmetric]",
    "[network_builder]") {
  const BuildResult r = build_network(k_source, 3, {{0, 1, 2.0, 1}, {2, 2, 3.0, 2}, {1, 0, 2.0, 3}},
                                      general(AsymmetryPolicy::reject));
  CHECK(r.warnings.empty());
  CHECK(r.network.cols() == std::vector<NodeIndex>{1, 0, 2});
  CHECK(r.network.weights() == std::vector<double>{2.0, 2.0, 3.0});
}

TEST_CASE(
    "Network builder rejects an asymmetric general matrix at the first unmatched entry "
    "[general / reject]",
    "[network_builder]") {
  // (3,1) has no transpose; (1,2) and (2,1) differ: three entries without an equal transpose.
  const auto e = input_error_from([] {
    build_network(k_source, 3, {{2, 0, 1.0, 4}, {0, 1, 1.0, 5}, {1, 0, 4.0, 6}},
                  general(AsymmetryPolicy::reject));
  });
  require_input_error(e, k_source, 5, "matrix is not symmetric: entry (1,2) has no transpose");
  CHECK_THAT(e->cause(), Contains("(3 such entries)"));
}

TEST_CASE(
    "Network builder symmetrises as (A+A^T)/2 and counts the unmatched entries "
    "[general / symmetrize]",
    "[network_builder]") {
  const BuildResult r =
      build_network(k_source, 3, {{2, 0, 1.0, 4}, {0, 1, 1.0, 5}, {1, 0, 4.0, 6}, {1, 1, 3.0, 7}},
                    general(AsymmetryPolicy::symmetrize));
  REQUIRE(r.warnings.size() == 1);
  CHECK(r.warnings.front() == k_source +
                                  ": warning: matrix is not symmetric (3 entries without an "
                                  "equal transpose); using (A+A^T)/2");
  // A = [0 1 0; 4 3 0; 1 0 0] -> (A+A^T)/2 = [0 2.5 0.5; 2.5 3 0; 0.5 0 0].
  CHECK(r.network.row_ptr() == std::vector<EdgeOffset>{0, 2, 4, 5});
  CHECK(r.network.cols() == std::vector<NodeIndex>{1, 2, 0, 1, 0});
  CHECK(r.network.weights() == std::vector<double>{2.5, 0.5, 2.5, 3.0, 0.5});
}

TEST_CASE(
    "Network builder stores a symmetrised matrix whose weights are all 1 as 0/1 "
    "[general / symmetrize / all 1]",
    "[network_builder]") {
  const BuildResult r =
      build_network(k_source, 2, {{0, 1, 2.0, 1}}, general(AsymmetryPolicy::symmetrize));
  REQUIRE(r.warnings.size() == 1);
  CHECK_THAT(r.warnings.front(), Contains("(1 entries"));
  CHECK_FALSE(r.network.weighted());
  CHECK(r.network.cols() == std::vector<NodeIndex>{1, 0});
}

TEST_CASE("Network builder warns about zeros and asymmetry together [general / zeros]",
          "[network_builder]") {
  // The explicit zero (1,0) is no entry: (0,1) is unmatched and is halved.
  const BuildResult r = build_network(k_source, 2, {{0, 1, 1.0, 1}, {1, 0, 0.0, 2}},
                                      general(AsymmetryPolicy::symmetrize));
  REQUIRE(r.warnings.size() == 2);
  CHECK_THAT(r.warnings[0], Contains("1 explicit zero"));
  CHECK_THAT(r.warnings[1], Contains("(1 entries"));
  CHECK(r.network.weights() == std::vector<double>{0.5, 0.5});
}

// Edge-list reader and writer: comments, index bases, every malformed line refused with
// "FILE:LINE: cause", and write-then-read is bit-exact.
#include <catch2/catch.hpp>

#include "io/edge_list.hpp"
#include "io/node_count_limit.hpp"
#include "support/io_helpers.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;
using hmfnet::test::input_error_from;
using hmfnet::test::require_input_error;
using hmfnet::test::TempDirectory;
using hmfnet::test::write_text;

namespace {

std::optional<InputError> read_error(const TempDirectory& dir, const std::string& name,
                                     const std::string& text, const ReadOptions& options = {}) {
  write_text(dir.file(name), text);
  return input_error_from([&] { read_edge_list(dir.file(name), options); });
}

ReadOptions base_one() {
  ReadOptions options;
  options.edge_list_base = 1;
  return options;
}

}  // namespace

TEST_CASE("Edge-list reader skips comments and blank lines and keeps a self-loop [0-based]",
          "[io][edge_list]") {
  TempDirectory dir;
  write_text(dir.file("e.txt"), "# header\n\n0 1   # trailing comment\n\t2 1\n  \n2 2\n");
  const ReadResult r = read_edge_list(dir.file("e.txt"));
  CHECK(r.warnings.empty());
  REQUIRE(r.network.size() == 3);
  CHECK(r.network.row_ptr() == std::vector<EdgeOffset>{0, 1, 3, 5});
  CHECK(r.network.cols() == std::vector<NodeIndex>{1, 0, 2, 1, 2});
  CHECK_FALSE(r.network.weighted());
}

TEST_CASE("Edge-list reader shifts a 1-based file to 0-based nodes [1-based]", "[io][edge_list]") {
  TempDirectory dir;
  write_text(dir.file("e.txt"), "1 2\n3 2\n");
  const ReadResult r = read_edge_list(dir.file("e.txt"), base_one());
  REQUIRE(r.network.size() == 3);
  CHECK(r.network.cols() == std::vector<NodeIndex>{1, 0, 2, 1});
}

TEST_CASE(
    "Edge-list reader keeps isolated nodes past the largest index when given the count "
    "[nodes]",
    "[io][edge_list]") {
  TempDirectory dir;
  write_text(dir.file("e.txt"), "0 1\n");
  ReadOptions options;
  options.edge_list_nodes = 5;
  const ReadResult r = read_edge_list(dir.file("e.txt"), options);
  CHECK(r.network.size() == 5);
  CHECK(r.network.row_ptr() == std::vector<EdgeOffset>{0, 1, 2, 2, 2, 2});
}

TEST_CASE("Edge-list reader keeps weights exactly and stores all-1 weights as 0/1 [weighted]",
          "[io][edge_list]") {
  TempDirectory dir;
  SECTION("weights") {
    write_text(dir.file("w.txt"), "0 1 0.125\n1 2 3\n");
    const ReadResult r = read_edge_list(dir.file("w.txt"));
    REQUIRE(r.network.weighted());
    CHECK(r.network.weights() == std::vector<double>{0.125, 0.125, 3.0, 3.0});
  }
  SECTION("all weights 1") {
    write_text(dir.file("w.txt"), "0 1 1\n1 2 1.000\n");
    const ReadResult r = read_edge_list(dir.file("w.txt"));
    CHECK_FALSE(r.network.weighted());
    CHECK(r.network.nnz() == 4);
  }
}

TEST_CASE("Edge-list reader drops zero-weight edges with a warning [zeros]", "[io][edge_list]") {
  TempDirectory dir;
  write_text(dir.file("z.txt"), "0 1 2\n1 2 0\n");
  const ReadResult r = read_edge_list(dir.file("z.txt"));
  CHECK(r.network.edges() == 1);
  REQUIRE(r.warnings.size() == 1);
  CHECK_THAT(r.warnings.front(), Contains(dir.file("z.txt")) && Contains("1 explicit zero"));
}

TEST_CASE("Edge-list reader rejects 'u v' followed by 'v u' [duplicate]", "[io][edge_list]") {
  TempDirectory dir;
  const auto e = read_error(dir, "d.txt", "# c\n0 1\n1 2\n1 0\n");
  require_input_error(e, dir.file("d.txt"), 4, "duplicate edge (0,1) (first given at line 2)");
}

TEST_CASE(
    "Edge-list reader rejects the same line twice and prints 1-based indices as written "
    "[duplicate / 1-based]",
    "[io][edge_list]") {
  TempDirectory dir;
  const auto e = read_error(dir, "d.txt", "1 2\n2 3\n1 2\n", base_one());
  require_input_error(e, dir.file("d.txt"), 3, "duplicate edge (1,2) (first given at line 1)");
}

TEST_CASE("Edge-list reader rejects a duplicate self-loop [duplicate / loop]", "[io][edge_list]") {
  TempDirectory dir;
  const auto e = read_error(dir, "d.txt", "0 1\n2 2\n2 2\n");
  require_input_error(e, dir.file("d.txt"), 3, "duplicate edge (2,2)");
}

TEST_CASE("Edge-list reader rejects weighted and unweighted lines mixed [mixed]",
          "[io][edge_list]") {
  TempDirectory dir;
  SECTION("weight missing") {
    const auto e = read_error(dir, "m.txt", "0 1 0.5\n# c\n1 2\n");
    require_input_error(e, dir.file("m.txt"), 3,
                        "this line has 2 fields, earlier lines have 3 "
                        "(weights on every line or on none)");
  }
  SECTION("weight added") {
    const auto e = read_error(dir, "m.txt", "0 1\n1 2\n2 3 1.0\n");
    require_input_error(e, dir.file("m.txt"), 3, "this line has 3 fields, earlier lines have 2");
  }
}

TEST_CASE("Edge-list reader rejects a line with 1 or 4 fields [fields]", "[io][edge_list]") {
  const auto [line, count] = GENERATE(table<std::string, std::string>({
      {"7", "1"},
      {"0 1 1.0 extra", "4"},
  }));
  TempDirectory dir;
  const auto e = read_error(dir, "f.txt", "0 1\n" + line + "\n");
  require_input_error(e, dir.file("f.txt"), 2,
                      "expected 'u v' or 'u v w', found " + count + " fields");
}

TEST_CASE("Edge-list reader rejects a non-numeric token [bad token]", "[io][edge_list]") {
  TempDirectory dir;
  SECTION("node") {
    const auto e = read_error(dir, "b.txt", "0 1\nA 2\n");
    require_input_error(e, dir.file("b.txt"), 2, "node index 'A' is not an integer");
  }
  SECTION("fractional node") {
    const auto e = read_error(dir, "b.txt", "0 1.5\n");
    require_input_error(e, dir.file("b.txt"), 1, "node index '1.5' is not an integer");
  }
  SECTION("weight") {
    const auto e = read_error(dir, "b.txt", "0 1 1\n1 2 heavy\n");
    require_input_error(e, dir.file("b.txt"), 2, "weight 'heavy' is not a number");
  }
  SECTION("node beyond int64") {
    const auto e = read_error(dir, "b.txt", "0 99999999999999999999\n");
    require_input_error(e, dir.file("b.txt"), 1, "is out of the integer range");
  }
}

TEST_CASE("Edge-list reader rejects negative / NaN and infinite weights [bad weight]",
          "[io][edge_list]") {
  const auto [token, cause] = GENERATE(table<std::string, std::string>({
      {"-1", "negative weight"},
      {"nan", "weight is NaN"},
      {"inf", "weight is infinite"},
      {"infinity", "weight is infinite"},
  }));
  INFO("weight token " << token);
  TempDirectory dir;
  const auto e = read_error(dir, "w.txt", "0 1 1\n1 2 2\n\n2 3 " + token + "\n");
  require_input_error(e, dir.file("w.txt"), 4, cause);
}

TEST_CASE("Edge-list reader rejects a node index out of range [out of range]", "[io][edge_list]") {
  TempDirectory dir;
  SECTION("negative index, 0-based") {
    const auto e = read_error(dir, "r.txt", "0 1\n-1 2\n");
    require_input_error(e, dir.file("r.txt"), 2, "node index -1 is out of range 0..");
    // A negative index in a 0-based file is not a base mistake: no "-1-based" hint.
    CHECK_THAT(e->cause(), !Contains("based"));
  }
  SECTION("index 0 in a 1-based file suggests the base") {
    const auto e = read_error(dir, "r.txt", "1 2\n0 2\n", base_one());
    require_input_error(e, dir.file("r.txt"), 2, "node index 0 is out of range 1..");
    CHECK_THAT(e->cause(), Contains("is the file 0-based? see --index-base"));
  }
  SECTION("index past the given node count") {
    ReadOptions options;
    options.edge_list_nodes = 3;
    const auto e = read_error(dir, "r.txt", "0 1\n1 2\n2 3\n", options);
    require_input_error(e, dir.file("r.txt"), 3, "node index 3 is out of range 0..2");
  }
  SECTION("index past the given node count, 1-based") {
    ReadOptions options = base_one();
    options.edge_list_nodes = 3;
    const auto e = read_error(dir, "r.txt", "1 4\n", options);
    require_input_error(e, dir.file("r.txt"), 1, "node index 4 is out of range 1..3");
  }
  SECTION("index past int32") {
    const auto e = read_error(dir, "r.txt", "0 3000000000\n");
    require_input_error(e, dir.file("r.txt"), 1, "node index 3000000000 is out of range");
  }
}

TEST_CASE("Edge-list reader rejects an empty network [no edges]", "[io][edge_list]") {
  TempDirectory dir;
  SECTION("only comments") {
    const auto e = read_error(dir, "e.txt", "# nothing\n\n   # here\n");
    require_input_error(e, dir.file("e.txt"), 0, "empty network: 0 nodes and no edges");
  }
  SECTION("empty file with a node count") {
    ReadOptions options;
    options.edge_list_nodes = 4;
    const auto e = read_error(dir, "e.txt", "", options);
    require_input_error(e, dir.file("e.txt"), 0, "empty network: 4 nodes and no edges");
  }
  SECTION("'# nodes 1999999999' and nothing else: refused before 16 GB of row pointers") {
    // Found by tests/fuzz (crashes/edge_list/oom-a20d...): with no entries the node count is not
    // bounded, so emptiness must be decided before the rows are allocated.
    const auto e = read_error(dir, "e.txt", "# nodes 1999999999\n");
    require_input_error(e, dir.file("e.txt"), 0, "empty network: 1999999999 nodes and no edges");
  }
}

TEST_CASE("Edge-list reader refuses an index base other than 0 or 1 [base 2]", "[io][edge_list]") {
  TempDirectory dir;
  write_text(dir.file("e.txt"), "0 1\n");
  ReadOptions options;
  options.edge_list_base = 2;
  CHECK_THROWS_AS(read_edge_list(dir.file("e.txt"), options), ParameterError);
}

TEST_CASE("Edge-list reader names a missing file [no file]", "[io][edge_list]") {
  TempDirectory dir;
  const auto e = input_error_from([&] { read_edge_list(dir.file("absent.txt")); });
  require_input_error(e, dir.file("absent.txt"), 0, "cannot open file for reading");
}

TEST_CASE("Edge-list round trip is exact [0/1 with self-loops]", "[io][edge_list]") {
  TempDirectory dir;
  const Network net = test::unweighted_network_with_loops();
  write_edge_list(dir.file("u.txt"), net, "provenance line 1\nline 2");
  CHECK_THAT(test::read_text(dir.file("u.txt")),
             Catch::Matchers::StartsWith("# nodes 6\n# provenance line 1\n# line 2\n0 0\n0 1\n"));
  const ReadResult r = read_edge_list(dir.file("u.txt"));
  CHECK(r.warnings.empty());
  test::require_same_network(r.network, net);
  CHECK(dir.listing() == std::vector<std::string>{"u.txt"});
}

TEST_CASE("Edge-list round trip is exact [weighted with self-loops / 17 digits]",
          "[io][edge_list]") {
  TempDirectory dir;
  const Network net = test::awkward_weighted_network();
  write_edge_list(dir.file("w.txt"), net);
  const ReadResult r = read_edge_list(dir.file("w.txt"));
  test::require_same_network(r.network, net);
}

TEST_CASE(
    "Edge-list round trip keeps trailing isolated nodes when the node count is given "
    "[isolated nodes]",
    "[io][edge_list]") {
  TempDirectory dir;
  const Network net = Network::from_undirected_edges(5, {{0, 1}, {1, 2}});
  write_edge_list(dir.file("i.txt"), net);
  ReadOptions options;
  options.edge_list_nodes = net.size();
  test::require_same_network(read_edge_list(dir.file("i.txt"), options).network, net);
}

TEST_CASE(
    "Edge-list round trip keeps trailing isolated nodes through the '# nodes' line "
    "[isolated nodes]",
    "[io][edge_list]") {
  TempDirectory dir;
  const Network net = Network::from_undirected_edges(5, {{0, 1}, {1, 2}});
  write_edge_list(dir.file("i.txt"), net);
  test::require_same_network(read_edge_list(dir.file("i.txt")).network, net);
}

TEST_CASE(
    "Edge-list reader refuses a '# nodes' line smaller than an index in the file "
    "[nodes]",
    "[io][edge_list]") {
  TempDirectory dir;
  test::write_text(dir.file("n.txt"), "# nodes 2\n0 1\n1 2\n");
  REQUIRE_THROWS_WITH(read_edge_list(dir.file("n.txt")), Catch::Contains("'# nodes 2'"));
}

// Found by tests/fuzz (crashes/edge_list/oom-85da4e...): one edge "0 1214748364" made the reader
// allocate 9.7 GB of row pointers for a 15-byte file.
TEST_CASE(
    "Edge-list reader refuses a node count that one edge cannot back instead of allocating "
    "it [fuzz: node count]",
    "[io][edge_list]") {
  TempDirectory dir;
  SECTION("large index on the only edge") {
    const auto e = read_error(dir, "big.txt", "0\t1214748364\n1\t2\r\n");
    require_input_error(e, dir.file("big.txt"), 0, "1214748365 nodes for 2 edges: at most");
  }
  SECTION("large '# nodes' line") {
    const auto e = read_error(dir, "big.txt", "# nodes 2000000000\n0 1\n");
    require_input_error(e, dir.file("big.txt"), 0, "2000000000 nodes for 1 edges: at most");
  }
  SECTION("the limit itself is accepted: 2^20 + 64 nodes for one edge") {
    write_text(dir.file("edge.txt"),
               "# nodes " + std::to_string(max_nodes_for_entries(1)) + "\n0 1\n");
    CHECK(read_edge_list(dir.file("edge.txt")).network.size() == (1 << 20) + 64);
    const auto e = read_error(
        dir, "over.txt", "# nodes " + std::to_string(max_nodes_for_entries(1) + 1) + "\n0 1\n");
    require_input_error(e, dir.file("over.txt"), 0, "nodes for 1 edges: at most 1048640");
  }
}

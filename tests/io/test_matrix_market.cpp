// Matrix Market reader and writer: every malformed input is refused with "FILE:LINE: cause",
// a general matrix is symmetrised only on request, and write-then-read is bit-exact.
#include <catch2/catch.hpp>

#include "io/matrix_market.hpp"
#include "io/node_count_limit.hpp"
#include "support/io_helpers.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;
using hmfnet::test::input_error_from;
using hmfnet::test::require_input_error;
using hmfnet::test::TempDirectory;
using hmfnet::test::write_text;

namespace {

const std::string k_pattern_symmetric = "%%MatrixMarket matrix coordinate pattern symmetric\n";
const std::string k_real_symmetric = "%%MatrixMarket matrix coordinate real symmetric\n";
const std::string k_real_general = "%%MatrixMarket matrix coordinate real general\n";

// Writes `text` to NAME in `dir` and reads it back, expecting an InputError.
std::optional<InputError> read_error(const TempDirectory& dir, const std::string& name,
                                     const std::string& text, const ReadOptions& options = {}) {
  write_text(dir.file(name), text);
  return input_error_from([&] { read_matrix_market(dir.file(name), options); });
}

}  // namespace

TEST_CASE("Matrix Market reader mirrors a pattern symmetric file and keeps a self-loop [pattern]",
          "[io][matrix_market]") {
  TempDirectory dir;
  // Path 1-2-3 plus a self-loop on node 3; entries out of order and comments in between.
  write_text(dir.file("path.mtx"),
             k_pattern_symmetric + "% comment\n3 3 3\n3 2\n\n2 1\n% x\n3 3\n");
  const ReadResult r = read_matrix_market(dir.file("path.mtx"));
  CHECK(r.warnings.empty());
  REQUIRE(r.network.size() == 3);
  CHECK(r.network.row_ptr() == std::vector<EdgeOffset>{0, 1, 3, 5});
  CHECK(r.network.cols() == std::vector<NodeIndex>{1, 0, 2, 1, 2});
  CHECK_FALSE(r.network.weighted());
  CHECK(r.network.self_loops() == 1);
}

TEST_CASE("Matrix Market reader keeps the weights of a real file exactly [real]",
          "[io][matrix_market]") {
  TempDirectory dir;
  write_text(dir.file("w.mtx"), k_real_symmetric + "3 3 2\n2 1 0.25\n3 1 2.5e3\n");
  const ReadResult r = read_matrix_market(dir.file("w.mtx"));
  REQUIRE(r.network.weighted());
  CHECK(r.network.cols() == std::vector<NodeIndex>{1, 2, 0, 0});
  CHECK(r.network.weights() == std::vector<double>{0.25, 2500.0, 0.25, 2500.0});
}

TEST_CASE("Matrix Market reader reads integer weights [integer]", "[io][matrix_market]") {
  TempDirectory dir;
  write_text(dir.file("i.mtx"),
             "%%MatrixMarket matrix coordinate integer symmetric\n2 2 2\n2 1 3\n2 2 +4\n");
  const ReadResult r = read_matrix_market(dir.file("i.mtx"));
  REQUIRE(r.network.weighted());
  CHECK(r.network.weights() == std::vector<double>{3.0, 3.0, 4.0});
}

TEST_CASE("Matrix Market reader stores a real file whose weights are all 1 as 0/1 [real / all 1]",
          "[io][matrix_market]") {
  TempDirectory dir;
  write_text(dir.file("ones.mtx"), k_real_symmetric + "3 3 2\n2 1 1.0\n3 2 1e0\n");
  const ReadResult r = read_matrix_market(dir.file("ones.mtx"));
  CHECK_FALSE(r.network.weighted());
  CHECK(r.network.nnz() == 4);
}

TEST_CASE("Matrix Market reader is case-insensitive in the header and accepts CRLF lines",
          "[io][matrix_market]") {
  TempDirectory dir;
  write_text(dir.file("crlf.mtx"),
             "%%matrixmarket MATRIX Coordinate PATTERN Symmetric\r\n2 2 1\r\n2 1\r\n");
  const ReadResult r = read_matrix_market(dir.file("crlf.mtx"));
  CHECK(r.network.edges() == 1);
}

TEST_CASE("Matrix Market reader drops explicit zero entries with a warning [zeros]",
          "[io][matrix_market]") {
  TempDirectory dir;
  write_text(dir.file("z.mtx"), k_real_symmetric + "3 3 3\n2 1 0\n3 2 1.5\n3 1 0.0\n");
  const ReadResult r = read_matrix_market(dir.file("z.mtx"));
  CHECK(r.network.edges() == 1);
  CHECK_FALSE(r.network.has_entry(0, 1));
  REQUIRE(r.warnings.size() == 1);
  INFO(r.warnings.front());
  CHECK_THAT(r.warnings.front(), Contains(dir.file("z.mtx")) && Contains("2 explicit zero"));
}

TEST_CASE("Matrix Market reader accepts a general file that is symmetric [general]",
          "[io][matrix_market]") {
  TempDirectory dir;
  write_text(dir.file("g.mtx"), k_real_general + "3 3 5\n1 2 2\n2 1 2\n2 3 0.5\n3 2 0.5\n3 3 7\n");
  const ReadResult r = read_matrix_market(dir.file("g.mtx"));
  CHECK(r.warnings.empty());
  CHECK(r.network.row_ptr() == std::vector<EdgeOffset>{0, 1, 3, 5});
  CHECK(r.network.cols() == std::vector<NodeIndex>{1, 0, 2, 1, 2});
  CHECK(r.network.weights() == std::vector<double>{2, 2, 0.5, 0.5, 7});
}

TEST_CASE("Matrix Market reader rejects a file with fewer entries than declared [truncated]",
          "[io][matrix_market]") {
  TempDirectory dir;
  // Data stops at line 5: the error points there, where the missing entry should have been.
  const auto e = read_error(dir, "t.mtx", k_pattern_symmetric + "% c\n3 3 3\n2 1\n3 2\n");
  require_input_error(e, dir.file("t.mtx"), 5, "truncated: 3 entries declared, 2 found");
}

TEST_CASE("Matrix Market reader rejects a file that ends before the size line [truncated]",
          "[io][matrix_market]") {
  TempDirectory dir;
  const auto e = read_error(dir, "t.mtx", k_pattern_symmetric + "% only a comment\n");
  require_input_error(e, dir.file("t.mtx"), 2, "no size line");
}

TEST_CASE("Matrix Market reader rejects an entry past the declared count [more entries]",
          "[io][matrix_market]") {
  TempDirectory dir;
  const auto e = read_error(dir, "m.mtx", k_pattern_symmetric + "3 3 1\n2 1\n3 2\n");
  require_input_error(e, dir.file("m.mtx"), 4, "more entries than the 1 declared");
}

TEST_CASE("Matrix Market reader rejects an index past N [out of range]", "[io][matrix_market]") {
  TempDirectory dir;
  SECTION("row") {
    const auto e = read_error(dir, "r.mtx", k_pattern_symmetric + "3 3 2\n2 1\n4 1\n");
    require_input_error(e, dir.file("r.mtx"), 4, "row index 4 is out of range 1..3");
  }
  SECTION("column") {
    const auto e = read_error(dir, "c.mtx", k_real_symmetric + "3 3 1\n3 9 1.0\n");
    require_input_error(e, dir.file("c.mtx"), 3, "column index 9 is out of range 1..3");
  }
  SECTION("negative") {
    const auto e = read_error(dir, "n.mtx", k_pattern_symmetric + "3 3 1\n-1 2\n");
    require_input_error(e, dir.file("n.mtx"), 3, "row index -1 is out of range");
  }
}

TEST_CASE("Matrix Market reader rejects index 0 and says indices are 1-based [index 0]",
          "[io][matrix_market]") {
  TempDirectory dir;
  const auto e = read_error(dir, "z.mtx", k_pattern_symmetric + "3 3 2\n2 1\n2 0\n");
  require_input_error(e, dir.file("z.mtx"), 4, "column index 0 is out of range 1..3");
  CHECK_THAT(e->cause(), Contains("1-based"));
}

TEST_CASE("Matrix Market reader rejects a non-numeric token [bad token]", "[io][matrix_market]") {
  TempDirectory dir;
  SECTION("index") {
    const auto e = read_error(dir, "i.mtx", k_pattern_symmetric + "3 3 2\n2 1\n3 two\n");
    require_input_error(e, dir.file("i.mtx"), 4, "column index 'two' is not an integer");
  }
  SECTION("index with trailing junk") {
    const auto e = read_error(dir, "j.mtx", k_pattern_symmetric + "3 3 1\n2x 1\n");
    require_input_error(e, dir.file("j.mtx"), 3, "row index '2x' is not an integer");
  }
  SECTION("real weight") {
    const auto e = read_error(dir, "w.mtx", k_real_symmetric + "3 3 2\n2 1 1.0\n3 1 1,5\n");
    require_input_error(e, dir.file("w.mtx"), 4, "weight '1,5' is not a number");
  }
  SECTION("fractional weight in an integer file") {
    const auto e = read_error(
        dir, "f.mtx", "%%MatrixMarket matrix coordinate integer symmetric\n3 3 1\n2 1 1.5\n");
    require_input_error(e, dir.file("f.mtx"), 3, "weight '1.5' is not an integer");
  }
  SECTION("size line") {
    const auto e = read_error(dir, "s.mtx", k_pattern_symmetric + "3 3 many\n2 1\n");
    require_input_error(e, dir.file("s.mtx"), 2, "entry count 'many' is not an integer");
  }
}

TEST_CASE("Matrix Market reader rejects negative / NaN and infinite weights [bad weight]",
          "[io][matrix_market]") {
  const auto [token, cause] = GENERATE(table<std::string, std::string>({
      {"-0.5", "negative weight"},
      {"nan", "weight is NaN"},
      {"NaN", "weight is NaN"},
      {"inf", "weight is infinite"},
      {"-inf", "weight is infinite"},
      {"1e400", "out of the double range"},
  }));
  INFO("weight token " << token);
  TempDirectory dir;
  const auto e =
      read_error(dir, "b.mtx", k_real_symmetric + "3 3 3\n2 1 1\n3 1 2\n3 2 " + token + "\n");
  require_input_error(e, dir.file("b.mtx"), 5, cause);
}

TEST_CASE(
    "Matrix Market reader rejects both A_ij and A_ji given in a symmetric file "
    "[duplicate]",
    "[io][matrix_market]") {
  TempDirectory dir;
  const auto e = read_error(dir, "d.mtx", k_pattern_symmetric + "3 3 3\n2 1\n3 2\n1 2\n");
  require_input_error(e, dir.file("d.mtx"), 5, "duplicate edge (1,2) (first given at line 3)");
}

TEST_CASE("Matrix Market reader rejects the same entry twice in a general file [duplicate]",
          "[io][matrix_market]") {
  TempDirectory dir;
  const auto e = read_error(dir, "d.mtx", k_real_general + "3 3 4\n1 2 1\n2 1 1\n1 2 1\n3 3 1\n");
  require_input_error(e, dir.file("d.mtx"), 5, "duplicate entry (1,2) (first given at line 3)");
}

TEST_CASE(
    "Matrix Market reader rejects a duplicate even when one copy is an explicit zero "
    "[duplicate / zero]",
    "[io][matrix_market]") {
  TempDirectory dir;
  const auto e = read_error(dir, "d.mtx", k_real_symmetric + "3 3 2\n2 1 0\n1 2 3\n");
  require_input_error(e, dir.file("d.mtx"), 4, "duplicate edge (1,2)");
}

TEST_CASE("Matrix Market reader rejects an empty network [no entries]", "[io][matrix_market]") {
  TempDirectory dir;
  SECTION("no entries declared") {
    const auto e = read_error(dir, "e.mtx", k_pattern_symmetric + "4 4 0\n");
    require_input_error(e, dir.file("e.mtx"), 0, "empty network: 4 nodes and no edges");
  }
  SECTION("zero nodes") {
    const auto e = read_error(dir, "e.mtx", k_pattern_symmetric + "0 0 0\n");
    require_input_error(e, dir.file("e.mtx"), 0, "empty network: 0 nodes");
  }
  SECTION("only explicit zeros") {
    const auto e = read_error(dir, "e.mtx", k_real_symmetric + "2 2 1\n2 1 0\n");
    require_input_error(e, dir.file("e.mtx"), 0, "empty network");
  }
  SECTION("2 10^9 nodes and no entries: refused before their row pointers are allocated") {
    const auto e = read_error(dir, "e.mtx", k_pattern_symmetric + "2000000000 2000000000 0\n");
    require_input_error(e, dir.file("e.mtx"), 0, "empty network: 2000000000 nodes");
  }
}

TEST_CASE("Matrix Market reader rejects a bad header [header]", "[io][matrix_market]") {
  const auto [header, cause] = GENERATE(table<std::string, std::string>({
      {"3 3 1", "first line is not a '%%MatrixMarket"},
      {"%%MatrixMarket matrix coordinate pattern", "first line is not a '%%MatrixMarket"},
      {"%MatrixMarket matrix coordinate pattern symmetric", "first line is not"},
      {"%%MatrixMarket vector coordinate pattern symmetric", "object 'vector' is not 'matrix'"},
      {"%%MatrixMarket matrix array real symmetric", "format 'array' is not supported"},
      {"%%MatrixMarket matrix coordinate complex symmetric", "field 'complex' is not supported"},
      {"%%MatrixMarket matrix coordinate real hermitian", "symmetry 'hermitian' is not supported"},
      {"%%MatrixMarket matrix coordinate real skew-symmetric", "symmetry 'skew-symmetric'"},
  }));
  INFO("header: " << header);
  TempDirectory dir;
  const auto e = read_error(dir, "h.mtx", header + "\n3 3 1\n2 1 1\n");
  require_input_error(e, dir.file("h.mtx"), 1, cause);
}

TEST_CASE("Matrix Market reader rejects an empty file [header]", "[io][matrix_market]") {
  TempDirectory dir;
  const auto e = read_error(dir, "empty.mtx", "");
  require_input_error(e, dir.file("empty.mtx"), 0, "empty file");
}

TEST_CASE("Matrix Market reader rejects a non-square size line [3 x 4]", "[io][matrix_market]") {
  TempDirectory dir;
  const auto e = read_error(dir, "ns.mtx", k_pattern_symmetric + "% a\n% b\n3 4 1\n2 1\n");
  require_input_error(e, dir.file("ns.mtx"), 4,
                      "matrix is 3 x 4: an adjacency matrix must be square");
}

TEST_CASE("Matrix Market reader rejects a malformed size line [size line]", "[io][matrix_market]") {
  TempDirectory dir;
  SECTION("two fields") {
    const auto e = read_error(dir, "s.mtx", k_pattern_symmetric + "3 3\n2 1\n");
    require_input_error(e, dir.file("s.mtx"), 2, "size line must be 'ROWS COLS ENTRIES'");
  }
  SECTION("negative entry count") {
    const auto e = read_error(dir, "s.mtx", k_pattern_symmetric + "3 3 -1\n");
    require_input_error(e, dir.file("s.mtx"), 2, "size line out of range");
  }
  SECTION("more nodes than int32 indices allow") {
    const auto e = read_error(dir, "s.mtx", k_pattern_symmetric + "3000000000 3000000000 1\n1 1\n");
    require_input_error(e, dir.file("s.mtx"), 2, "size line out of range");
  }
}

TEST_CASE("Matrix Market reader rejects a line with the wrong number of fields [fields]",
          "[io][matrix_market]") {
  TempDirectory dir;
  SECTION("weight in a pattern file") {
    const auto e = read_error(dir, "p.mtx", k_pattern_symmetric + "3 3 2\n2 1\n3 1 1.0\n");
    require_input_error(e, dir.file("p.mtx"), 4, "expected 2 fields, found 3");
  }
  SECTION("no weight in a real file") {
    const auto e = read_error(dir, "r.mtx", k_real_symmetric + "3 3 1\n2 1\n");
    require_input_error(e, dir.file("r.mtx"), 3, "expected 3 fields, found 2");
  }
}

TEST_CASE("Matrix Market reader rejects an asymmetric general file by default [asymmetric]",
          "[io][matrix_market]") {
  TempDirectory dir;
  // (1,2) has no transpose; (2,3) and (3,2) differ in weight: three unmatched entries.
  const auto e = read_error(dir, "a.mtx", k_real_general + "3 3 4\n1 2 1\n2 3 1\n3 2 2\n1 1 5\n");
  require_input_error(e, dir.file("a.mtx"), 3, "matrix is not symmetric: entry (1,2)");
  CHECK_THAT(e->cause(), Contains("3 such entries") && Contains("--symmetrize"));
}

TEST_CASE(
    "Matrix Market reader symmetrises an asymmetric general file as (A+A^T)/2 on request "
    "[symmetrize]",
    "[io][matrix_market]") {
  TempDirectory dir;
  write_text(dir.file("a.mtx"), k_real_general + "3 3 4\n1 2 1\n2 3 1\n3 2 2\n1 1 5\n");
  ReadOptions options;
  options.asymmetry = AsymmetryPolicy::symmetrize;
  const ReadResult r = read_matrix_market(dir.file("a.mtx"), options);
  REQUIRE(r.warnings.size() == 1);
  INFO(r.warnings.front());
  CHECK_THAT(r.warnings.front(),
             Contains(dir.file("a.mtx")) && Contains("not symmetric (3 entries"));
  // Unmatched weight 1 becomes 0.5 both ways; 1 and 2 average to 1.5; the diagonal is kept.
  CHECK(r.network.row_ptr() == std::vector<EdgeOffset>{0, 2, 4, 5});
  CHECK(r.network.cols() == std::vector<NodeIndex>{0, 1, 0, 2, 1});
  CHECK(r.network.weights() == std::vector<double>{5.0, 0.5, 0.5, 1.5, 1.5});
}

TEST_CASE(
    "Matrix Market reader symmetrising a pattern general file gives weights 1/2 "
    "[symmetrize / pattern]",
    "[io][matrix_market]") {
  TempDirectory dir;
  write_text(dir.file("p.mtx"),
             "%%MatrixMarket matrix coordinate pattern general\n3 3 3\n1 2\n2 1\n3 1\n");
  ReadOptions options;
  options.asymmetry = AsymmetryPolicy::symmetrize;
  const ReadResult r = read_matrix_market(dir.file("p.mtx"), options);
  REQUIRE(r.warnings.size() == 1);
  CHECK_THAT(r.warnings.front(), Contains("(1 entries"));
  CHECK(r.network.cols() == std::vector<NodeIndex>{1, 2, 0, 0});
  CHECK(r.network.weights() == std::vector<double>{1.0, 0.5, 1.0, 0.5});
}

TEST_CASE("Matrix Market reader names a missing file [no file]", "[io][matrix_market]") {
  TempDirectory dir;
  const auto e = input_error_from([&] { read_matrix_market(dir.file("absent.mtx")); });
  require_input_error(e, dir.file("absent.mtx"), 0, "cannot open file for reading");
}

TEST_CASE("Matrix Market round trip is exact [0/1 with self-loops]", "[io][matrix_market]") {
  TempDirectory dir;
  const Network net = test::unweighted_network_with_loops();
  write_matrix_market(dir.file("u.mtx"), net, "{\"generator\": \"test\"}\nsecond line");
  const std::string text = test::read_text(dir.file("u.mtx"));
  CHECK_THAT(text, Catch::Matchers::StartsWith(k_pattern_symmetric + "% {\"generator\": \"test\"}\n"
                                                                     "% second line\n"
                                                                     "6 6 7\n"));
  const ReadResult r = read_matrix_market(dir.file("u.mtx"));
  CHECK(r.warnings.empty());
  test::require_same_network(r.network, net);
  CHECK(dir.listing() == std::vector<std::string>{"u.mtx"});
}

TEST_CASE("Matrix Market round trip is exact [weighted with self-loops / 17 digits]",
          "[io][matrix_market]") {
  TempDirectory dir;
  const Network net = test::awkward_weighted_network();
  write_matrix_market(dir.file("w.mtx"), net);
  CHECK_THAT(test::read_text(dir.file("w.mtx")), Catch::Matchers::StartsWith(k_real_symmetric));
  const ReadResult r = read_matrix_market(dir.file("w.mtx"));
  CHECK(r.warnings.empty());
  test::require_same_network(r.network, net);
}

TEST_CASE("Matrix Market writer to a missing directory throws and creates nothing [no dir]",
          "[io][matrix_market]") {
  TempDirectory dir;
  const std::string path = dir.file("missing/out.mtx");
  const auto e =
      input_error_from([&] { write_matrix_market(path, test::unweighted_network_with_loops()); });
  require_input_error(e, path, 0, "does not exist");
  CHECK(dir.listing().empty());
}

// The size line "2000000000 2000000000 1" with one entry made the reader allocate 16 GB of row
// pointers for a 70-byte file: the bug the edge-list fuzzer found (tests/fuzz), kept as
// crashes/matrix_market/size_line_2e9_nodes.mtx.
TEST_CASE(
    "Matrix Market reader refuses a node count its entries cannot back instead of "
    "allocating it [fuzz: node count]",
    "[io][matrix_market]") {
  TempDirectory dir;
  SECTION("2*10^9 nodes, one entry") {
    const auto e =
        read_error(dir, "big.mtx", k_pattern_symmetric + "% c\n2000000000 2000000000 1\n1 1\n");
    require_input_error(e, dir.file("big.mtx"), 3, "2000000000 nodes for 1 entries: at most");
  }
  SECTION("the limit itself is accepted, one more node is not") {
    const std::string n = std::to_string(max_nodes_for_entries(2));
    write_text(dir.file("edge.mtx"), k_pattern_symmetric + n + " " + n + " 2\n2 1\n1 1\n");
    CHECK(read_matrix_market(dir.file("edge.mtx")).network.size() == (1 << 20) + 128);
    const std::string over = std::to_string(max_nodes_for_entries(2) + 1);
    const auto e =
        read_error(dir, "over.mtx", k_pattern_symmetric + over + " " + over + " 2\n2 1\n1 1\n");
    require_input_error(e, dir.file("over.mtx"), 2, "nodes for 2 entries: at most 1048704");
  }
}

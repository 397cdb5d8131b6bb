// Matrix Market and edge lists parsed by byte ranges over the ranks (docs/scaling.md): every
// rank's rows equal the serial reader's, with the same warnings, on every rank count; a malformed
// line in the last rank's range, a duplicate or an unmatched entry across ranks, a count that
// does not match the size line end every rank with the serial reader's own FILE:LINE message.
// Run at 1, 2 and 3 ranks (label mpi).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.hpp"
#include "io/network_file.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_text_read.hpp"
#include "parallel/parallel_session.hpp"
#include "support/bit_difference.hpp"
#include "support/shared_file.hpp"
#include "support/weighted_networks.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;
using hmfnet::test::collective_message;
using hmfnet::test::SharedFile;
using hmfnet::test::weighted_er;

namespace {

enum class Lines { upper, both };

// One line per entry of the upper triangle (an edge list, a `symmetric` Matrix Market) or of
// both (a `general` one), indices offset by `base`, a weight when the network has them; a
// comment every 97 lines and CRLF endings when asked, so that ranges cut through such lines.
std::string entry_lines(const Network& net, Lines which, int base, const std::string& comment,
                        bool crlf = false) {
  std::ostringstream out;
  std::int64_t k = 0;
  char weight[32];
  for (NodeIndex i = 0; i < net.size(); ++i) {
    for (const auto [j, w] : net.row(i)) {
      if (which == Lines::upper && j < i) continue;
      if (!comment.empty() && ++k % 97 == 0) out << comment << (crlf ? "\r\n" : "\n");
      out << i + base << ' ' << j + base;
      if (net.weighted()) {
        std::snprintf(weight, sizeof weight, " %.17g", w);
        out << weight;
      }
      out << (crlf ? "\r\n" : "\n");
    }
  }
  return out.str();
}

std::int64_t upper_entries(const Network& net) { return (net.nnz() + net.self_loops()) / 2; }

std::string matrix_market(const Network& net, Lines which, const std::string& body = {},
                          std::int64_t removed = 0) {
  const bool general = which == Lines::both;
  std::ostringstream out;
  out << "%%MatrixMarket matrix coordinate " << (net.weighted() ? "real" : "pattern") << ' '
      << (general ? "general" : "symmetric") << "\n% a comment line\n"
      << net.size() << ' ' << net.size() << ' '
      << (general ? net.nnz() : upper_entries(net)) - removed << '\n'
      << (body.empty() ? entry_lines(net, which, 1, "% between entries") : body);
  return out.str();
}

// The serial reader's result for the file, or its error message.
struct Serial {
  ReadResult result;
  std::string error;
};
Serial read_serially(const std::string& path, const ReadOptions& options) {
  Serial s;
  try {
    s.result = read_network(path, options);
  } catch (const InputError& e) {
    s.error = e.what();
  }
  return s;
}

// The rows this rank read equal the serial network's, the blocks are those a reader of the
// serial network cuts, and the warnings are the same.
void check_equals_serial(const SharedFile& file, const ReadOptions& options = {}) {
  const Serial serial = read_serially(file.path(), options);
  CHECK(serial.error.empty());
  const TextRows rows = read_text_rows(file.path(), options);
  const Network& net = serial.result.network;
  const RowBlock expected = slice_rows(net, rows.block.first_row, rows.block.rows());
  INFO(file.path() << " on rank " << ParallelSession::rank() << " of " << ParallelSession::ranks());
  CHECK(rows.block.n == net.size());
  CHECK(rows.block.first_row ==
        balanced_row_starts(
            net.row_ptr(),
            ParallelSession::ranks())[static_cast<std::size_t>(ParallelSession::rank())]);
  CHECK(test::bit_difference(rows.block.row_ptr, expected.row_ptr) == "");
  CHECK(test::bit_difference(rows.block.cols, expected.cols) == "");
  CHECK(test::bit_difference(rows.block.weights, expected.weights) == "");
  CHECK(rows.warnings == serial.result.warnings);
  const double covered = ParallelSession::sum(static_cast<double>(rows.block.rows()));
  CHECK(covered == static_cast<double>(net.size()));
}

// The parallel read fails on every rank with the serial reader's message (FILE:LINE: cause).
void check_same_error(const SharedFile& file, const ReadOptions& options = {}) {
  const Serial serial = read_serially(file.path(), options);
  CHECK_FALSE(serial.error.empty());
  const std::string message = collective_message([&] { read_text_rows(file.path(), options); });
  INFO("rank " << ParallelSession::rank() << " of " << ParallelSession::ranks() << ": " << message);
  CHECK_THAT(message, Contains(serial.error));
}

// The text with its line `line` (1-based) replaced.
std::string replace_line(const std::string& text, std::int64_t line, const std::string& by) {
  std::size_t begin = 0;
  for (std::int64_t k = 1; k < line; ++k) begin = text.find('\n', begin) + 1;
  const std::size_t end = text.find('\n', begin);
  return text.substr(0, begin) + by + text.substr(end);
}

std::int64_t count_lines(const std::string& text) {
  return static_cast<std::int64_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

TEST_CASE("Text files read by byte ranges equal the serial read on every rank count",
          "[distributed][text_read]") {
  const Network net = erdos_renyi({1500, 0.01, 21});
  const Network weighted = weighted_er(900, 0.02, 22);

  SECTION("Matrix Market symmetric pattern, comments between entries") {
    const SharedFile file("hmfnet_text_mm_pattern", ".mtx");
    file.write_text(matrix_market(net, Lines::upper));
    check_equals_serial(file);
  }
  SECTION("Matrix Market symmetric real (weights to the last bit)") {
    const SharedFile file("hmfnet_text_mm_real", ".mtx");
    file.write_text(matrix_market(weighted, Lines::upper));
    check_equals_serial(file);
  }
  SECTION("Matrix Market general: each entry and its transpose, possibly on other ranks") {
    const SharedFile file("hmfnet_text_mm_general", ".mtx");
    file.write_text(matrix_market(weighted, Lines::both));
    check_equals_serial(file);
  }
  SECTION("Matrix Market general, not symmetric, --symmetrize: (A+A^T)/2 and its warning") {
    const SharedFile file("hmfnet_text_mm_symmetrize", ".mtx");
    std::string body = entry_lines(weighted, Lines::both, 1, "");
    // The first entry's weight doubled: it and its transpose no longer match.
    body =
        replace_line(body, 1, "1 " + std::to_string((*weighted.row(0).begin()).col + 1) + " 7.25");
    file.write_text(matrix_market(weighted, Lines::both, body));
    ReadOptions options;
    options.asymmetry = AsymmetryPolicy::symmetrize;
    check_equals_serial(file, options);
  }
  SECTION("Matrix Market general, --symmetrize, a transpose missing across the ranks") {
    // Row 0's last entry (0, j), j in the last rank's rows, loses its transpose (j, 0): the rank
    // owning row j must halve its entry too, though every entry of its own rows is matched.
    const SharedFile file("hmfnet_text_mm_missing_transpose", ".mtx");
    const NodeIndex j = weighted.cols()[static_cast<std::size_t>(weighted.row_ptr()[1] - 1)];
    REQUIRE(j > weighted.size() / 2);
    std::string body = entry_lines(weighted, Lines::both, 1, "");
    // Row j's first entry, (j, 0), is entry row_ptr[j] of the body (one line each).
    body = replace_line(body, weighted.row_ptr()[static_cast<std::size_t>(j)] + 1, "% removed");
    file.write_text(matrix_market(weighted, Lines::both, body, 1));
    ReadOptions options;
    options.asymmetry = AsymmetryPolicy::symmetrize;
    check_equals_serial(file, options);
  }
  SECTION("Edge list, no newline after the last line") {
    const SharedFile file("hmfnet_text_no_newline", ".txt");
    std::string text = entry_lines(net, Lines::upper, 0, "");
    text.pop_back();
    file.write_text(text);
    check_equals_serial(file);
  }
  SECTION("Edge list, 0-based, comments and CRLF lines") {
    const SharedFile file("hmfnet_text_edges", ".txt");
    file.write_text("# an edge list\n" + entry_lines(net, Lines::upper, 0, "# between", true));
    check_equals_serial(file);
  }
  SECTION("Edge list, 1-based, weighted, '# nodes' keeping isolated trailing nodes") {
    const SharedFile file("hmfnet_text_edges_weighted", ".el");
    file.write_text("# nodes 905\n# weighted\n" + entry_lines(weighted, Lines::upper, 1, "#"));
    ReadOptions options;
    options.edge_list_base = 1;
    check_equals_serial(file, options);
  }
  SECTION("Explicit zeros dropped, counted once over the ranks") {
    const SharedFile file("hmfnet_text_edges_zeros", ".txt");
    std::string text = entry_lines(weighted, Lines::upper, 0, "");
    text += "899 899 0\n5 5 0\n";  // self-loops: never a duplicate of an ER edge
    file.write_text(text);
    check_equals_serial(file);
  }
  SECTION("More ranks than lines") {
    const SharedFile file("hmfnet_text_tiny", ".txt");
    file.write_text("0 1\n");
    check_equals_serial(file);
  }
}

TEST_CASE("A bad entry ends every rank with the serial reader's FILE:LINE message",
          "[distributed][text_read]") {
  const Network net = erdos_renyi({1500, 0.01, 23});
  const std::string edges = entry_lines(net, Lines::upper, 0, "");
  const std::int64_t lines = count_lines(edges);
  // Nine tenths into the file: in the last rank's byte range at 1, 2 and 3 ranks.
  const std::int64_t late = lines * 9 / 10;

  SECTION("A malformed line in the last rank's range, reported by that rank") {
    const SharedFile file("hmfnet_text_bad_token", ".txt");
    file.write_text(replace_line(edges, late, "12 x7"));
    check_same_error(file);
    const std::string message = collective_message([&] { read_text_rows(file.path(), {}); });
    CHECK_THAT(message,
               Contains(":" + std::to_string(late) + ": node index 'x7' is not an integer"));
    if (ParallelSession::ranks() > 1) {
      CHECK_THAT(message, Contains("(on rank " + std::to_string(ParallelSession::ranks() - 1)));
    }
  }
  SECTION("An index out of range") {
    const SharedFile file("hmfnet_text_bad_index", ".mtx");
    std::string body = entry_lines(net, Lines::upper, 1, "");
    body = replace_line(body, late, "3 1501");
    file.write_text(matrix_market(net, Lines::upper, body));
    check_same_error(file);
  }
  SECTION("A weight on one late line only") {
    const SharedFile file("hmfnet_text_bad_fields", ".txt");
    file.write_text(replace_line(edges, late, "3 5 0.5"));
    check_same_error(file);
  }
  SECTION("A duplicate edge, reversed, its copies far apart") {
    const SharedFile file("hmfnet_text_duplicate", ".txt");
    file.write_text(edges + std::to_string((*net.row(0).begin()).col) + " 0\n");
    check_same_error(file);
  }
  SECTION("A NaN weight") {
    const SharedFile file("hmfnet_text_nan", ".txt");
    file.write_text("0 1 1.0\n" + std::string("1 2 nan\n"));
    check_same_error(file);
  }
  SECTION("Matrix Market: more entries than declared, and fewer") {
    const std::string body = entry_lines(net, Lines::upper, 1, "");
    const std::string header = "%%MatrixMarket matrix coordinate pattern symmetric\n1500 1500 ";
    const SharedFile more("hmfnet_text_more", ".mtx");
    more.write_text(header + std::to_string(upper_entries(net) - 1) + "\n" + body);
    check_same_error(more);
    // Every rank's range alone holds more than 10: the message still names the 11th entry.
    const SharedFile far_more("hmfnet_text_far_more", ".mtx");
    far_more.write_text(header + "10\n" + body);
    check_same_error(far_more);
    const SharedFile fewer("hmfnet_text_fewer", ".mtx");
    fewer.write_text(header + std::to_string(upper_entries(net) + 1) + "\n" + body);
    check_same_error(fewer);
  }
  SECTION("Matrix Market general: an entry without its transpose") {
    const SharedFile file("hmfnet_text_unmatched", ".mtx");
    std::string body = entry_lines(net, Lines::both, 1, "");
    body = replace_line(body, count_lines(body) * 2 / 3, "% removed");
    file.write_text(matrix_market(net, Lines::both, body, 1));
    check_same_error(file);
  }
  SECTION("'# nodes 1999999999' and no edges: empty, refused before any O(N) allocation") {
    const SharedFile file("hmfnet_text_huge_empty", ".txt");
    file.write_text("# nodes 1999999999\n");
    check_same_error(file);
  }
  SECTION("Only zero weights: an empty network") {
    const SharedFile file("hmfnet_text_empty", ".txt");
    file.write_text("0 1 0\n2 3 0\n");
    check_same_error(file);
  }
  SECTION("A file that cannot be opened") {
    const std::string missing = "/nonexistent/hmfnet_no_such_file.mtx";
    const std::string message = collective_message([&] { read_text_rows(missing, {}); });
    CHECK_THAT(message, Contains(missing) && Contains("cannot open"));
  }
}

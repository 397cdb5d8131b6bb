#include "io/matrix_market.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/entry_lines.hpp"
#include "io/node_count_limit.hpp"
#include "io/text_scanner.hpp"

namespace hmfnet {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

void parse_banner(TextScanner& in, MatrixMarketHeader& h) {
  std::string_view line;
  if (!in.next_line(line)) in.fail("empty file: no %%MatrixMarket header");
  std::vector<std::string_view> t;
  TextScanner::split(line, t);
  if (t.size() != 5 || lower(t[0]) != "%%matrixmarket") {
    in.fail("first line is not a '%%MatrixMarket matrix coordinate FIELD SYMMETRY' header");
  }
  if (lower(t[1]) != "matrix") in.fail("object '" + std::string(t[1]) + "' is not 'matrix'");
  if (lower(t[2]) != "coordinate") {
    in.fail("format '" + std::string(t[2]) + "' is not supported (only 'coordinate')");
  }
  const std::string field = lower(t[3]);
  if (field == "pattern") {
    h.field = MatrixMarketField::pattern;
  } else if (field == "integer") {
    h.field = MatrixMarketField::integer;
  } else if (field == "real") {
    h.field = MatrixMarketField::real;
  } else {
    in.fail("field '" + std::string(t[3]) + "' is not supported (pattern, integer, real)");
  }
  const std::string sym = lower(t[4]);
  if (sym == "symmetric") {
    h.symmetry = EntrySymmetry::symmetric;
  } else if (sym == "general") {
    h.symmetry = EntrySymmetry::general;
  } else {
    in.fail("symmetry '" + std::string(t[4]) + "' is not supported (symmetric, general)");
  }
}

// Skips comments and blank lines; returns false at end of the text read.
bool next_data_line(TextScanner& in, std::string_view& line, std::vector<std::string_view>& t) {
  while (in.next_line(line)) {
    if (!line.empty() && line.front() == '%') continue;
    TextScanner::split(line, t);
    if (!t.empty()) return true;
  }
  return false;
}

NodeIndex parse_index(const TextScanner& in, std::string_view token, std::int64_t n,
                      const char* what) {
  const std::int64_t v = in.parse_integer(token, what);
  if (v < 1 || v > n) {
    in.fail(std::string(what) + " " + std::to_string(v) + " is out of range 1.." +
            std::to_string(n) + (v == 0 ? " (Matrix Market indices are 1-based)" : ""));
  }
  return static_cast<NodeIndex>(v - 1);
}

}  // namespace

std::optional<MatrixMarketHeader> read_matrix_market_header(TextScanner& in) {
  MatrixMarketHeader h;
  parse_banner(in, h);
  std::string_view line;
  std::vector<std::string_view> t;
  if (!next_data_line(in, line, t)) {
    if (in.truncated()) return std::nullopt;
    in.fail("truncated: no size line 'ROWS COLS ENTRIES'");
  }
  if (t.size() != 3) in.fail("size line must be 'ROWS COLS ENTRIES'");
  h.size_line = in.line_number();
  h.rows = in.parse_integer(t[0], "row count");
  const std::int64_t cols = in.parse_integer(t[1], "column count");
  h.declared = in.parse_integer(t[2], "entry count");
  if (h.rows != cols) {
    in.fail("matrix is " + std::to_string(h.rows) + " x " + std::to_string(cols) +
            ": an adjacency matrix must be square");
  }
  if (h.rows < 0 || h.rows > std::numeric_limits<NodeIndex>::max() || h.declared < 0) {
    in.fail("size line out of range");
  }
  return h;
}

void read_matrix_market_entries(TextScanner& in, const MatrixMarketHeader& header,
                                std::vector<MatrixEntry>& entries, std::int64_t limit,
                                EntryLimit at_limit) {
  const std::size_t fields = header.field == MatrixMarketField::pattern ? 2 : 3;
  std::string_view line;
  std::vector<std::string_view> t;
  while (next_data_line(in, line, t)) {
    if (static_cast<std::int64_t>(entries.size()) == limit) {
      if (at_limit == EntryLimit::stop) return;
      in.fail("more entries than the " + std::to_string(header.declared) +
              " declared on the size line");
    }
    if (t.size() != fields) {
      in.fail("expected " + std::to_string(fields) + " fields, found " + std::to_string(t.size()));
    }
    MatrixEntry e{parse_index(in, t[0], header.rows, "row index"),
                  parse_index(in, t[1], header.rows, "column index"), 1.0, in.line_number()};
    if (header.field == MatrixMarketField::integer) {
      e.weight = static_cast<double>(in.parse_integer(t[2], "weight"));
    } else if (header.field == MatrixMarketField::real) {
      e.weight = in.parse_real(t[2], "weight");
    }
    entries.push_back(e);
  }
}

void check_matrix_market_count(const std::string& path, const MatrixMarketHeader& header,
                               std::int64_t found, std::int64_t last_line) {
  if (found < header.declared) {
    throw InputError(path, last_line,
                     "truncated: " + std::to_string(header.declared) + " entries declared, " +
                         std::to_string(found) + " found");
  }
  if (found > 0 && header.rows > max_nodes_for_entries(found)) {
    throw InputError(path, header.size_line,
                     std::to_string(header.rows) + " nodes for " + std::to_string(found) +
                         " entries: at most " + std::to_string(max_nodes_for_entries(found)) +
                         " (mostly isolated nodes; see io/node_count_limit.hpp)");
  }
}

ReadResult read_matrix_market(const std::string& path, const ReadOptions& options) {
  TextScanner in(path);
  const MatrixMarketHeader header = *read_matrix_market_header(in);
  std::vector<MatrixEntry> entries;
  entries.reserve(static_cast<std::size_t>(std::min<std::int64_t>(header.declared, 1 << 20)));
  read_matrix_market_entries(in, header, entries, header.declared);
  check_matrix_market_count(path, header, static_cast<std::int64_t>(entries.size()),
                            in.line_number());
  BuildResult built = build_network(path, static_cast<NodeIndex>(header.rows), std::move(entries),
                                    {header.symmetry, options.asymmetry, 1});
  return {std::move(built.network), std::move(built.warnings)};
}

void write_matrix_market(const std::string& path, const Network& network,
                         const std::string& comment) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temp_path());
    if (!out) throw InputError(path, 0, "cannot open temporary output for writing");
    out << "%%MatrixMarket matrix coordinate " << (network.weighted() ? "real" : "pattern")
        << " symmetric\n";
    std::istringstream lines(comment);
    for (std::string c; std::getline(lines, c);) out << "% " << c << '\n';
    out << network.size() << ' ' << network.size() << ' ' << network.edges() << '\n';
    write_entry_lines(out, network, Triangle::lower, 1);
    out.flush();
    if (!out) throw InputError(path, 0, "write failed (disk full?)");
  }
  file.commit();
}

}  // namespace hmfnet

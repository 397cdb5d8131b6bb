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

enum class Field { pattern, integer, real };

struct Header {
  Field field = Field::pattern;
  EntrySymmetry symmetry = EntrySymmetry::symmetric;
};

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

Header parse_header(TextScanner& in) {
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
  Header h;
  const std::string field = lower(t[3]);
  if (field == "pattern") {
    h.field = Field::pattern;
  } else if (field == "integer") {
    h.field = Field::integer;
  } else if (field == "real") {
    h.field = Field::real;
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
  return h;
}

// Skips comments and blank lines; returns false at end of file.
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

ReadResult read_matrix_market(const std::string& path, const ReadOptions& options) {
  TextScanner in(path);
  const Header header = parse_header(in);
  std::string_view line;
  std::vector<std::string_view> t;
  if (!next_data_line(in, line, t)) in.fail("truncated: no size line 'ROWS COLS ENTRIES'");
  if (t.size() != 3) in.fail("size line must be 'ROWS COLS ENTRIES'");
  const std::int64_t size_line = in.line_number();
  const std::int64_t rows = in.parse_integer(t[0], "row count");
  const std::int64_t cols = in.parse_integer(t[1], "column count");
  const std::int64_t declared = in.parse_integer(t[2], "entry count");
  if (rows != cols) {
    in.fail("matrix is " + std::to_string(rows) + " x " + std::to_string(cols) +
            ": an adjacency matrix must be square");
  }
  if (rows < 0 || rows > std::numeric_limits<NodeIndex>::max() || declared < 0) {
    in.fail("size line out of range");
  }
  const std::size_t fields = header.field == Field::pattern ? 2 : 3;
  std::vector<MatrixEntry> entries;
  entries.reserve(static_cast<std::size_t>(std::min<std::int64_t>(declared, 1 << 20)));
  while (next_data_line(in, line, t)) {
    if (static_cast<std::int64_t>(entries.size()) == declared) {
      in.fail("more entries than the " + std::to_string(declared) + " declared on the size line");
    }
    if (t.size() != fields) {
      in.fail("expected " + std::to_string(fields) + " fields, found " + std::to_string(t.size()));
    }
    MatrixEntry e{parse_index(in, t[0], rows, "row index"),
                  parse_index(in, t[1], rows, "column index"), 1.0, in.line_number()};
    if (header.field == Field::integer) {
      e.weight = static_cast<double>(in.parse_integer(t[2], "weight"));
    } else if (header.field == Field::real) {
      e.weight = in.parse_real(t[2], "weight");
    }
    entries.push_back(e);
  }
  if (static_cast<std::int64_t>(entries.size()) < declared) {
    in.fail("truncated: " + std::to_string(declared) + " entries declared, " +
            std::to_string(entries.size()) + " found");
  }
  const auto stored = static_cast<std::int64_t>(entries.size());
  if (stored > 0 && rows > max_nodes_for_entries(stored)) {
    throw InputError(path, size_line,
                     std::to_string(rows) + " nodes for " + std::to_string(stored) +
                         " entries: at most " + std::to_string(max_nodes_for_entries(stored)) +
                         " (mostly isolated nodes; see io/node_count_limit.hpp)");
  }
  BuildResult built = build_network(path, static_cast<NodeIndex>(rows), std::move(entries),
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

#include "io/edge_list.hpp"

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
constexpr std::string_view k_nodes_comment = "# nodes ";

// The line without its trailing comment, split; empty for blank and comment lines.
void data_fields(std::string_view line, std::vector<std::string_view>& t) {
  const std::size_t hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  TextScanner::split(line, t);
}

void require_index_base(const ReadOptions& options) {
  if (options.edge_list_base != 0 && options.edge_list_base != 1) {
    throw ParameterError("index base", std::to_string(options.edge_list_base), "0 or 1");
  }
}
}  // namespace

std::string field_count_mismatch(std::size_t found, std::size_t earlier) {
  return "this line has " + std::to_string(found) + " fields, earlier lines have " +
         std::to_string(earlier) + " (weights on every line or on none)";
}

std::optional<EdgeListHeader> read_edge_list_header(TextScanner& in) {
  EdgeListHeader header;
  std::vector<std::string_view> t;
  std::string_view line;
  for (;;) {
    const std::int64_t offset = in.offset();
    const std::int64_t line_number = in.line_number();
    if (!in.next_line(line)) break;
    if (line.rfind(k_nodes_comment, 0) == 0) {
      // "# nodes N" (written by write_edge_list) keeps isolated trailing nodes.
      header.declared_nodes = in.parse_integer(line.substr(k_nodes_comment.size()), "node count");
      if (header.declared_nodes < 1 ||
          header.declared_nodes > std::numeric_limits<NodeIndex>::max()) {
        in.fail("node count " + std::to_string(header.declared_nodes) + " out of range");
      }
      continue;
    }
    data_fields(line, t);
    if (t.empty()) continue;
    if (t.size() == 2 || t.size() == 3) header.fields = t.size();
    in.rewind(offset, line_number);
    return header;
  }
  // Only comments in what was read: the header may go on past a prefix.
  if (in.truncated()) return std::nullopt;
  return header;
}

void read_edge_list_entries(TextScanner& in, const ReadOptions& options, EdgeListScan& scan,
                            std::vector<MatrixEntry>& entries) {
  require_index_base(options);
  const std::int64_t base = options.edge_list_base;
  const std::int64_t limit =
      options.edge_list_nodes > 0 ? options.edge_list_nodes : std::numeric_limits<NodeIndex>::max();
  std::vector<std::string_view> t;
  std::string_view line;
  while (in.next_line(line)) {
    data_fields(line, t);
    if (t.empty()) continue;
    if (t.size() != 2 && t.size() != 3) {
      in.fail("expected 'u v' or 'u v w', found " + std::to_string(t.size()) + " fields");
    }
    if (scan.fields == 0) scan.fields = t.size();
    if (t.size() != scan.fields) {
      in.fail(field_count_mismatch(t.size(), scan.fields));
    }
    std::int64_t ends[2];
    for (int k = 0; k < 2; ++k) {
      ends[k] = in.parse_integer(t[static_cast<std::size_t>(k)], "node index");
      if (ends[k] < base || ends[k] - base >= limit) {
        in.fail("node index " + std::to_string(ends[k]) + " is out of range " +
                std::to_string(base) + ".." + std::to_string(base + limit - 1) +
                (base == 1 && ends[k] == 0 ? " (is the file 0-based? see --index-base)" : ""));
      }
      scan.largest = std::max(scan.largest, ends[k] - base);
    }
    const double w = scan.fields == 3 ? in.parse_real(t[2], "weight") : 1.0;
    entries.push_back({static_cast<NodeIndex>(ends[0] - base),
                       static_cast<NodeIndex>(ends[1] - base), w, in.line_number()});
  }
}

NodeIndex edge_list_node_count(const std::string& path, const ReadOptions& options,
                               const EdgeListHeader& header, std::int64_t largest,
                               std::int64_t stored) {
  if (options.edge_list_nodes > 0) return options.edge_list_nodes;
  auto n = static_cast<NodeIndex>(largest + 1);
  if (header.declared_nodes > 0) {
    if (header.declared_nodes <= largest) {
      throw InputError(path, 0,
                       "'# nodes " + std::to_string(header.declared_nodes) + "' but node index " +
                           std::to_string(largest + options.edge_list_base) + " appears");
    }
    n = static_cast<NodeIndex>(header.declared_nodes);
  }
  if (stored > 0 && n > max_nodes_for_entries(stored)) {
    throw InputError(path, 0,
                     std::to_string(n) + " nodes for " + std::to_string(stored) +
                         " edges: at most " + std::to_string(max_nodes_for_entries(stored)) +
                         " without an explicit node count (mostly isolated nodes; see "
                         "io/node_count_limit.hpp)");
  }
  return n;
}

ReadResult read_edge_list(const std::string& path, const ReadOptions& options) {
  require_index_base(options);
  TextScanner in(path);
  const EdgeListHeader header = *read_edge_list_header(in);
  EdgeListScan scan{header.fields, -1};
  std::vector<MatrixEntry> entries;
  read_edge_list_entries(in, options, scan, entries);
  const NodeIndex n = edge_list_node_count(path, options, header, scan.largest,
                                           static_cast<std::int64_t>(entries.size()));
  BuildResult built =
      build_network(path, n, std::move(entries),
                    {EntrySymmetry::symmetric, AsymmetryPolicy::reject, options.edge_list_base});
  return {std::move(built.network), std::move(built.warnings)};
}

void write_edge_list(const std::string& path, const Network& network, const std::string& comment) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temp_path());
    if (!out) throw InputError(path, 0, "cannot open temporary output for writing");
    out << k_nodes_comment << network.size() << '\n';
    std::istringstream lines(comment);
    for (std::string c; std::getline(lines, c);) out << "# " << c << '\n';
    write_entry_lines(out, network, Triangle::upper, 0);
    out.flush();
    if (!out) throw InputError(path, 0, "write failed (disk full?)");
  }
  file.commit();
}

}  // namespace hmfnet

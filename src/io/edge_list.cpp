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
}

ReadResult read_edge_list(const std::string& path, const ReadOptions& options) {
  if (options.edge_list_base != 0 && options.edge_list_base != 1) {
    throw ParameterError("index base", std::to_string(options.edge_list_base), "0 or 1");
  }
  TextScanner in(path);
  const std::int64_t base = options.edge_list_base;
  const std::int64_t limit =
      options.edge_list_nodes > 0 ? options.edge_list_nodes : std::numeric_limits<NodeIndex>::max();
  std::vector<MatrixEntry> entries;
  std::vector<std::string_view> t;
  std::string_view line;
  std::size_t fields = 0;
  std::int64_t largest = -1;
  std::int64_t declared_nodes = 0;
  while (in.next_line(line)) {
    if (entries.empty() && line.rfind(k_nodes_comment, 0) == 0) {
      // "# nodes N" (written by write_edge_list) keeps isolated trailing nodes.
      declared_nodes = in.parse_integer(line.substr(k_nodes_comment.size()), "node count");
      if (declared_nodes < 1 || declared_nodes > std::numeric_limits<NodeIndex>::max()) {
        in.fail("node count " + std::to_string(declared_nodes) + " out of range");
      }
      continue;
    }
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    TextScanner::split(line, t);
    if (t.empty()) continue;
    if (t.size() != 2 && t.size() != 3) {
      in.fail("expected 'u v' or 'u v w', found " + std::to_string(t.size()) + " fields");
    }
    if (fields == 0) fields = t.size();
    if (t.size() != fields) {
      in.fail("this line has " + std::to_string(t.size()) + " fields, earlier lines have " +
              std::to_string(fields) + " (weights on every line or on none)");
    }
    std::int64_t ends[2];
    for (int k = 0; k < 2; ++k) {
      ends[k] = in.parse_integer(t[static_cast<std::size_t>(k)], "node index");
      if (ends[k] < base || ends[k] - base >= limit) {
        in.fail("node index " + std::to_string(ends[k]) + " is out of range " +
                std::to_string(base) + ".." + std::to_string(base + limit - 1) +
                (base == 1 && ends[k] == 0 ? " (is the file 0-based? see --index-base)" : ""));
      }
      largest = std::max(largest, ends[k] - base);
    }
    const double w = fields == 3 ? in.parse_real(t[2], "weight") : 1.0;
    entries.push_back({static_cast<NodeIndex>(ends[0] - base),
                       static_cast<NodeIndex>(ends[1] - base), w, in.line_number()});
  }
  NodeIndex n =
      options.edge_list_nodes > 0 ? options.edge_list_nodes : static_cast<NodeIndex>(largest + 1);
  if (options.edge_list_nodes == 0 && declared_nodes > 0) {
    if (declared_nodes <= largest) {
      throw InputError(path, 0,
                       "'# nodes " + std::to_string(declared_nodes) + "' but node index " +
                           std::to_string(largest + base) + " appears");
    }
    n = static_cast<NodeIndex>(declared_nodes);
  }
  const auto stored = static_cast<std::int64_t>(entries.size());
  if (options.edge_list_nodes == 0 && stored > 0 && n > max_nodes_for_entries(stored)) {
    throw InputError(path, 0,
                     std::to_string(n) + " nodes for " + std::to_string(stored) +
                         " edges: at most " + std::to_string(max_nodes_for_entries(stored)) +
                         " without an explicit node count (mostly isolated nodes; see "
                         "io/node_count_limit.hpp)");
  }
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

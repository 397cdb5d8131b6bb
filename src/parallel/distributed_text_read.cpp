#include "parallel/distributed_text_read.hpp"

#include <algorithm>
#include <optional>

#include "core/error.hpp"
#include "io/edge_list.hpp"
#include "io/matrix_market.hpp"
#include "io/network_file.hpp"
#include "parallel/entry_exchange.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

std::size_t at(std::int64_t k) { return static_cast<std::size_t>(k); }

// Where the body (the entry lines) starts and how many lines precede it.
struct BodyStart {
  std::int64_t offset = 0;
  std::int64_t lines = 0;
};

// The header from a prefix of the file, grown until it holds the whole header.
template <class Header, class ReadHeader>
Header read_header(const std::string& path, ReadHeader read, BodyStart& body) {
  for (std::int64_t prefix = 1 << 16;; prefix *= 4) {
    TextScanner in(path, 0, prefix);
    if (const std::optional<Header> header = read(in)) {
      body = {in.offset(), in.line_number()};
      return *header;
    }
  }
}

// This rank's share of the body: equal byte ranges moved to line starts. Not collective (it
// may fail on one rank: run it inside agree).
TextScanner read_own_range(const std::string& path, const BodyStart& body) {
  const std::int64_t size = TextScanner::file_size(path);
  const auto p = static_cast<std::int64_t>(ParallelSession::rank());
  const auto ranks = static_cast<std::int64_t>(ParallelSession::ranks());
  const auto start = [&](std::int64_t q) {
    if (q == 0) return body.offset;
    if (q == ranks) return size;
    return TextScanner::line_start_at_or_after(path,
                                               body.offset + (size - body.offset) * q / ranks);
  };
  return TextScanner(path, start(p), start(p + 1));
}

// Collective: numbers the lines of every range on from those of the ranges before it.
void number_lines(TextScanner& in, const BodyStart& body) {
  const auto lines = ParallelSession::all_gather(in.count_lines());
  std::int64_t before = body.lines;
  for (int q = 0; q < ParallelSession::rank(); ++q) before += lines[at(q)];
  in.set_lines_before(before);
}

// The header (every rank reads it) and this rank's range of the body, its lines numbered.
template <class Header, class ReadHeader>
std::optional<TextScanner> read_header_and_range(const std::string& path, ReadHeader read,
                                                 Header& header) {
  BodyStart body;
  std::optional<TextScanner> in;
  ParallelSession::agree([&] { header = read_header<Header>(path, read, body); });
  ParallelSession::agree([&] { in.emplace(read_own_range(path, body)); });
  number_lines(*in, body);
  return in;
}

// The parsed entries of this rank and what the whole file says.
struct Parsed {
  NodeIndex n = 0;
  BuildOptions build;
  std::vector<MatrixEntry> entries;
};

Parsed parse_matrix_market(const std::string& path, const ReadOptions& options) {
  Parsed parsed;
  MatrixMarketHeader header;
  std::optional<TextScanner> in = read_header_and_range(path, read_matrix_market_header, header);
  // Each rank stops after declared + 1 entries (what a file with a wrong size line may hold
  // is bounded) and the check below names the first entry past the declared count.
  ParallelSession::agree([&] {
    read_matrix_market_entries(*in, header, parsed.entries, header.declared + 1, EntryLimit::stop);
  });
  const auto counts = ParallelSession::all_gather(static_cast<std::int64_t>(parsed.entries.size()));
  ParallelSession::agree([&] {
    std::int64_t before = 0;
    for (int q = 0; q < ParallelSession::rank(); ++q) before += counts[at(q)];
    const std::int64_t mine = static_cast<std::int64_t>(parsed.entries.size());
    if (before <= header.declared && header.declared < before + mine) {
      throw InputError(path, parsed.entries[at(header.declared - before)].line,
                       "more entries than the " + std::to_string(header.declared) +
                           " declared on the size line");
    }
  });
  std::int64_t found = 0;
  for (const auto c : counts) found += c;
  const auto last_line = static_cast<std::int64_t>(
      ParallelSession::max(static_cast<double>(in->line_number())));  // the last rank's last line
  ParallelSession::agree([&] { check_matrix_market_count(path, header, found, last_line); });
  parsed.n = static_cast<NodeIndex>(header.rows);
  parsed.build = {header.symmetry, options.asymmetry, 1};
  return parsed;
}

Parsed parse_edge_list(const std::string& path, const ReadOptions& options) {
  Parsed parsed;
  EdgeListHeader header;
  std::optional<TextScanner> in = read_header_and_range(path, read_edge_list_header, header);
  // Weights on every line or on none: the file's first edge line (in the header's view) sets the
  // field count for every rank.
  EdgeListScan scan{header.fields, -1};
  ParallelSession::agree([&] { read_edge_list_entries(*in, options, scan, parsed.entries); });
  const auto largest =
      static_cast<std::int64_t>(ParallelSession::max(static_cast<double>(scan.largest)));
  std::int64_t stored = 0;
  for (const auto c : ParallelSession::all_gather(static_cast<std::int64_t>(parsed.entries.size())))
    stored += c;
  ParallelSession::agree(
      [&] { parsed.n = edge_list_node_count(path, options, header, largest, stored); });
  parsed.build = {EntrySymmetry::symmetric, AsymmetryPolicy::reject, options.edge_list_base};
  return parsed;
}

// Rows cut by the entries each would store (both ends of a symmetric entry), summed over ranks.
std::vector<NodeIndex> row_starts_by_entries(const Parsed& parsed) {
  std::vector<std::uint64_t> count;
  ParallelSession::agree([&] {
    count.assign(at(parsed.n), 0);
    for (const auto& e : parsed.entries) {
      if (e.weight == 0.0) continue;  // an explicit zero is dropped, not stored
      ++count[at(e.row)];
      if (parsed.build.symmetry == EntrySymmetry::symmetric && e.row != e.col) ++count[at(e.col)];
    }
  });
  ParallelSession::sum_in_place(count);
  return balanced_row_starts(row_pointers_from_counts(count), ParallelSession::ranks());
}

}  // namespace

TextRows read_text_rows(const std::string& path, const ReadOptions& options) {
  NetworkFormat format = NetworkFormat::hdf5;
  ParallelSession::agree([&] { format = format_from_extension(path); });
  Parsed parsed = format == NetworkFormat::matrix_market ? parse_matrix_market(path, options)
                                                         : parse_edge_list(path, options);
  // Refused before anything O(N) is allocated: with no entries the node count is not bounded
  // (io/node_count_limit.hpp), "# nodes 1999999999" alone would ask for 16 GB per rank.
  const double nonzero = ParallelSession::sum(
      static_cast<double>(std::count_if(parsed.entries.begin(), parsed.entries.end(),
                                        [](const MatrixEntry& e) { return e.weight != 0.0; })));
  ParallelSession::agree([&] {
    if (parsed.n <= 0 || nonzero == 0.0) {
      throw InputError(path, 0,
                       "empty network: " + std::to_string(parsed.n) + " nodes and no edges");
    }
  });
  const std::vector<NodeIndex> row_starts = row_starts_by_entries(parsed);
  const NodeIndex first = row_starts[at(ParallelSession::rank())];
  const NodeIndex last = row_starts[at(ParallelSession::rank()) + 1];
  std::vector<MatrixEntry> mine =
      send_to_owners(parsed.entries, row_starts, Destinations::row_and_column_owner);
  parsed.entries = {};
  RowsBuild build;
  ParallelSession::agree(
      [&] { build = build_rows(path, parsed.n, first, last, std::move(mine), parsed.build); });

  // What needs the whole network: emptiness, the counts behind warnings, 0/1 or weighted.
  TextRows result;
  const double zeros = ParallelSession::sum(static_cast<double>(build.zeros));
  const double unmatched = ParallelSession::sum(static_cast<double>(build.unmatched));
  const double stored = ParallelSession::sum(static_cast<double>(build.block.nnz()));
  const double weighted = ParallelSession::max(build.all_ones ? 0.0 : 1.0);
  if (zeros > 0) result.warnings.push_back(zeros_warning(path, static_cast<std::int64_t>(zeros)));
  ParallelSession::agree([&] {
    if (stored == 0) {
      throw InputError(path, 0,
                       "empty network: " + std::to_string(parsed.n) + " nodes and no edges");
    }
    if (build.unmatched > 0 && parsed.build.asymmetry == AsymmetryPolicy::reject) {
      throw InputError(path, build.first_unmatched_line,
                       asymmetry_message(build, static_cast<std::int64_t>(unmatched)));
    }
  });
  if (unmatched > 0)
    result.warnings.push_back(asymmetry_warning(path, static_cast<std::int64_t>(unmatched)));
  // A block whose own weights are all 1 kept none; the network is weighted if any block is.
  if (weighted > 0.0 && build.all_ones) build.block.weights.assign(build.block.cols.size(), 1.0);
  result.block = std::move(build.block);
  return result;
}

}  // namespace hmfnet

#include "io/network_hdf5.hpp"

#include <limits>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/hdf5_file.hpp"

namespace hmfnet {

namespace {
// Version 1: the CSR arrays. Version 2: a structure stored implicitly (no arrays); CSR files are
// still written as version 1, so every file an older hmfnet reads is still written the same way,
// and an older hmfnet refuses an implicit file by its version instead of a missing dataset.
constexpr std::int64_t k_csr_version = 1;
constexpr std::int64_t k_implicit_version = 2;

// Checks the root attributes and returns the format version (1 or 2).
std::int64_t network_format_version(const Hdf5File& file) {
  const hid_t root = file.id();
  if (!file.has_attribute(root, "hmfnet_format") ||
      file.string_attribute(root, "hmfnet_format") != "network") {
    file.fail("not an hmfnet network file (attribute hmfnet_format != \"network\")");
  }
  const std::int64_t version = file.int_attribute(root, "format_version");
  if (version != k_csr_version && version != k_implicit_version) {
    file.fail("network format version " + std::to_string(version) + " is not supported (" +
              std::to_string(k_csr_version) + " or " + std::to_string(k_implicit_version) + ")");
  }
  return version;
}

void write_root_attributes(const Hdf5File& file, std::int64_t format_version,
                           const std::string& provenance) {
  const hid_t root = file.id();
  file.set_attribute(root, "hmfnet_format", std::string("network"));
  file.set_attribute(root, "format_version", format_version);
  file.set_attribute(root, "hmfnet_version", std::string(version()));
  file.set_attribute(root, "git_commit", std::string(git_commit()));
  file.set_attribute(root, "provenance", provenance);
}

CompleteGraph read_complete_graph(const Hdf5File& file) {
  const H5Id group = file.open_group("network");
  const std::string structure = file.string_attribute(group.get(), "structure");
  if (structure != "complete") {
    file.fail("/network: structure \"" + structure + "\" is not known (complete)");
  }
  const std::int64_t n = file.int_attribute(group.get(), "n");
  if (n < 2 || n > std::numeric_limits<NodeIndex>::max()) {
    file.fail("/network: n = " + std::to_string(n) + " (allowed: 2 <= n <= " +
              std::to_string(std::numeric_limits<NodeIndex>::max()) + ")");
  }
  const std::int64_t loops = file.int_attribute(group.get(), "self_loops_all");
  if (loops != 0 && loops != 1) {
    file.fail("/network: self_loops_all = " + std::to_string(loops) + " (allowed: 0 or 1)");
  }
  const CompleteGraph graph = CompleteGraph::make(n, loops == 1);
  // The summary attributes are what tools that read only attributes see: they must agree.
  const std::pair<const char*, std::int64_t> summary[] = {
      {"nnz", graph.nnz()},
      {"edges", graph.edges()},
      {"self_loops", graph.self_loops ? graph.n : 0},
      {"weighted", 0}};
  for (const auto& [name, expected] : summary) {
    const std::int64_t stored = file.int_attribute(group.get(), name);
    if (stored != expected) {
      file.fail(std::string("/network: ") + name + " = " + std::to_string(stored) +
                " disagrees with the complete graph of n = " + std::to_string(n) +
                (graph.self_loops ? " with" : " without") + " self-loops (" +
                std::to_string(expected) + ")");
    }
  }
  return graph;
}

NodeIndex node_count(const Hdf5File& file, hid_t group) {
  const std::int64_t n = file.int_attribute(group, "n");
  if (n < 0 || n > std::numeric_limits<NodeIndex>::max()) {
    file.fail("/network: node count " + std::to_string(n) + " out of range");
  }
  return static_cast<NodeIndex>(n);
}

// Whether the file stores weights: `weights` exists exactly when weighted = 1
// (docs/file_formats.md). A file with one but not the other contradicts itself, and reading it
// either way would be a guess, so it is refused.
bool weighted_flag(const Hdf5File& file, hid_t group) {
  const std::int64_t weighted = file.int_attribute(group, "weighted");
  if (weighted != 0 && weighted != 1) {
    file.fail("/network: weighted = " + std::to_string(weighted) + " (allowed: 0 or 1)");
  }
  if (weighted == 0 && file.exists("network/weights")) {
    file.fail("/network: dataset weights is present but attribute weighted = 0");
  }
  return weighted == 1;
}

// The summary attribute nnz is what tools that read only attributes see: it must count the
// stored column indices.
void require_nnz_attribute(const Hdf5File& file, hid_t group, std::int64_t entries) {
  const std::int64_t nnz = file.int_attribute(group, "nnz");
  if (nnz != entries) {
    file.fail("/network: attribute nnz = " + std::to_string(nnz) + " but dataset col holds " +
              std::to_string(entries) + " entries");
  }
}

// Network::check_csr walks col[row_ptr[i]..row_ptr[i+1]) row by row and only then sees a
// pointer that is out of order, so pointers from a file are bounded first: a corrupted one
// must be refused, not read past the end of col.
void require_bounded_row_ptr(const Hdf5File& file, const std::vector<std::int64_t>& row_ptr,
                             std::int64_t nnz) {
  for (std::size_t i = 0; i < row_ptr.size(); ++i) {
    const std::int64_t low = i == 0 ? 0 : row_ptr[i - 1];
    if (row_ptr[i] < low || row_ptr[i] > nnz) {
      file.fail("/network: row_ptr[" + std::to_string(i) + "] = " + std::to_string(row_ptr[i]) +
                " is outside [" + std::to_string(low) + ", nnz = " + std::to_string(nnz) + "]");
    }
  }
}

}  // namespace

std::optional<CompleteGraph> read_implicit_network_hdf5(const std::string& path) {
  const Hdf5File file(path, Hdf5File::Mode::read);
  if (network_format_version(file) != k_implicit_version) return std::nullopt;
  return read_complete_graph(file);
}

namespace {
void refuse_implicit(const Hdf5File& file) {
  if (network_format_version(file) == k_implicit_version) {
    const CompleteGraph graph = read_complete_graph(file);
    file.fail("the complete graph of " + std::to_string(graph.n) +
              " nodes is stored implicitly, not as rows: this needs stored rows (hmfnet "
              "spectrum, theory and simulate read it; in the library, read_network_input)");
  }
}
}  // namespace

ReadResult read_network_hdf5(const std::string& path) {
  const Hdf5File file(path, Hdf5File::Mode::read);
  refuse_implicit(file);
  const H5Id group = file.open_group("network");
  const NodeIndex n = node_count(file, group.get());
  auto row_ptr = file.read_int64(group.get(), "row_ptr");
  auto cols = file.read_int32(group.get(), "col");
  std::vector<double> weights;
  if (weighted_flag(file, group.get())) weights = file.read_double(group.get(), "weights");
  require_nnz_attribute(file, group.get(), static_cast<std::int64_t>(cols.size()));
  require_bounded_row_ptr(file, row_ptr, static_cast<std::int64_t>(cols.size()));
  const NodeIndex nodes = n;
  const std::string why = Network::check_csr(nodes, row_ptr, cols, weights);
  if (!why.empty()) file.fail("/network: " + why);
  if (cols.empty()) file.fail("empty network: " + std::to_string(n) + " nodes and no edges");
  return {Network::from_csr(nodes, std::move(row_ptr), std::move(cols), std::move(weights)), {}};
}

RowBlock read_network_hdf5_rows(const std::string& path, int part, int parts) {
  if (parts < 1 || part < 0 || part >= parts) {
    throw ParameterError("row block of " + path,
                         "part " + std::to_string(part) + " of " + std::to_string(parts),
                         "0 <= part < parts");
  }
  const Hdf5File file(path, Hdf5File::Mode::read);
  refuse_implicit(file);
  const H5Id group = file.open_group("network");
  RowBlock block;
  block.n = node_count(file, group.get());
  // O(N) on every rank: the pointers bound the blocks and cut them by stored entries.
  const std::vector<std::int64_t> row_ptr = file.read_int64(group.get(), "row_ptr");
  const auto nnz = static_cast<std::int64_t>(file.dataset_size(group.get(), "col", H5T_INTEGER));
  if (row_ptr.size() != static_cast<std::size_t>(block.n) + 1) {
    file.fail("/network: row_ptr has " + std::to_string(row_ptr.size()) +
              " entries, expected n+1 = " + std::to_string(std::int64_t{block.n} + 1));
  }
  require_nnz_attribute(file, group.get(), nnz);
  const bool weighted = weighted_flag(file, group.get());
  require_bounded_row_ptr(file, row_ptr, nnz);
  // Blocks are read relative to their first pointer, so a shifted array would go unnoticed.
  if (row_ptr.front() != 0) {
    file.fail("/network: row_ptr[0] = " + std::to_string(row_ptr.front()) + ", not 0");
  }
  if (row_ptr.back() != nnz) {
    file.fail("/network: row_ptr[n] = " + std::to_string(row_ptr.back()) + " but there are " +
              std::to_string(nnz) + " column indices");
  }
  if (nnz == 0) file.fail("empty network: " + std::to_string(block.n) + " nodes and no edges");
  const std::vector<NodeIndex> starts = balanced_row_starts(row_ptr, parts);
  block.first_row = starts[static_cast<std::size_t>(part)];
  const NodeIndex last = starts[static_cast<std::size_t>(part) + 1];
  const std::int64_t begin = row_ptr[static_cast<std::size_t>(block.first_row)];
  const std::int64_t end = row_ptr[static_cast<std::size_t>(last)];
  block.row_ptr.assign(row_ptr.begin() + block.first_row, row_ptr.begin() + last + 1);
  for (auto& p : block.row_ptr) p -= begin;
  const auto first = static_cast<std::size_t>(begin);
  const auto count = static_cast<std::size_t>(end - begin);
  block.cols = file.read_int32(group.get(), "col", first, count);
  if (weighted) {
    block.weights = file.read_double(group.get(), "weights", first, count);
    if (file.dataset_size(group.get(), "weights", H5T_FLOAT) != static_cast<std::size_t>(nnz)) {
      file.fail("/network: weights and col differ in length");
    }
  }
  const std::string why = check_row_block(block);
  if (!why.empty()) file.fail("/network: " + why);
  return block;
}

namespace {
void write_network_attributes(const Hdf5File& file, hid_t group, const NetworkTotals& totals) {
  file.set_attribute(group, "n", static_cast<std::int64_t>(totals.n));
  file.set_attribute(group, "nnz", totals.nnz);
  // Every off-diagonal edge is stored twice, a self-loop once.
  file.set_attribute(group, "edges", (totals.nnz + totals.self_loops) / 2);
  file.set_attribute(group, "self_loops", totals.self_loops);
  file.set_attribute(group, "weighted", static_cast<std::int64_t>(totals.weighted));
}
}  // namespace

void write_network_hdf5(const std::string& path, const Network& network,
                        const std::string& provenance) {
  AtomicFile out(path);
  {
    const Hdf5File file(out.temp_path(), Hdf5File::Mode::create);
    write_root_attributes(file, k_csr_version, provenance);
    const H5Id group = file.create_group("network");
    write_network_attributes(
        file, group.get(),
        {network.size(), network.nnz(), network.self_loops(), network.weighted()});
    file.write(group.get(), "row_ptr", network.row_ptr());
    file.write(group.get(), "col", network.cols());
    if (network.weighted()) file.write(group.get(), "weights", network.weights());
    file.flush();
  }
  out.commit();
}

void create_network_hdf5(const std::string& path, const NetworkTotals& totals,
                         const std::string& provenance) {
  const Hdf5File file(path, Hdf5File::Mode::create);
  write_root_attributes(file, k_csr_version, provenance);
  const H5Id group = file.create_group("network");
  write_network_attributes(file, group.get(), totals);
  const auto nnz = static_cast<std::size_t>(totals.nnz);
  file.create_dataset(group.get(), "row_ptr", H5T_STD_I64LE,
                      static_cast<std::size_t>(totals.n) + 1);
  file.create_dataset(group.get(), "col", H5T_STD_I32LE, nnz);
  if (totals.weighted) file.create_dataset(group.get(), "weights", H5T_IEEE_F64LE, nnz);
  file.flush();
}

void write_original_index(const std::string& path, const std::vector<NodeIndex>& original_index) {
  const Hdf5File file(path, Hdf5File::Mode::update);
  const H5Id group = file.open_group("network");
  file.write(group.get(), "original_index",
             std::vector<std::int32_t>(original_index.begin(), original_index.end()));
  file.flush();
}

void write_network_hdf5_rows(const std::string& path, const RowBlock& block,
                             EdgeOffset entries_before) {
  const Hdf5File file(path, Hdf5File::Mode::update);
  const H5Id group = file.open_group("network");
  std::vector<std::int64_t> pointers(block.row_ptr.begin(), block.row_ptr.end());
  for (auto& p : pointers) p += entries_before;
  // rows + 1 pointers: the last one is the next block's first (the same value), or row_ptr[n].
  file.write_range(group.get(), "row_ptr", static_cast<std::size_t>(block.first_row), pointers);
  const auto first = static_cast<std::size_t>(entries_before);
  file.write_range(group.get(), "col", first, block.cols);
  if (block.weighted()) file.write_range(group.get(), "weights", first, block.weights);
  file.flush();
}

}  // namespace hmfnet

namespace hmfnet {

void write_complete_graph_hdf5(const std::string& path, const CompleteGraph& graph,
                               const std::string& provenance) {
  AtomicFile out(path);
  {
    const Hdf5File file(out.temp_path(), Hdf5File::Mode::create);
    write_root_attributes(file, k_implicit_version, provenance);
    const H5Id group = file.create_group("network");
    file.set_attribute(group.get(), "structure", std::string("complete"));
    file.set_attribute(group.get(), "n", static_cast<std::int64_t>(graph.n));
    file.set_attribute(group.get(), "self_loops_all", static_cast<std::int64_t>(graph.self_loops));
    // The summary attributes of a CSR file, for tools that read only attributes.
    file.set_attribute(group.get(), "nnz", static_cast<std::int64_t>(graph.nnz()));
    file.set_attribute(group.get(), "edges", static_cast<std::int64_t>(graph.edges()));
    file.set_attribute(group.get(), "self_loops",
                       static_cast<std::int64_t>(graph.self_loops ? graph.n : 0));
    file.set_attribute(group.get(), "weighted", std::int64_t{0});
    file.flush();
  }
  out.commit();
}

}  // namespace hmfnet

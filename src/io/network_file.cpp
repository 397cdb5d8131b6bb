#include "io/network_file.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include "core/error.hpp"
#include "io/edge_list.hpp"
#include "io/matrix_market.hpp"
#include "io/network_hdf5.hpp"

namespace hmfnet {

namespace {

std::optional<NetworkFormat> format_of_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? std::string() : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "mtx" || ext == "mm") return NetworkFormat::matrix_market;
  if (ext == "h5" || ext == "hdf5") return NetworkFormat::hdf5;
  if (ext == "txt" || ext == "edges" || ext == "el" || ext == "tsv")
    return NetworkFormat::edge_list;
  return std::nullopt;
}

}  // namespace

NetworkFormat format_from_extension(const std::string& path) {
  if (const auto format = format_of_extension(path)) return *format;
  throw InputError(path, 0,
                   "unknown network file extension (use .mtx/.mm, .h5/.hdf5, or "
                   ".txt/.edges/.el/.tsv for edge lists)");
}

void require_not_a_text_network_name(const std::string& role, const std::string& path) {
  const auto format = format_of_extension(path);
  if (format != NetworkFormat::matrix_market && format != NetworkFormat::edge_list) return;
  throw InputError(
      path, 0,
      role + " is written in HDF5, but its extension names " +
          (format == NetworkFormat::matrix_market ? "a Matrix Market" : "an edge-list") +
          " network file; choose a name ending in .h5");
}

ReadResult read_network(const std::string& path, const ReadOptions& options) {
  switch (format_from_extension(path)) {
    case NetworkFormat::matrix_market:
      return read_matrix_market(path, options);
    case NetworkFormat::hdf5:
      return read_network_hdf5(path);
    case NetworkFormat::edge_list:
      return read_edge_list(path, options);
  }
  throw InputError(path, 0, "unreachable format");
}

NetworkInput read_network_input(const std::string& path, const ReadOptions& options) {
  if (format_from_extension(path) == NetworkFormat::hdf5) {
    if (auto graph = read_implicit_network_hdf5(path)) return {*graph, {}};
  }
  ReadResult r = read_network(path, options);
  return {std::move(r.network), std::move(r.warnings)};
}

void require_complete_graph_format(const std::string& path) {
  if (format_from_extension(path) != NetworkFormat::hdf5) {
    throw InputError(path, 0,
                     "the complete graph is stored implicitly only in hmfnet HDF5 (.h5): a text "
                     "format would list N (N - 1) entries");
  }
}

void write_complete_graph(const std::string& path, const CompleteGraph& graph,
                          const std::string& provenance) {
  require_complete_graph_format(path);
  write_complete_graph_hdf5(path, graph, provenance);
}

void write_network(const std::string& path, const Network& network, const std::string& provenance) {
  switch (format_from_extension(path)) {
    case NetworkFormat::matrix_market:
      write_matrix_market(path, network, provenance);
      return;
    case NetworkFormat::hdf5:
      write_network_hdf5(path, network, provenance);
      return;
    case NetworkFormat::edge_list:
      write_edge_list(path, network, provenance);
      return;
  }
}

}  // namespace hmfnet

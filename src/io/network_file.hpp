#pragma once
// Reading and writing networks by file name: `.mtx`/`.mm` Matrix Market, `.h5`/`.hdf5` hmfnet
// HDF5, `.txt`/`.edges`/`.el`/`.tsv` whitespace edge list. Unknown extensions are an error.
#include <string>
#include <variant>
#include <vector>

#include "io/read_options.hpp"
#include "network/complete_graph.hpp"

namespace hmfnet {

enum class NetworkFormat { matrix_market, hdf5, edge_list };

/// Throws InputError naming the file if the extension is not one of the above.
NetworkFormat format_from_extension(const std::string& path);

/// Throws InputError naming the file and `role` (an option: "--output") where the extension
/// names a text network format (.mtx/.mm, an edge list) but the command writes HDF5 there: the
/// file would not be what its name says, and a later read of it as a network fails.
void require_not_a_text_network_name(const std::string& role, const std::string& path);

/// The stored rows of a network file; a file that holds an implicit structure (the complete
/// graph) is refused with an InputError naming it: read those with read_network_input.
ReadResult read_network(const std::string& path, const ReadOptions& options = {});

/// What a network file holds: its stored rows, or a structure stored implicitly in O(1) space.
struct NetworkInput {
  std::variant<Network, CompleteGraph> graph;
  std::vector<std::string> warnings;  ///< as ReadResult's

  /// The complete graph, or nullptr when the file stores rows.
  const CompleteGraph* complete() const { return std::get_if<CompleteGraph>(&graph); }
  /// The stored rows; throws std::bad_variant_access for an implicit structure.
  const Network& stored() const { return std::get<Network>(graph); }
  NodeIndex size() const { return complete() != nullptr ? complete()->n : stored().size(); }
};

/// Any network file: an implicit structure (hmfnet HDF5 format 2) as it is, anything else as
/// read_network reads it.
NetworkInput read_network_input(const std::string& path, const ReadOptions& options = {});

/// Throws the InputError of write_complete_graph for a path that is not hmfnet HDF5.
void require_complete_graph_format(const std::string& path);

/// K_N, which only hmfnet HDF5 stores implicitly: another extension is refused with an
/// InputError naming the file (a text format would list N (N - 1) entries).
void write_complete_graph(const std::string& path, const CompleteGraph& graph,
                          const std::string& provenance = "{}");

/// `provenance`: JSON text, stored as an attribute (HDF5) or as comment lines (text formats).
void write_network(const std::string& path, const Network& network,
                   const std::string& provenance = "{}");

}  // namespace hmfnet

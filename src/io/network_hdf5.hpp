#pragma once
// hmfnet's own network file (HDF5), documented in docs/file_formats.md:
//   /                attributes  hmfnet_format = "network", format_version = 1,
//                                hmfnet_version, git_commit, provenance (JSON text)
//   /network         attributes  n, nnz, edges, self_loops, weighted (0/1)
//   /network/row_ptr int64[n+1]  CSR row pointers
//   /network/col     int32[nnz]  column indices, sorted within each row, full symmetric matrix
//   /network/weights float64[nnz] only when weighted
// The reader checks every invariant of Network (so a corrupted file is refused, naming the
// dataset and the violation).
//
// A structure stored implicitly (format_version = 2, no datasets):
//   /network         attributes  structure = "complete", n, self_loops_all (0/1), and the
//                                summary attributes nnz, edges, self_loops, weighted = 0
#include <optional>
#include <string>

#include "io/read_options.hpp"
#include "network/complete_graph.hpp"
#include "network/row_block.hpp"

namespace hmfnet {

/// The CSR network; a file with an implicit structure is refused (InputError naming it).
ReadResult read_network_hdf5(const std::string& path);

/// Block `part` of `parts` of a CSR network file (0 <= part < parts): the rows
/// balanced_row_starts gives it, read by hyperslabs, so a rank holds O(N) pointers and its own
/// entries only. Every per-row invariant is checked (InputError naming the file); symmetry spans
/// the blocks: check it with require_symmetric (parallel/distributed_read.hpp, collective).
/// Not collective itself: every rank opens the file read-only on its own.
RowBlock read_network_hdf5_rows(const std::string& path, int part, int parts);

/// The complete graph a format-2 file holds, or nullopt for a CSR file (read_network_hdf5 reads
/// it). Refuses, naming the file, an unknown structure and N or self_loops_all out of range.
std::optional<CompleteGraph> read_implicit_network_hdf5(const std::string& path);

/// K_N in O(1) space (format_version 2), written to a temporary and renamed.
void write_complete_graph_hdf5(const std::string& path, const CompleteGraph& graph,
                               const std::string& provenance = "{}");

/// `provenance` is JSON text (generator, parameters, seed, command line).
void write_network_hdf5(const std::string& path, const Network& network,
                        const std::string& provenance = "{}");

/// What the /network attributes of a CSR file say, summed over the row blocks.
struct NetworkTotals {
  NodeIndex n = 0;
  EdgeOffset nnz = 0;
  EdgeOffset self_loops = 0;
  bool weighted = false;
};

/// A CSR network file written by row blocks, the same file write_network_hdf5 writes: one rank
/// creates it (attributes, datasets allocated but empty), then each rank in turn writes its rows
/// (row_ptr[first_row .. first_row + rows], col and weights from entries_before on, the stored
/// entries of the rows before the block). Not atomic by itself: `path` is an AtomicFile's
/// temporary, renamed once every block is in (parallel/distributed_generation.hpp).
void create_network_hdf5(const std::string& path, const NetworkTotals& totals,
                         const std::string& provenance = "{}");
void write_network_hdf5_rows(const std::string& path, const RowBlock& block,
                             EdgeOffset entries_before);
/// Adds /network/original_index (int32[n]) to such a file: node i was node original_index[i]
/// of the network it was renumbered from (`hmfnet convert --partition`). Readers ignore it.
void write_original_index(const std::string& path, const std::vector<NodeIndex>& original_index);

}  // namespace hmfnet

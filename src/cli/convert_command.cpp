// `hmfnet convert IN -o OUT.h5`: a network file to hmfnet HDF5, the format every rank reads by
// row blocks, so a large text network is parsed once (issue #15 item 1). The text is parsed in
// parallel (parallel/distributed_text_read.hpp) and the rows written without gathering them
// (parallel/distributed_network_file.hpp): the file is the same for any rank count and equals
// what `write_network` writes for the serial read. `--partition P` renumbers the nodes so that
// the P parts of a Zoltan2 partition (PHG) are contiguous row blocks
// (parallel/graph_partition.hpp), recording the old indices in /network/original_index.
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command_options.hpp"
#include "cli/commands.hpp"
#include "cli/provenance.hpp"
#include "cli/read_flags.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/network_file.hpp"
#include "parallel/distributed_network_file.hpp"
#include "parallel/distributed_read.hpp"
#include "parallel/graph_partition.hpp"
#include "parallel/node_renumbering.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet::cli {

namespace {

// Renumbers `block` so that the parts Zoltan2 finds are contiguous; records the cut in
// `parameters` and returns the original index of each new node (for rank 0 to write).
std::vector<NodeIndex> partition_and_renumber(RowBlock& block, int parts, std::uint64_t seed,
                                              nlohmann::json& parameters) {
  const std::vector<int> part = partition_rows(block, parts, seed);
  const PartOrder order = order_by_part(block, part, parts);
  block = renumber_rows(block, order.new_index);
  const std::int64_t cut = cut_entries(block, order);
  std::vector<std::uint64_t> total{static_cast<std::uint64_t>(block.nnz())};
  ParallelSession::sum_in_place(total);
  std::vector<NodeIndex> sizes;
  for (std::size_t p = 0; p + 1 < order.part_start.size(); ++p)
    sizes.push_back(order.part_start[p + 1] - order.part_start[p]);
  parameters["partition_method"] = "Zoltan2 phg (Zoltan PHG), vertex weight 1 + stored entries";
  parameters["partition_nodes"] = sizes;
  parameters["cut_entries"] = cut;
  parameters["cut_fraction"] = static_cast<double>(cut) / static_cast<double>(total[0]);
  if (is_root()) {
    std::cerr << "partition into " << parts << " parts: " << cut << " of " << total[0]
              << " stored entries cut (" << static_cast<double>(cut) / static_cast<double>(total[0])
              << ")\n";
  }
  std::vector<NodeIndex> original(order.new_index.size());
  for (std::size_t i = 0; i < original.size(); ++i)
    original[static_cast<std::size_t>(order.new_index[i])] = static_cast<NodeIndex>(i);
  return original;
}

void run(const ConvertFlags& f) {
  if (format_from_extension(f.output) != NetworkFormat::hdf5) {
    throw InputError(f.output, 0,
                     "convert writes hmfnet HDF5 (.h5/.hdf5), the format the ranks read by row "
                     "blocks");
  }
  require_writable_destination(f.output);
  const auto start = std::chrono::steady_clock::now();
  DistributedRows rows = f.read.read_distributed_rows(f.input);
  nlohmann::json parameters{{"input", f.input}, {"partition", f.partition}, {"seed", f.seed}};
  std::vector<NodeIndex> original_index;
  if (f.partition > 0 && rows.complete) {
    throw InputError(f.input, 0,
                     "the complete graph is held implicitly: it has no rows to partition");
  }
  if (f.partition > 0) {
    original_index = partition_and_renumber(rows.block, f.partition, f.seed, parameters);
  }
  const std::string record = provenance("convert", parameters);
  std::uint64_t nnz = 0;
  if (rows.complete) {
    ParallelSession::agree([&] {
      if (is_root()) write_complete_graph(f.output, *rows.complete, record);
    });
    nnz = static_cast<std::uint64_t>(rows.complete->nnz());
  } else {
    std::vector<std::uint64_t> total{static_cast<std::uint64_t>(rows.block.nnz())};
    ParallelSession::sum_in_place(total);
    nnz = total[0];
    write_distributed_network_hdf5(f.output, rows.block, record, original_index);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<double> peak = ParallelSession::peak_memory_mb();
  if (!is_root()) return;
  const NodeIndex n = rows.complete ? rows.complete->n : rows.block.n;
  std::cerr << "wrote " << f.output << ": N = " << n << ", stored entries = " << nnz << " ("
            << seconds << " s on " << ParallelSession::ranks()
            << " rank(s); peak memory per rank, MB:";
  for (const double mb : peak) std::cerr << ' ' << std::lround(mb);
  std::cerr << ")\n";
}

}  // namespace

void add_convert_command(CLI::App& app) {
  static ConvertFlags f;
  add_convert_options(app, f, [] { run(f); });
}

}  // namespace hmfnet::cli

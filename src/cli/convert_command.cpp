// `hmfnet convert IN -o OUT.h5`: a network file to hmfnet HDF5, the format every rank reads by
// row blocks, so a large text network is parsed once (docs/scaling.md). The text is parsed in
// parallel (parallel/distributed_text_read.hpp) and the rows written without gathering them
// (parallel/distributed_network_file.hpp): the file is the same for any rank count and equals
// what `write_network` writes for the serial read. `--partition P` renumbers the nodes so that
// the P parts of a Zoltan2 partition (PHG) are contiguous row blocks
// (parallel/graph_partition.hpp), recording the old indices in /network/original_index.
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numeric>

#include "app/provenance.hpp"
#include "cli/command_options.hpp"
#include "cli/commands.hpp"
#include "cli/read_flags.hpp"
#include "core/atomic_file.hpp"
#include "core/distinct_files.hpp"
#include "core/error.hpp"
#include "io/network_file.hpp"
#include "network/node_ordering.hpp"
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
  return inverse_permutation(order.new_index);
}

// The band of the whole network under `new_index` (the largest over the ranks' blocks).
double global_bandwidth(const RowBlock& block, const std::vector<NodeIndex>& new_index) {
  return ParallelSession::max(static_cast<double>(bandwidth(block, new_index)));
}

// Renumbers `block` in the order `order` (reverse Cuthill-McKee, or by stored entries); records
// the band before and after in `parameters`; returns the original index of each new node.
std::vector<NodeIndex> order_and_renumber(RowBlock& block, NodeOrder order,
                                          nlohmann::json& parameters) {
  std::vector<NodeIndex> identity(static_cast<std::size_t>(block.n));
  std::iota(identity.begin(), identity.end(), NodeIndex{0});
  std::vector<NodeIndex> new_index;
  if (order == NodeOrder::rcm) {
    if (ParallelSession::ranks() > 1) {
      throw ParameterError("--order",
                           "rcm on " + std::to_string(ParallelSession::ranks()) + " ranks",
                           "one rank (the breadth-first search runs over the whole network)");
    }
    new_index = reverse_cuthill_mckee(block);
  } else {
    std::vector<double> entries(static_cast<std::size_t>(block.n), 0.0);
    for (NodeIndex r = 0; r < block.rows(); ++r) {
      entries[static_cast<std::size_t>(block.first_row) + static_cast<std::size_t>(r)] =
          static_cast<double>(block.row_ptr[static_cast<std::size_t>(r) + 1] -
                              block.row_ptr[static_cast<std::size_t>(r)]);
    }
    ParallelSession::sum_in_place(entries);
    new_index = degree_order(entries);
  }
  const double before = global_bandwidth(block, identity);
  const double after = global_bandwidth(block, new_index);
  parameters["bandwidth_before"] = before;
  parameters["bandwidth_after"] = after;
  if (is_root())
    std::cerr << "order " << name_of(order) << ": bandwidth " << before << " -> " << after << "\n";
  block = renumber_rows(block, new_index);
  return inverse_permutation(new_index);
}

void run(const ConvertFlags& f) {
  if (format_from_extension(f.output) != NetworkFormat::hdf5) {
    throw InputError(f.output, 0,
                     "convert writes hmfnet HDF5 (.h5/.hdf5), the format the ranks read by row "
                     "blocks");
  }
  require_writable_destination(f.output);
  require_distinct_files({{"input", f.input}}, {{"--output", f.output}});
  const auto start = std::chrono::steady_clock::now();
  DistributedRows rows = f.read.read_distributed_rows(f.input);
  nlohmann::json parameters{
      {"input", f.input}, {"partition", f.partition}, {"seed", f.seed}, {"order", f.order}};
  std::vector<NodeIndex> original_index;
  if (f.partition > 0 && rows.complete) {
    throw InputError(f.input, 0,
                     "the complete graph is held implicitly: it has no rows to partition");
  }
  const NodeOrder order = parse_node_order(f.order, "--order");
  if (order != NodeOrder::original && rows.complete) {
    throw InputError(f.input, 0, "the complete graph is held implicitly: it has no rows to order");
  }
  if (f.partition > 0) {
    original_index = partition_and_renumber(rows.block, f.partition, f.seed, parameters);
  } else if (order != NodeOrder::original) {
    original_index = order_and_renumber(rows.block, order, parameters);
  }
  const std::string record = app::provenance("convert", parameters);
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

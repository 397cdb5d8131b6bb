#include "app/network_conversion.hpp"

#include <chrono>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>

#include "app/provenance.hpp"
#include "core/atomic_file.hpp"
#include "core/distinct_files.hpp"
#include "core/error.hpp"
#include "io/network_file.hpp"
#include "network/node_ordering.hpp"
#include "parallel/distributed_network_file.hpp"
#include "parallel/graph_partition.hpp"
#include "parallel/node_renumbering.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet::app {

namespace {

// Renumbers `block` so that the parts Zoltan2 finds are contiguous; records the cut in
// `parameters` and returns the original index of each new node (for rank 0 to write).
std::vector<NodeIndex> partition_and_renumber(RowBlock& block, int parts, std::uint64_t seed,
                                              nlohmann::json& parameters,
                                              std::vector<std::string>& notes) {
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
  std::ostringstream note;
  note << "partition into " << parts << " parts: " << cut << " of " << total[0]
       << " stored entries cut (" << static_cast<double>(cut) / static_cast<double>(total[0])
       << ")";
  notes.push_back(note.str());
  return inverse_permutation(order.new_index);
}

// The band of the whole network under `new_index` (the largest over the ranks' blocks).
double global_bandwidth(const RowBlock& block, const std::vector<NodeIndex>& new_index) {
  return ParallelSession::max(static_cast<double>(bandwidth(block, new_index)));
}

// Renumbers `block` in the order `order` (reverse Cuthill-McKee, or by stored entries); records
// the band before and after in `parameters`; returns the original index of each new node.
std::vector<NodeIndex> order_and_renumber(RowBlock& block, NodeOrder order,
                                          nlohmann::json& parameters,
                                          std::vector<std::string>& notes) {
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
  std::ostringstream note;
  note << "order " << name_of(order) << ": bandwidth " << before << " -> " << after;
  notes.push_back(note.str());
  block = renumber_rows(block, new_index);
  return inverse_permutation(new_index);
}

}  // namespace

void check_convert(const ConvertRequest& r) {
  validate(r);
  if (format_from_extension(r.output) != NetworkFormat::hdf5) {
    throw InputError(r.output, 0,
                     "convert writes hmfnet HDF5 (.h5/.hdf5), the format the ranks read by row "
                     "blocks");
  }
  require_writable_destination(r.output);
  require_distinct_files({{"input", r.input}}, {{"--output", r.output}});
}

ConvertedFile convert(const ConvertRequest& r, DistributedRows rows) {
  check_convert(r);
  const auto start = std::chrono::steady_clock::now();
  nlohmann::json parameters{
      {"input", r.input}, {"partition", r.partition}, {"seed", r.seed}, {"order", r.order}};
  ConvertedFile file;
  std::vector<NodeIndex> original_index;
  if (r.partition > 0 && rows.complete) {
    throw InputError(r.input, 0,
                     "the complete graph is held implicitly: it has no rows to partition");
  }
  const NodeOrder order = parse_node_order(r.order, "--order");
  if (order != NodeOrder::original && rows.complete) {
    throw InputError(r.input, 0, "the complete graph is held implicitly: it has no rows to order");
  }
  if (r.partition > 0) {
    original_index =
        partition_and_renumber(rows.block, r.partition, r.seed, parameters, file.notes);
  } else if (order != NodeOrder::original) {
    original_index = order_and_renumber(rows.block, order, parameters, file.notes);
  }
  const std::string record = provenance("convert", parameters);
  if (rows.complete) {
    ParallelSession::agree([&] {
      if (ParallelSession::rank() == 0) write_complete_graph(r.output, *rows.complete, record);
    });
    file.nnz = rows.complete->nnz();
  } else {
    std::vector<std::uint64_t> total{static_cast<std::uint64_t>(rows.block.nnz())};
    ParallelSession::sum_in_place(total);
    file.nnz = static_cast<EdgeOffset>(total[0]);
    write_distributed_network_hdf5(r.output, rows.block, record, original_index);
  }
  file.n = rows.complete ? rows.complete->n : rows.block.n;
  file.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  file.ranks = ParallelSession::ranks();
  file.peak_rss_mb_per_rank = ParallelSession::peak_memory_mb();  // collective
  return file;
}

}  // namespace hmfnet::app

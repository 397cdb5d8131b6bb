#include "parallel/graph_partition.hpp"

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsGraph.hpp>
#include <Zoltan2_PartitioningProblem.hpp>
#include <Zoltan2_XpetraCrsGraphAdapter.hpp>
#include <string>

#include "core/error.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

using Graph = Tpetra::CrsGraph<>;
using GlobalIndex = Graph::global_ordinal_type;
using Adapter = Zoltan2::XpetraCrsGraphAdapter<Graph>;

std::size_t at(std::int64_t k) { return static_cast<std::size_t>(k); }

// The rows held here as a Tpetra graph on the contiguous row map (what Zoltan2's adapter takes).
Teuchos::RCP<const Graph> tpetra_graph(const RowBlock& block) {
  const auto comm = Tpetra::getDefaultComm();
  const auto rows = Teuchos::rcp(
      new Tpetra::Map<>(static_cast<Tpetra::global_size_t>(block.n), at(block.rows()), 0, comm));
  std::vector<std::size_t> per_row(at(block.rows()));
  for (NodeIndex r = 0; r < block.rows(); ++r)
    per_row[at(r)] = at(block.row_ptr[at(r) + 1] - block.row_ptr[at(r)]);
  auto graph = Teuchos::rcp(new Graph(rows, Teuchos::ArrayView<const std::size_t>(per_row)));
  std::vector<GlobalIndex> cols;
  for (NodeIndex r = 0; r < block.rows(); ++r) {
    cols.assign(block.cols.begin() + block.row_ptr[at(r)],
                block.cols.begin() + block.row_ptr[at(r) + 1]);
    graph->insertGlobalIndices(block.first_row + r, Teuchos::ArrayView<const GlobalIndex>(cols));
  }
  graph->fillComplete();
  return graph;
}

}  // namespace

std::vector<int> partition_rows(const RowBlock& block, int parts, std::uint64_t seed) {
  if (parts < 1) throw ParameterError("parts", std::to_string(parts), ">= 1");
  std::vector<int> part(at(block.rows()), 0);
  if (parts == 1) return part;
  // Collective itself (the map, fillComplete): not inside agree, which must see every rank.
  const Teuchos::RCP<const Graph> graph = tpetra_graph(block);
  Adapter adapter(graph, 1, 0);
  // A node's work is its stored entries (one more, so that isolated nodes are placed too).
  std::vector<double> work(at(block.rows()));
  for (NodeIndex r = 0; r < block.rows(); ++r)
    work[at(r)] = 1.0 + static_cast<double>(block.row_ptr[at(r) + 1] - block.row_ptr[at(r)]);
  adapter.setVertexWeights(work.data(), 1, 0);
  Teuchos::ParameterList params;
  params.set("algorithm", "phg");
  params.set("num_global_parts", parts);
  // Zoltan prints its parameters unless told not to, and seeds its generator from SEED on every
  // call (left alone, two calls on the same input gave different parts).
  Teuchos::ParameterList& zoltan = params.sublist("zoltan_parameters");
  zoltan.set("DEBUG_LEVEL", std::string("0"));
  zoltan.set("SEED", std::to_string(seed % 2147483647));
  Zoltan2::PartitioningProblem<Adapter> problem(&adapter, &params, Tpetra::getDefaultComm());
  problem.solve();
  const int* list = problem.getSolution().getPartListView();
  ParallelSession::agree([&] {
    for (NodeIndex r = 0; r < block.rows(); ++r) {
      part[at(r)] = list[r];
      if (list[r] < 0 || list[r] >= parts) {
        throw std::logic_error("Zoltan2 put row " + std::to_string(block.first_row + r) +
                               " in part " + std::to_string(list[r]) + " of " +
                               std::to_string(parts));
      }
    }
  });
  return part;
}

}  // namespace hmfnet

#include "parallel/distributed_network.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <algorithm>
#include <utility>

#include "core/error.hpp"
#include "core/index_cast.hpp"
#include "parallel/distributed_network_impl.hpp"

namespace hmfnet {

namespace {

const DistributedNetwork::Impl& require_rows(const DistributedNetwork::Impl& impl,
                                             const char* what) {
  if (!impl.stores_rows) {
    throw ParameterError(what, "the complete graph, held without stored rows",
                         "a network with stored rows (K_N: the rank-one force and the closed "
                         "forms of network/complete_graph.hpp)");
  }
  return impl;
}

// The stored rows with their column indices, which release_columns may have given away.
const DistributedNetwork::Impl& require_columns(const DistributedNetwork::Impl& impl,
                                                const char* what) {
  if (require_rows(impl, what).columns_released) {
    throw ParameterError(what, "the network's column indices were given to the sparse force",
                         "a network whose column indices were not released (release_columns)");
  }
  return impl;
}

template <class T>
T sum_over_ranks(const Teuchos::Comm<int>& comm, T local) {
  T global{};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

// The blocks must tile [0, n) in rank order: this rank's first row is the sum of the rows of
// the ranks before it. Checked on every rank, refused on every rank.
void require_tiling(const Teuchos::Comm<int>& comm, const RowBlock& block) {
  const auto rows = static_cast<long long>(block.rows());
  long long through_here = 0;
  Teuchos::scan(comm, Teuchos::REDUCE_SUM, rows, Teuchos::outArg(through_here));
  const long long total = sum_over_ranks(comm, rows);
  const int here_ok = (through_here - rows == block.first_row && total == block.n) ? 1 : 0;
  int all_ok = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, here_ok, Teuchos::outArg(all_ok));
  if (all_ok == 0) {
    throw ParameterError(
        "row blocks", "not contiguous in rank order over all " + std::to_string(block.n) + " nodes",
        "rank r holds the rows after those of ranks 0..r-1");
  }
}

// The column space (own rows and every referenced node, ascending global order) and the block's
// columns renumbered into it in place; O(N) scratch of 4 bytes per node, no copy of the entries.
std::vector<GlobalOrdinal> renumber_columns(RowBlock& block) {
  std::vector<NodeIndex> local_of(idx(block.n), -1);
  for (NodeIndex r = 0; r < block.rows(); ++r) local_of[idx(block.first_row + r)] = 0;
  for (const NodeIndex j : block.cols) local_of[idx(j)] = 0;
  std::vector<GlobalOrdinal> gids;
  for (NodeIndex i = 0; i < block.n; ++i) {
    if (local_of[idx(i)] < 0) continue;
    local_of[idx(i)] = static_cast<NodeIndex>(gids.size());
    gids.push_back(i);
  }
  for (NodeIndex& j : block.cols) j = local_of[idx(j)];
  return gids;
}

Teuchos::RCP<const TpetraMap> row_map(NodeIndex n, NodeIndex local_rows) {
  return Teuchos::rcp(new TpetraMap(static_cast<Tpetra::global_size_t>(n),
                                    static_cast<size_t>(local_rows), 0, Tpetra::getDefaultComm()));
}

// A's products for Anasazi: each row summed in ascending global column order (so a product
// does not depend on the rank count), rows shared among threads (each row's sum stays serial, so
// neither does it depend on the thread count).
class AdjacencyOperator final : public TpetraOperator {
 public:
  explicit AdjacencyOperator(const DistributedNetwork::Impl& impl) : m_impl(impl) {}
  Teuchos::RCP<const TpetraMap> getDomainMap() const override { return m_impl.map; }
  Teuchos::RCP<const TpetraMap> getRangeMap() const override { return m_impl.map; }
  bool hasTransposeApply() const override { return true; }  // A is symmetric

  void apply(const TpetraMultiVector& X, TpetraMultiVector& Y, Teuchos::ETransp /*mode*/,
             double alpha, double beta) const override {
    require_columns(m_impl, "the adjacency operator");  // one made before release_columns
    const size_t width = X.getNumVectors();
    if (!X.isConstantStride() || !Y.isConstantStride()) {
      // A view of chosen columns: the host view below would index the parent's columns, so
      // take one vector (constant stride) at a time.
      for (size_t v = 0; v < width; ++v) {
        apply(*X.getVector(v), *Y.getVectorNonConst(v), Teuchos::NO_TRANS, alpha, beta);
      }
      return;
    }
    const TpetraMultiVector* source = &X;
    if (!m_impl.identity_import) {
      if (m_columns.is_null() || m_columns->getNumVectors() != width) {
        m_columns = Teuchos::rcp(new TpetraMultiVector(m_impl.column_map, width));
      }
      m_columns->doImport(X, *m_impl.row_to_columns, Tpetra::INSERT);
      source = m_columns.get();
    }
    const auto x = source->getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto y = Y.getLocalViewHost(Tpetra::Access::ReadWrite);  // read only when beta != 0
    const auto& a = m_impl.adjacency;
    const auto rows = static_cast<std::ptrdiff_t>(a.row_ptr.size()) - 1;
    const bool weighted = !a.weights.empty();
#pragma omp parallel for schedule(static) if (a.cols.size() > (std::size_t{1} << 16))
    for (std::ptrdiff_t r = 0; r < rows; ++r) {
      for (size_t v = 0; v < width; ++v) {
        double s = 0.0;
        for (auto k = static_cast<std::size_t>(a.row_ptr[static_cast<std::size_t>(r)]);
             k < static_cast<std::size_t>(a.row_ptr[static_cast<std::size_t>(r) + 1]); ++k) {
          const double xj = x(static_cast<size_t>(a.cols[k]), v);
          s += weighted ? a.weights[k] * xj : xj;
        }
        y(static_cast<size_t>(r), v) =
            beta == 0.0 ? alpha * s : alpha * s + beta * y(static_cast<size_t>(r), v);
      }
    }
  }

 private:
  const DistributedNetwork::Impl& m_impl;
  mutable Teuchos::RCP<TpetraMultiVector> m_columns;  // reused while the width stays
};

}  // namespace

DistributedNetwork::DistributedNetwork(const Network& network)
    : DistributedNetwork([&network] {
        const auto starts =
            balanced_row_starts(network.row_ptr(), Tpetra::getDefaultComm()->getSize());
        const auto p = static_cast<std::size_t>(Tpetra::getDefaultComm()->getRank());
        return slice_rows(network, starts[p], starts[p + 1] - starts[p]);
      }()) {}

DistributedNetwork::DistributedNetwork(RowBlock block) : m_impl(std::make_unique<Impl>()) {
  const auto comm = Tpetra::getDefaultComm();
  require_tiling(*comm, block);
  Impl& impl = *m_impl;
  impl.stores_rows = true;
  impl.first_row = block.first_row;
  impl.map = row_map(block.n, block.rows());
  impl.nnz = sum_over_ranks(*comm, static_cast<long long>(block.nnz()));
  impl.self_loops = sum_over_ranks(*comm, static_cast<long long>(block.self_loops()));
  impl.weighted = sum_over_ranks(*comm, block.weighted() ? 1 : 0) > 0;
  const std::vector<GlobalOrdinal> gids = renumber_columns(block);
  impl.column_map = Teuchos::rcp(new TpetraMap(
      Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
      Teuchos::ArrayView<const GlobalOrdinal>(gids.data(), static_cast<int>(gids.size())), 0,
      comm));
  impl.row_to_columns = Teuchos::rcp(new TpetraImport(impl.map, impl.column_map));
  // The column space starts with the own rows only when nothing else is referenced (ascending
  // order puts lower-ranked ghosts first otherwise).
  const int mine = gids.size() == idx(block.rows()) ? 1 : 0;
  int everywhere = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(everywhere));
  impl.identity_import = everywhere == 1;
  impl.adjacency.columns = static_cast<NodeIndex>(gids.size());
  impl.adjacency.row_ptr = std::move(block.row_ptr);
  impl.adjacency.cols = std::move(block.cols);
  impl.adjacency.weights = std::move(block.weights);
}

DistributedNetwork::DistributedNetwork(const CompleteGraph& graph)
    : m_impl(std::make_unique<Impl>()) {
  const auto comm = Tpetra::getDefaultComm();
  const auto per_row = static_cast<EdgeOffset>(graph.degree());
  const auto starts =
      balanced_row_starts(graph.n, comm->getSize(), [per_row](NodeIndex i) { return per_row * i; });
  const auto p = static_cast<std::size_t>(comm->getRank());
  m_impl->first_row = starts[p];
  m_impl->map = row_map(graph.n, starts[p + 1] - starts[p]);
  m_impl->nnz = graph.nnz();
  m_impl->self_loops = graph.self_loops ? graph.n : 0;
}

DistributedNetwork::~DistributedNetwork() = default;

const DistributedNetwork::Impl& tpetra_impl(const DistributedNetwork& network) {
  return *network.m_impl;
}

Teuchos::RCP<const TpetraOperator> adjacency_operator(const DistributedNetwork& network) {
  const auto& impl = require_columns(tpetra_impl(network), "the adjacency operator");
  if (impl.op.is_null()) impl.op = Teuchos::rcp(new AdjacencyOperator(impl));
  return impl.op;
}

NodeIndex DistributedNetwork::global_size() const {
  return static_cast<NodeIndex>(m_impl->map->getGlobalNumElements());
}

NodeIndex DistributedNetwork::local_size() const {
  return static_cast<NodeIndex>(m_impl->map->getNodeNumElements());
}

NodeIndex DistributedNetwork::first_row() const { return m_impl->first_row; }

EdgeOffset DistributedNetwork::global_nnz() const { return m_impl->nnz; }

bool DistributedNetwork::stores_rows() const { return m_impl->stores_rows; }

bool DistributedNetwork::weighted() const { return m_impl->weighted; }

EdgeOffset DistributedNetwork::global_self_loops() const { return m_impl->self_loops; }

NodeIndex DistributedNetwork::ghost_count() const {
  if (!stores_rows()) return 0;
  return m_impl->adjacency.columns - local_size();
}

std::vector<double> DistributedNetwork::local_degrees() const {
  const auto& a = require_rows(*m_impl, "DistributedNetwork::local_degrees").adjacency;
  std::vector<double> d(a.row_ptr.size() - 1, 0.0);
  for (std::size_t r = 0; r < d.size(); ++r) {
    const auto b = static_cast<std::size_t>(a.row_ptr[r]);
    const auto e = static_cast<std::size_t>(a.row_ptr[r + 1]);
    if (a.weights.empty()) {
      d[r] = static_cast<double>(e - b);
      continue;
    }
    for (std::size_t k = b; k < e; ++k) d[r] += a.weights[k];
  }
  return d;
}

void DistributedNetwork::apply(const std::vector<double>& x_local,
                               std::vector<double>& y_local) const {
  const auto op = adjacency_operator(*this);
  TpetraMultiVector x(m_impl->map, 1), y(m_impl->map, 1);
  {
    auto xv = x.getDataNonConst(0);
    std::copy(x_local.begin(), x_local.begin() + local_size(), xv.begin());
  }
  op->apply(x, y);
  const auto yv = y.getData(0);
  y_local.assign(yv.begin(), yv.end());
}

std::vector<double> DistributedNetwork::gather(const std::vector<double>& x_local) const {
  const auto n = static_cast<size_t>(global_size());
  std::vector<double> mine(n, 0.0), all(n, 0.0);
  const auto first = static_cast<size_t>(first_row());
  for (size_t r = 0; r < x_local.size(); ++r) mine[first + r] = x_local[r];
  // Blocks are disjoint, so a sum reduction assembles the vector exactly (x + 0 = x).
  Teuchos::reduceAll(*m_impl->map->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(n), mine.data(),
                     all.data());
  return all;
}

const DistributedNetwork::LocalAdjacency& DistributedNetwork::local_adjacency() const {
  return require_columns(*m_impl, "DistributedNetwork::local_adjacency").adjacency;
}

std::vector<NodeIndex> DistributedNetwork::release_columns() {
  auto& impl = *m_impl;
  require_columns(impl, "DistributedNetwork::release_columns");
  impl.columns_released = true;
  std::vector<NodeIndex> cols;
  cols.swap(impl.adjacency.cols);  // leaves the rows' cols empty, as documented
  return cols;
}

NodeIndex DistributedNetwork::global_column(NodeIndex c) const {
  return static_cast<NodeIndex>(
      require_rows(*m_impl, "DistributedNetwork::global_column").column_map->getGlobalElement(c));
}

std::vector<NodeIndex> DistributedNetwork::column_globals() const {
  const auto list =
      require_rows(*m_impl, "DistributedNetwork::column_globals").column_map->getNodeElementList();
  std::vector<NodeIndex> out;
  out.reserve(static_cast<std::size_t>(list.size()));
  for (const GlobalOrdinal g : list) out.push_back(static_cast<NodeIndex>(g));
  return out;
}

bool DistributedNetwork::columns_are_owned_rows() const {
  return require_rows(*m_impl, "DistributedNetwork::columns_are_owned_rows").identity_import;
}

void DistributedNetwork::import_columns(const double* owned, int width, double* columns) const {
  auto& impl = *m_impl;
  require_rows(impl, "DistributedNetwork::import_columns");
  const auto w = static_cast<size_t>(width);
  if (impl.import_source.is_null() || impl.import_source->getNumVectors() != w) {
    impl.import_source = Teuchos::rcp(new TpetraMultiVector(impl.map, w));
    impl.import_target = Teuchos::rcp(new TpetraMultiVector(impl.column_map, w));
  }
  TpetraMultiVector& source = *impl.import_source;
  TpetraMultiVector& target = *impl.import_target;
  const auto n_owned = static_cast<size_t>(local_size());
  {
    auto view = source.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t r = 0; r < n_owned; ++r)
      for (size_t c = 0; c < w; ++c) view(r, c) = owned[r * w + c];
  }
  target.doImport(source, *impl.row_to_columns, Tpetra::INSERT);
  const auto view = target.getLocalViewHost(Tpetra::Access::ReadOnly);
  const size_t n_columns = impl.column_map->getNodeNumElements();
  for (size_t r = 0; r < n_columns; ++r)
    for (size_t c = 0; c < w; ++c) columns[r * w + c] = view(r, c);
}

}  // namespace hmfnet

#pragma once
// Private: the Tpetra types behind DistributedNetwork. Include only from .cpp files that need
// Trilinos (each such translation unit costs ~15 s and ~0.6 GB to compile).
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include "parallel/distributed_network.hpp"

namespace hmfnet {

using TpetraMap = Tpetra::Map<>;
using TpetraMultiVector = Tpetra::MultiVector<double>;
using TpetraOperator = Tpetra::Operator<double>;
using GlobalOrdinal = TpetraMap::global_ordinal_type;
using LocalOrdinal = TpetraMap::local_ordinal_type;

using TpetraImport = Tpetra::Import<>;

struct DistributedNetwork::Impl {
  Teuchos::RCP<const TpetraMap> map;  ///< the row blocks
  bool stores_rows = false;           ///< false: the complete graph held implicitly
  NodeIndex first_row = 0;
  EdgeOffset nnz = 0;             ///< over all ranks (the complete graph's n (n - 1) [+ n])
  EdgeOffset self_loops = 0;      ///< over all ranks
  bool weighted = false;          ///< over all ranks
  LocalAdjacency adjacency;       ///< this rank's rows, columns in the column space
  bool columns_released = false;  ///< adjacency.cols given away (release_columns)
  Teuchos::RCP<const TpetraMap> column_map;         ///< ascending global order
  Teuchos::RCP<const TpetraImport> row_to_columns;  ///< rows -> column space
  bool identity_import = false;                     ///< every rank's column space is its own rows
  mutable Teuchos::RCP<const TpetraOperator> op;    ///< A as a Tpetra operator (on first use)
  // Reused across steps (allocated again only when the width changes).
  Teuchos::RCP<TpetraMultiVector> import_source, import_target;
};

/// A as a Tpetra::Operator on the row map (for Anasazi): Y = alpha A X + beta Y on the stored
/// rows, the ghost values of X imported first. Built once per network.
Teuchos::RCP<const TpetraOperator> adjacency_operator(const DistributedNetwork& network);

/// The Tpetra map and rows behind a DistributedNetwork, for the Trilinos code that needs them
/// (spectral/perron.cpp hands adjacency_operator to Anasazi).
const DistributedNetwork::Impl& tpetra_impl(const DistributedNetwork& network);

}  // namespace hmfnet

#pragma once
// Private: the Tpetra types behind DistributedNetwork. Include only from .cpp files that need
// Trilinos (each such translation unit costs ~15 s and ~0.6 GB to compile).
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include "parallel/distributed_network.hpp"

namespace hmfnet {

using TpetraMap = Tpetra::Map<>;
using TpetraMatrix = Tpetra::CrsMatrix<double>;
using TpetraMultiVector = Tpetra::MultiVector<double>;
using TpetraOperator = Tpetra::Operator<double>;
using GlobalOrdinal = TpetraMap::global_ordinal_type;
using LocalOrdinal = TpetraMap::local_ordinal_type;

using TpetraImport = Tpetra::Import<>;

struct DistributedNetwork::Impl {
  Teuchos::RCP<const TpetraMap> map;
  Teuchos::RCP<TpetraMatrix> matrix;  ///< null for the complete graph held implicitly
  EdgeOffset implicit_nnz = 0;        ///< the complete graph's n (n - 1) [+ n]
  bool weighted = false;
  Teuchos::RCP<const TpetraImport> row_to_columns;  // built on first import_columns
  // Reused across steps (allocated again only when the width changes).
  Teuchos::RCP<TpetraMultiVector> import_source, import_target;
};

/// The Tpetra matrix and map behind a DistributedNetwork, for the Trilinos code that needs them
/// (spectral/perron.cpp hands the matrix to Anasazi).
const DistributedNetwork::Impl& tpetra_impl(const DistributedNetwork& network);

}  // namespace hmfnet

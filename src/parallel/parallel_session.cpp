#include "parallel/parallel_session.hpp"

#include <Tpetra_Core.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <string>
#include <vector>

namespace hmfnet {

namespace {

// Kokkos prints its own option list when it sees --help/-h; the CLI owns those, so Kokkos and
// MPI get a copy of the arguments without them.
std::vector<char*> without_help(int argc, char** argv) {
  std::vector<char*> kept;
  for (int k = 0; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg != "--help" && arg != "-h" && arg != "--help-all") kept.push_back(argv[k]);
  }
  kept.push_back(nullptr);
  return kept;
}

}  // namespace

struct ParallelSession::Guard {
  Guard(int argc, char** argv)
      : args(without_help(argc, argv)),
        count(static_cast<int>(args.size()) - 1),
        data(args.data()),
        scope(&count, &data) {}
  std::vector<char*> args;
  int count;
  char** data;
  Tpetra::ScopeGuard scope;
};

ParallelSession::ParallelSession(int* argc, char*** argv)
    : m_guard(std::make_unique<Guard>(*argc, *argv)) {}

ParallelSession::~ParallelSession() = default;

int ParallelSession::rank() { return Tpetra::getDefaultComm()->getRank(); }

int ParallelSession::ranks() { return Tpetra::getDefaultComm()->getSize(); }

double ParallelSession::sum(double local) {
  double global = 0.0;
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_SUM, local,
                     Teuchos::outArg(global));
  return global;
}

double ParallelSession::max(double local) {
  double global = 0.0;
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_MAX, local,
                     Teuchos::outArg(global));
  return global;
}

}  // namespace hmfnet

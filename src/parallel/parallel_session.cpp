#include "parallel/parallel_session.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <string>
#include <vector>

namespace hmfnet {

namespace {

// Kokkos reads options of its own from the command line (--help, --threads, --numa, --device,
// --kokkos-*) and aborts on forms it dislikes ("--threads 2"); those names belong to our CLI, so
// Kokkos and MPI get the program name only.
std::vector<char*> program_name_only(int argc, char** argv) {
  std::vector<char*> kept;
  if (argc > 0) kept.push_back(argv[0]);
  kept.push_back(nullptr);
  return kept;
}

}  // namespace

struct ParallelSession::Guard {
  Guard(int argc, char** argv)
      : args(program_name_only(argc, argv)),
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

void ParallelSession::sum_in_place(std::vector<double>& values) {
  if (values.empty() || ranks() == 1) return;
  std::vector<double> global(values.size());
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_SUM,
                     static_cast<int>(values.size()), values.data(), global.data());
  values.swap(global);
}

}  // namespace hmfnet

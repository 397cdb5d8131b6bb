#include "parallel/parallel_session.hpp"

#include <sys/resource.h>
#include <unistd.h>  // environ, gethostname

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <algorithm>
#include <array>
#include <cstdlib>
#include <exception>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
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

// Element-wise `op` over ranks, in one reduction; nothing to do on one rank.
void reduce_in_place(std::vector<double>& values, Teuchos::EReductionType op) {
  if (values.empty() || Tpetra::getDefaultComm()->getSize() == 1) return;
  std::vector<double> global(values.size());
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), op, static_cast<int>(values.size()), values.data(),
                     global.data());
  values.swap(global);
}

// Whether a launcher (mpirun, mpiexec, srun) started this process as one rank of a job: each of
// them sets one of these in the rank's environment (Open MPI, PMIx, PMI-1/2).
bool launched_as_rank() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

// A process started without a launcher is an MPI singleton. Open MPI 4 then starts a daemon for
// it, and its default messaging layer probes UCX for peers a singleton cannot have: `hmfnet
// --version` took 0.38 s, 0.07 s without both (Open MPI 4.1, Debian; the bare MPI_Init 0.38 s
// against 0.04 s), paid by every command and every Python session. Two MCA parameters, read
// from the environment at MPI_Init, skip both: an isolated singleton (no daemon; Open MPI 5 has
// no such parameter and starts none) and the ob1 messaging layer. A value the user set is kept.
constexpr std::array<std::pair<const char*, const char*>, 2> k_singleton_parameters{{
    {"OMPI_MCA_ess_singleton_isolated", "1"},
    {"OMPI_MCA_pml", "ob1"},
}};

// An isolated singleton is also kept out of the file system: every one names itself [0,1],0 and
// so shares one session directory, TMPDIR/ompi.HOST.UID/jf.0/1/0, and one ending removes jf.0
// while another creates it ("A call to mkdir was unable to create the desired directory": 6 of
// 300 `hmfnet --version` started 8 at a time, none with this parameter). With no daemon and no
// process it could spawn, it has no peer to share memory with. A singleton the user made
// non-isolated (to spawn: docs/commands.md) keeps its directory, which its daemon's children use.
constexpr std::pair<const char*, const char*> k_isolated_no_session_dirs{
    "OMPI_MCA_orte_create_session_dirs", "0"};

// Whether Open MPI reads the isolated-singleton parameter as true (its boolean spellings).
bool isolated_singleton() {
  const char* value = std::getenv(k_singleton_parameters[0].first);
  if (value == nullptr) return false;
  const std::string_view v(value);
  return v == "1" || v == "true" || v == "yes";
}

// The names of the environment's variables that Open MPI and PMIx read (OMPI_, OPAL_, PMIX_).
std::set<std::string> mpi_variable_names() {
  std::set<std::string> names;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string_view text(*entry);
    const std::string_view name = text.substr(0, text.find('='));
    for (const std::string_view prefix : {"OMPI_", "OPAL_", "PMIX_"}) {
      if (name.substr(0, prefix.size()) == prefix) names.emplace(name);
    }
  }
  return names;
}

// A singleton's MPI_Init: the parameters above set for it, and, when it ends, every Open MPI or
// PMIx variable that was not there before unset, the session's and those Open MPI writes for
// itself (OMPI_MCA_ess=singleton, OMPI_MCA_pmix=isolated, ...; read at MPI_Init only). Inherited,
// they broke the processes this one starts: an mpirun started from a Python session gave its
// ranks a singleton's settings, and they failed at start.
class SingletonEnvironment {
 public:
  SingletonEnvironment() : m_before(mpi_variable_names()) {
    for (const auto& [name, value] : k_singleton_parameters) {
      setenv(name, value, /*overwrite=*/0);
    }
    if (isolated_singleton()) {
      setenv(k_isolated_no_session_dirs.first, k_isolated_no_session_dirs.second, /*overwrite=*/0);
    }
  }
  ~SingletonEnvironment() {
    for (const std::string& name : mpi_variable_names()) {
      if (m_before.count(name) == 0) unsetenv(name.c_str());
    }
  }
  SingletonEnvironment(const SingletonEnvironment&) = delete;
  SingletonEnvironment& operator=(const SingletonEnvironment&) = delete;

 private:
  std::set<std::string> m_before;
};

bool g_started_by_launcher = false;

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

ParallelSession::ParallelSession(int* argc, char*** argv) {
  // Before MPI_Init: a singleton's start writes PMIX_RANK into the environment.
  g_started_by_launcher = launched_as_rank();
  std::optional<SingletonEnvironment> singleton;
  if (!g_started_by_launcher) singleton.emplace();
  m_guard = std::make_unique<Guard>(*argc, *argv);
}

bool ParallelSession::started_by_launcher() { return g_started_by_launcher; }

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

std::vector<std::int64_t> ParallelSession::all_gather(std::int64_t mine) {
  // One non-zero slot per rank: the sum modulo 2^64 is each rank's value, negative ones too.
  std::vector<std::uint64_t> slots(static_cast<std::size_t>(ranks()), 0);
  slots[static_cast<std::size_t>(rank())] = static_cast<std::uint64_t>(mine);
  sum_in_place(slots);
  std::vector<std::int64_t> values(slots.size());
  for (std::size_t p = 0; p < slots.size(); ++p) values[p] = static_cast<std::int64_t>(slots[p]);
  return values;
}

ParallelSession::MachineRanks ParallelSession::machine_ranks() {
  std::array<char, 256> host{};
  if (gethostname(host.data(), host.size() - 1) != 0) host[0] = '\0';
  // The host name's FNV-1a hash stands for it: one 64-bit value a rank in one all_gather.
  std::uint64_t hash = 14695981039346656037ULL;
  for (const char* c = host.data(); *c != '\0'; ++c) {
    hash = (hash ^ static_cast<unsigned char>(*c)) * 1099511628211ULL;
  }
  const std::vector<std::int64_t> hosts = all_gather(static_cast<std::int64_t>(hash));
  MachineRanks m;
  m.count = 0;
  for (std::size_t r = 0; r < hosts.size(); ++r) {
    if (hosts[r] != static_cast<std::int64_t>(hash)) continue;
    if (static_cast<int>(r) < rank()) ++m.index;
    ++m.count;
  }
  return m;
}

void ParallelSession::sum_in_place(std::vector<double>& values) {
  reduce_in_place(values, Teuchos::REDUCE_SUM);
}

void ParallelSession::max_in_place(std::vector<double>& values) {
  reduce_in_place(values, Teuchos::REDUCE_MAX);
}

void ParallelSession::sum_in_place(std::vector<std::uint64_t>& values) {
  if (values.empty() || ranks() == 1) return;
  static_assert(sizeof(unsigned long long) == sizeof(std::uint64_t));
  std::vector<unsigned long long> mine(values.size()), global(values.size());
  std::copy(values.begin(), values.end(), mine.begin());
  // Unsigned addition wraps: the sums are exact modulo 2^64 whatever the reduction order.
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_SUM,
                     static_cast<int>(values.size()), mine.data(), global.data());
  std::copy(global.begin(), global.end(), values.begin());
}

void ParallelSession::send(const std::vector<std::int64_t>& values, int destination) {
  const auto comm = Tpetra::getDefaultComm();
  const auto length = static_cast<long long>(values.size());
  Teuchos::send(*comm, length, destination);
  std::vector<long long> data(values.begin(), values.end());
  if (length > 0) Teuchos::send(*comm, static_cast<int>(length), data.data(), destination);
}

std::vector<std::int64_t> ParallelSession::receive(int source) {
  const auto comm = Tpetra::getDefaultComm();
  long long length = 0;
  Teuchos::receive(*comm, source, &length);
  std::vector<long long> data(static_cast<std::size_t>(length));
  if (length > 0) Teuchos::receive(*comm, source, static_cast<int>(length), data.data());
  return std::vector<std::int64_t>(data.begin(), data.end());
}

void ParallelSession::broadcast(std::vector<std::int64_t>& values, int root) {
  const auto comm = Tpetra::getDefaultComm();
  auto length = static_cast<long long>(values.size());
  Teuchos::broadcast(*comm, root, Teuchos::outArg(length));
  std::vector<long long> data(values.begin(), values.end());
  data.resize(static_cast<std::size_t>(length));
  if (length > 0) Teuchos::broadcast(*comm, root, static_cast<int>(length), data.data());
  values.assign(data.begin(), data.end());
}

void ParallelSession::broadcast(std::string& text, int root) {
  const auto comm = Tpetra::getDefaultComm();
  int length = static_cast<int>(text.size());
  Teuchos::broadcast(*comm, root, Teuchos::outArg(length));
  text.resize(static_cast<std::size_t>(length));
  if (length > 0) Teuchos::broadcast(*comm, root, length, text.data());
}

void ParallelSession::barrier() { Tpetra::getDefaultComm()->barrier(); }

double ParallelSession::own_peak_memory_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // KB
}

std::vector<double> ParallelSession::peak_memory_mb() {
  std::vector<double> mb(static_cast<std::size_t>(ranks()), 0.0);
  mb[static_cast<std::size_t>(rank())] = own_peak_memory_mb();
  sum_in_place(mb);
  return mb;
}

void ParallelSession::agree(const std::function<void()>& step) {
  std::string message;
  bool failed = false;
  try {
    step();
  } catch (const std::exception& e) {
    message = e.what();
    failed = true;
  }
  const auto comm = Tpetra::getDefaultComm();
  const int mine = failed ? comm->getRank() : comm->getSize();
  int first = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  if (first == comm->getSize()) return;
  int length = static_cast<int>(message.size());
  Teuchos::broadcast(*comm, first, Teuchos::outArg(length));
  std::vector<char> text(message.begin(), message.end());
  text.resize(static_cast<std::size_t>(length));
  if (length > 0) Teuchos::broadcast(*comm, first, length, text.data());
  std::string shared(text.begin(), text.end());
  if (comm->getSize() > 1) shared += " (on rank " + std::to_string(first) + ")";
  throw CollectiveError(shared, first);
}

}  // namespace hmfnet

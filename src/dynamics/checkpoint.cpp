#include "dynamics/checkpoint.hpp"

#include <cstdio>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "dynamics/run_file.hpp"
#include "io/hdf5_file.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

// 2: checksum; 3: measured frame; 4: the fields of segment_state.hpp's lists, named in the file
// (count_fields, real_fields, array_fields), node statistics carry their frame frequency;
// 5: the fingerprint holds the network's content hash and the force (kernel and precision).
constexpr std::int64_t k_checkpoint_version = 5;

std::size_t columns_of(int width, int replicas) {
  return static_cast<std::size_t>(width > 0 ? width : replicas);
}

// Segment and position -> record (collective: rows are gathered, additive sums reduced).
class Capture {
 public:
  Capture(CheckpointRecord& out, int replicas, const RowExchange& exchange)
      : m_out(out), m_replicas(replicas), m_exchange(exchange) {}

  void count(const std::string& name, std::int64_t x) { m_out.counts.emplace_back(name, x); }
  void real(const std::string& name, double x) { m_out.reals.emplace_back(name, x); }
  void replicated(const std::string& name, const std::vector<double>& v) {
    m_out.arrays.push_back({name, v, 1});
  }
  void rows(const std::string& name, const std::vector<double>& local, int width) {
    const std::size_t w = columns_of(width, m_replicas);
    // An accumulator not started yet is empty on every rank that has rows; all ranks must take
    // the same branch because gather is collective.
    const bool started = ParallelSession::max(local.empty() ? 0.0 : 1.0) > 0.0;
    m_out.arrays.push_back(
        {name, started ? m_exchange.gather(local, w) : std::vector<double>{}, w});
  }
  void batch_means(const std::string& name, const BatchMeans& b) {
    count(name + "_count", b.count());
    m_out.arrays.push_back({name + "_sums", b.sums(), static_cast<std::size_t>(b.width())});
  }
  void node_statistics(const std::string& name, const NodeStatistics& s) {
    rows(name + "_rows", s.row_state(), NodeStatistics::k_row_width);
    std::vector<double> globals = s.global_state();
    const auto shared = static_cast<std::ptrdiff_t>(NodeStatistics::k_shared_globals);
    std::vector<double> additive(globals.begin() + shared, globals.end());
    ParallelSession::sum_in_place(additive);
    std::copy(additive.begin(), additive.end(), globals.begin() + shared);
    replicated(name + "_globals", globals);
  }

 private:
  CheckpointRecord& m_out;
  int m_replicas;
  const RowExchange& m_exchange;
};

// Record -> segment and position (collective: rows are scattered). Every size is checked, so a
// record of another run shape is refused with the field's name.
class Restore {
 public:
  Restore(const CheckpointRecord& in, int replicas, const RowExchange& exchange)
      : m_in(in), m_replicas(replicas), m_exchange(exchange) {}

  void count(const std::string& name, std::int64_t& x) const { x = m_in.count(name); }
  void real(const std::string& name, double& x) const { x = m_in.real(name); }
  void replicated(const std::string& name, std::vector<double>& v) const {
    v = sized(name, static_cast<std::size_t>(m_replicas)).values;
  }
  void rows(const std::string& name, std::vector<double>& local, int width) const {
    const auto& a = m_in.array(name);
    if (a.columns != columns_of(width, m_replicas)) misfit(name, "has the wrong number of columns");
    local = a.values.empty() ? std::vector<double>{} : m_exchange.scatter(a.values, a.columns);
  }
  void batch_means(const std::string& name, BatchMeans& b) const {
    b.restore(m_in.count(name + "_count"), sized(name + "_sums", b.sums().size()).values);
  }
  void node_statistics(const std::string& name, NodeStatistics& s) const {
    std::vector<double> rows_state;
    rows(name + "_rows", rows_state, NodeStatistics::k_row_width);
    if (rows_state.size() != s.row_state().size()) misfit(name + "_rows", "does not fit this run");
    const auto& globals = sized(name + "_globals", s.global_state().size()).values;
    s.restore(std::move(rows_state), globals, ParallelSession::rank() == 0);
  }

 private:
  const CheckpointRecord::Array& sized(const std::string& name, std::size_t size) const {
    const auto& a = m_in.array(name);
    if (a.values.size() != size) {
      misfit(name, "has " + std::to_string(a.values.size()) + " values where this run has " +
                       std::to_string(size));
    }
    return a;
  }
  [[noreturn]] void misfit(const std::string& name, const std::string& cause) const {
    throw InputError(m_in.source, 0, "checkpoint field " + name + " " + cause);
  }

  const CheckpointRecord& m_in;
  int m_replicas;
  const RowExchange& m_exchange;
};

// FNV-1a (64 bit) over the bytes of everything a resume uses, in a fixed order: a bit flipped on
// disk (or a file truncated and padded) changes it, and the checkpoint is refused instead of
// silently continuing from a wrong state. Not cryptographic: it guards against accidents.
class Fnv1a {
 public:
  void add(const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k) m_hash = (m_hash ^ b[k]) * 0x100000001b3ULL;
  }
  void add(const std::string& s) {
    add_scalar(static_cast<std::uint64_t>(s.size()));
    add(s.data(), s.size());
  }
  void add(const std::vector<double>& v) {
    add_scalar(static_cast<std::uint64_t>(v.size()));
    add(v.data(), v.size() * sizeof(double));
  }
  template <class T>
  void add_scalar(T x) {
    add(&x, sizeof x);
  }
  std::string hex() const {
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(m_hash));
    return buffer;
  }

 private:
  std::uint64_t m_hash = 0xcbf29ce484222325ULL;
};

// Adds every result field to the hash: scalars as their bytes, strings and vectors with their
// length first (Fnv1a::add).
struct ChecksumFields {
  Fnv1a& hash;
  void scalar(const char*, double x) { hash.add_scalar(x); }
  void text(const char*, const std::string& s) { hash.add(s); }
  void per_replica(const char*, const std::vector<double>& v) { hash.add(v); }
  void per_node_replica(const char*, const std::vector<double>& v) { hash.add(v); }
  void node_vector(const char*, const std::vector<double>& v) { hash.add(v); }
  void per_record(const char*, const std::vector<double>& v) { hash.add(v); }
  void per_record_replica(const char*, const std::vector<double>& v) { hash.add(v); }
};

}  // namespace

std::string checkpoint_checksum(const Checkpoint& c) {
  Fnv1a h;
  h.add(c.fingerprint);
  h.add_scalar(static_cast<std::int64_t>(c.replicas));
  for (const auto& [name, x] : c.record.counts) {
    h.add(name);
    h.add_scalar(x);
  }
  for (const auto& [name, x] : c.record.reals) {
    h.add(name);
    h.add_scalar(x);
  }
  for (const auto& a : c.record.arrays) {
    h.add(a.name);
    h.add_scalar(static_cast<std::uint64_t>(a.columns));
    h.add(a.values);
  }
  // The results so far, field by field in their lists' order (point_result.hpp).
  ChecksumFields fields{h};
  for (const PointResult& pt : c.points) visit_point_fields(fields, pt);
  visit_series_fields(fields, c.series);
  return h.hex();
}

namespace {

template <class Pairs>
std::string joined_names(const Pairs& items) {
  std::string names;
  for (const auto& item : items) names += (names.empty() ? "" : "\n") + std::string(item.first);
  return names;
}

std::vector<std::string> split_names(const std::string& joined) {
  std::vector<std::string> names;
  std::istringstream in(joined);
  for (std::string line; std::getline(in, line);) names.push_back(line);
  return names;
}

}  // namespace

std::int64_t CheckpointRecord::count(const std::string& name) const {
  for (const auto& [n, x] : counts)
    if (n == name) return x;
  throw InputError(source, 0, "checkpoint lacks the field " + name);
}

double CheckpointRecord::real(const std::string& name) const {
  for (const auto& [n, x] : reals)
    if (n == name) return x;
  throw InputError(source, 0, "checkpoint lacks the field " + name);
}

const CheckpointRecord::Array& CheckpointRecord::array(const std::string& name) const {
  for (const auto& a : arrays)
    if (a.name == name) return a;
  throw InputError(source, 0, "checkpoint lacks the field " + name);
}

RowExchange row_exchange(const DistributedNetwork& network, const std::string& source) {
  const auto n = static_cast<std::size_t>(network.global_size());
  const auto first = static_cast<std::size_t>(network.first_row());
  const auto rows = static_cast<std::size_t>(network.local_size());
  RowExchange exchange;
  exchange.gather = [&network, n, rows](const std::vector<double>& local, std::size_t width) {
    std::vector<double> global(n * width), column(rows);
    for (std::size_t b = 0; b < width; ++b) {
      for (std::size_t r = 0; r < rows; ++r) column[r] = local[r * width + b];
      const std::vector<double> all = network.gather(column);
      for (std::size_t i = 0; i < n; ++i) global[i * width + b] = all[i];
    }
    return global;
  };
  exchange.scatter = [n, first, rows, source](const std::vector<double>& global,
                                              std::size_t width) {
    if (global.size() != n * width) {
      throw InputError(source, 0,
                       "checkpoint arrays do not fit this network (" +
                           std::to_string(global.size()) + " values for " + std::to_string(n) +
                           " nodes x " + std::to_string(width) + ")");
    }
    const auto begin = global.begin() + static_cast<std::ptrdiff_t>(first * width);
    return std::vector<double>(begin, begin + static_cast<std::ptrdiff_t>(rows * width));
  };
  return exchange;
}

CheckpointRecord capture(const RunPosition& position, const SegmentState& segment, int replicas,
                         const RowExchange& exchange) {
  CheckpointRecord record;
  Capture visitor(record, replicas, exchange);
  visit_fields(position, segment, visitor);
  return record;
}

void restore(const CheckpointRecord& record, RunPosition& position, SegmentState& segment,
             int replicas, const RowExchange& exchange) {
  Restore visitor(record, replicas, exchange);
  visit_fields(position, segment, visitor);
}

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  AtomicFile out(path);
  {
    const Hdf5File f(out.temp_path(), Hdf5File::Mode::create);
    const hid_t root = f.id();
    f.set_attribute(root, "hmfnet_format", std::string("checkpoint"));
    f.set_attribute(root, "format_version", k_checkpoint_version);
    f.set_attribute(root, "fingerprint", c.fingerprint);
    f.set_attribute(root, "replicas", static_cast<std::int64_t>(c.replicas));
    f.set_attribute(root, "count_fields", joined_names(c.record.counts));
    f.set_attribute(root, "real_fields", joined_names(c.record.reals));
    std::vector<std::pair<std::string, int>> array_names;
    for (const auto& a : c.record.arrays) array_names.emplace_back(a.name, 0);
    f.set_attribute(root, "array_fields", joined_names(array_names));
    for (const auto& [name, x] : c.record.counts) f.set_attribute(root, name, x);
    for (const auto& [name, x] : c.record.reals) f.set_attribute(root, name, x);
    for (const auto& a : c.record.arrays) {
      if (a.columns == 0 || a.values.size() % a.columns != 0) {
        f.fail("checkpoint field " + a.name + " is not a whole number of rows");
      }
      f.write_matrix(root, a.name, a.values, a.values.size() / a.columns, a.columns);
    }
    write_results(f, c.points, c.series, c.replicas);
    f.set_attribute(root, "checksum", checkpoint_checksum(c));
    f.flush();
  }
  out.commit();
}

Checkpoint read_checkpoint(const std::string& path) {
  const Hdf5File f(path, Hdf5File::Mode::read);
  const hid_t root = f.id();
  if (!f.has_attribute(root, "hmfnet_format") ||
      f.string_attribute(root, "hmfnet_format") != "checkpoint") {
    f.fail("not an hmfnet checkpoint (attribute hmfnet_format != \"checkpoint\")");
  }
  const std::int64_t version = f.int_attribute(root, "format_version");
  if (version != k_checkpoint_version) {
    f.fail("checkpoint format version " + std::to_string(version) + " is not supported (this " +
           "hmfnet reads version " + std::to_string(k_checkpoint_version) +
           "): it was written by another hmfnet; remove it to start the run over, or finish the "
           "run with the hmfnet that wrote it");
  }
  Checkpoint c;
  c.fingerprint = f.string_attribute(root, "fingerprint");
  c.replicas = static_cast<int>(f.int_attribute(root, "replicas"));
  if (c.replicas < 1) f.fail("checkpoint has no replicas");
  c.record.source = path;
  for (const auto& name : split_names(f.string_attribute(root, "count_fields")))
    c.record.counts.emplace_back(name, f.int_attribute(root, name));
  for (const auto& name : split_names(f.string_attribute(root, "real_fields")))
    c.record.reals.emplace_back(name, f.double_attribute(root, name));
  for (const auto& name : split_names(f.string_attribute(root, "array_fields"))) {
    std::size_t rows = 0, cols = 0;
    std::vector<double> values = f.read_matrix(root, name, rows, cols);
    c.record.arrays.push_back({name, std::move(values), cols});
  }
  read_results(f, c.points, c.series, c.replicas);
  const std::string stored = f.string_attribute(root, "checksum"),
                    computed = checkpoint_checksum(c);
  if (stored != computed) {
    f.fail("checksum mismatch (stored " + stored + ", computed " + computed +
           "): the checkpoint is corrupted; remove it to start the run over");
  }
  return c;
}

}  // namespace hmfnet

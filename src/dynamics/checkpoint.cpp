#include "dynamics/checkpoint.hpp"

#include <cstdio>

#include "core/atomic_file.hpp"
#include "dynamics/run_file.hpp"
#include "io/hdf5_file.hpp"

namespace hmfnet {

namespace {

constexpr std::int64_t k_checkpoint_version = 3;  // 2: checksum; 3: measured frame

void write_vector(const Hdf5File& f, hid_t g, const std::string& name,
                  const std::vector<double>& v) {
  f.write(g, name, v);
}

// FNV-1a (64 bit) over the bytes of everything a resume uses, in a fixed order: a bit flipped on
// disk (or a file truncated and padded) changes it, and the checkpoint is refused instead of
// silently continuing from a wrong state. Not cryptographic: it guards against accidents.
class Fnv1a {
 public:
  void add(const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k) m_hash = (m_hash ^ b[k]) * 0x100000001b3ULL;
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

std::string checksum(const Checkpoint& c) {
  Fnv1a h;
  h.add(c.fingerprint.data(), c.fingerprint.size());
  h.add_scalar(static_cast<std::int64_t>(c.k_index));
  for (const std::int64_t x : {c.segment_step, c.steps_total, c.evaluations, c.batch_count,
                               static_cast<std::int64_t>(c.replicas)}) {
    h.add_scalar(x);
  }
  h.add_scalar(c.integration_seconds);
  for (const auto* v : {&c.theta, &c.p, &c.batch_sums, &c.energy0, &c.momentum0, &c.momentum_scale,
                        &c.energy_err_max, &c.momentum_drift_max, &c.theta_T1, &c.R_node_sum,
                        &c.node_rows, &c.node_globals}) {
    h.add(*v);
  }
  for (const PointResult& pt : c.points) {
    h.add_scalar(pt.K);
    for (const auto* v :
         {&pt.R_mean, &pt.R_sem, &pt.energy_rel_error_max, &pt.momentum_drift, &pt.R_node,
          &pt.omega_node, &pt.r_node, &pt.fluctuation, &pt.synchronised, &pt.phase_histogram,
          &pt.rotor_theta_bar, &pt.rotor_p_bar, &pt.psi_frequency, &pt.frame}) {
      h.add(*v);
    }
  }
  for (const auto* v :
       {&c.series.t, &c.series.K, &c.series.R, &c.series.energy, &c.series.momentum}) {
    h.add(*v);
  }
  return h.hex();
}

}  // namespace

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  AtomicFile out(path);
  {
    const Hdf5File f(out.temp_path(), Hdf5File::Mode::create);
    const hid_t root = f.id();
    f.set_attribute(root, "hmfnet_format", std::string("checkpoint"));
    f.set_attribute(root, "format_version", k_checkpoint_version);
    f.set_attribute(root, "fingerprint", c.fingerprint);
    f.set_attribute(root, "k_index", static_cast<std::int64_t>(c.k_index));
    f.set_attribute(root, "segment_step", c.segment_step);
    f.set_attribute(root, "steps_total", c.steps_total);
    f.set_attribute(root, "evaluations", c.evaluations);
    f.set_attribute(root, "integration_seconds", c.integration_seconds);
    f.set_attribute(root, "replicas", static_cast<std::int64_t>(c.replicas));
    f.set_attribute(root, "batch_count", c.batch_count);
    const auto w = static_cast<std::size_t>(c.replicas);
    f.write_matrix(root, "theta", c.theta, c.theta.size() / w, w);
    f.write_matrix(root, "p", c.p, c.p.size() / w, w);
    write_vector(f, root, "batch_sums", c.batch_sums);
    write_vector(f, root, "energy0", c.energy0);
    write_vector(f, root, "momentum0", c.momentum0);
    write_vector(f, root, "momentum_scale", c.momentum_scale);
    write_vector(f, root, "energy_err_max", c.energy_err_max);
    write_vector(f, root, "momentum_drift_max", c.momentum_drift_max);
    write_vector(f, root, "theta_T1", c.theta_T1);
    write_vector(f, root, "R_node_sum", c.R_node_sum);
    write_vector(f, root, "node_rows", c.node_rows);
    write_vector(f, root, "node_globals", c.node_globals);
    write_results(f, c.points, c.series, c.replicas);
    f.set_attribute(root, "checksum", checksum(c));
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
  if (f.int_attribute(root, "format_version") != k_checkpoint_version) {
    f.fail("checkpoint format version not supported");
  }
  Checkpoint c;
  c.fingerprint = f.string_attribute(root, "fingerprint");
  c.k_index = static_cast<int>(f.int_attribute(root, "k_index"));
  c.segment_step = f.int_attribute(root, "segment_step");
  c.steps_total = f.int_attribute(root, "steps_total");
  c.evaluations = f.int_attribute(root, "evaluations");
  c.integration_seconds = f.double_attribute(root, "integration_seconds");
  c.replicas = static_cast<int>(f.int_attribute(root, "replicas"));
  c.batch_count = f.int_attribute(root, "batch_count");
  std::size_t rows = 0, cols = 0;
  c.theta = f.read_matrix(root, "theta", rows, cols);
  if (cols != static_cast<std::size_t>(c.replicas))
    f.fail("theta has the wrong number of replicas");
  c.p = f.read_matrix(root, "p", rows, cols);
  c.batch_sums = f.read_double(root, "batch_sums");
  c.energy0 = f.read_double(root, "energy0");
  c.momentum0 = f.read_double(root, "momentum0");
  c.momentum_scale = f.read_double(root, "momentum_scale");
  c.energy_err_max = f.read_double(root, "energy_err_max");
  c.momentum_drift_max = f.read_double(root, "momentum_drift_max");
  c.theta_T1 = f.read_double(root, "theta_T1");
  c.R_node_sum = f.read_double(root, "R_node_sum");
  c.node_rows = f.read_double(root, "node_rows");
  c.node_globals = f.read_double(root, "node_globals");
  read_results(f, c.points, c.series, c.replicas);
  const std::string stored = f.string_attribute(root, "checksum"), computed = checksum(c);
  if (stored != computed) {
    f.fail("checksum mismatch (stored " + stored + ", computed " + computed +
           "): the checkpoint is corrupted; remove it to start the run over");
  }
  return c;
}

}  // namespace hmfnet

#include "dynamics/checkpoint.hpp"

#include "core/atomic_file.hpp"
#include "dynamics/run_file.hpp"
#include "io/hdf5_file.hpp"

namespace hmfnet {

namespace {

constexpr std::int64_t k_checkpoint_version = 1;

void write_vector(const Hdf5File& f, hid_t g, const std::string& name, const std::vector<double>& v) {
  f.write(g, name, v);
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
  if (cols != static_cast<std::size_t>(c.replicas)) f.fail("theta has the wrong number of replicas");
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
  return c;
}

}  // namespace hmfnet

#include "dynamics/run_file.hpp"

#include <algorithm>
#include <cmath>

#include "core/atomic_file.hpp"
#include "core/version.hpp"

namespace hmfnet {

namespace {

// A PointResult field over all points, in the order of visit_point_fields.
enum class FieldKind { scalar, text, per_replica, per_node_replica, node_vector };

struct Column {
  std::string name;
  FieldKind kind;
  std::vector<double> values;
  std::vector<std::string> strings;
};

// Stacks each field of the points it visits into its column, point after point. The columns are
// laid out from a default PointResult, so a run without points still writes every required one.
class Stacker {
 public:
  Stacker() {
    PointResult shape;
    visit_point_fields(*this, shape);
    m_declared = true;
  }
  void add(const PointResult& p) {
    m_next = 0;
    visit_point_fields(*this, p);
  }
  const std::vector<Column>& columns() const { return m_columns; }

  void scalar(const char* name, const double& x) { at(name, FieldKind::scalar, {x}); }
  void text(const char* name, const std::string& s) {
    Column& c = at(name, FieldKind::text, {});
    if (m_declared) c.strings.push_back(s);
  }
  void per_replica(const char* name, const std::vector<double>& v) {
    at(name, FieldKind::per_replica, v);
  }
  void per_node_replica(const char* name, const std::vector<double>& v) {
    at(name, FieldKind::per_node_replica, v);
  }
  void node_vector(const char* name, const std::vector<double>& v) {
    at(name, FieldKind::node_vector, v);
  }

 private:
  Column& at(const char* name, FieldKind kind, const std::vector<double>& values) {
    if (!m_declared) {
      m_columns.push_back({name, kind, {}, {}});
      return m_columns.back();
    }
    Column& c = m_columns[m_next++];
    c.values.insert(c.values.end(), values.begin(), values.end());
    return c;
  }
  std::vector<Column> m_columns;
  std::size_t m_next = 0;
  bool m_declared = false;
};

void write_column(const Hdf5File& f, hid_t group, const Column& c, std::size_t points,
                  std::size_t replicas) {
  switch (c.kind) {
    case FieldKind::scalar:
      f.write(group, c.name, c.values);
      return;
    case FieldKind::text:
      f.write_strings(group, c.name, c.strings);
      return;
    case FieldKind::per_replica:
      f.write_matrix(group, c.name, c.values, points, replicas);
      return;
    case FieldKind::per_node_replica:  // node data only: absent without it
      if (!c.values.empty()) {
        f.write_matrix(group, c.name, c.values, c.values.size() / replicas, replicas);
      }
      return;
    case FieldKind::node_vector:
      if (!c.values.empty()) {
        f.write_matrix(group, c.name, c.values, points, c.values.size() / points);
      }
      return;
  }
}

// Reads every column back (the node-data ones may be absent), then hands each point its share:
// one value, one string, or an equal slice of the column.
class Unstacker {
 public:
  Unstacker(const Hdf5File& f, hid_t group, std::size_t replicas)
      : m_file(f), m_group(group), m_replicas(replicas) {}

  std::vector<PointResult> points() {
    std::vector<PointResult> points(m_file.read_double(m_group, "K").size());
    m_points = points.size();
    for (m_point = 0; m_point < m_points; ++m_point) {
      m_next = 0;
      visit_point_fields(*this, points[m_point]);
    }
    return points;
  }

  void scalar(const char* name, double& x) { x = column(name, FieldKind::scalar).values[m_point]; }
  void text(const char* name, std::string& s) {
    s = column(name, FieldKind::text).strings[m_point];
  }
  void per_replica(const char* name, std::vector<double>& v) {
    slice(column(name, FieldKind::per_replica), v);
  }
  void per_node_replica(const char* name, std::vector<double>& v) {
    slice(column(name, FieldKind::per_node_replica), v);
  }
  void node_vector(const char* name, std::vector<double>& v) {
    slice(column(name, FieldKind::node_vector), v);
  }

 private:
  // The column `name`, read when the first point asks for it and checked against the K count.
  const Column& column(const char* name, FieldKind kind) {
    if (m_next == m_columns.size()) m_columns.push_back(read(name, kind));
    return m_columns[m_next++];
  }
  Column read(const char* name, FieldKind kind) const {
    Column c{name, kind, {}, {}};
    const std::string path = std::string("points/") + name;
    const bool node_data = kind == FieldKind::per_node_replica || kind == FieldKind::node_vector;
    if (node_data && !m_file.exists(path)) return c;  // a run without node data
    std::size_t size = 0;
    if (kind == FieldKind::text) {
      c.strings = m_file.read_strings(m_group, name);
      size = c.strings.size();
    } else if (kind == FieldKind::scalar) {
      c.values = m_file.read_double(m_group, name);
      size = c.values.size();
    } else {
      std::size_t rows = 0, cols = 0;
      c.values = m_file.read_matrix(m_group, name, rows, cols);
      size = c.values.size();
    }
    const std::size_t per_point = kind == FieldKind::per_replica ? m_replicas : 1;
    if (node_data ? size % m_points != 0 : size != m_points * per_point) {
      m_file.fail(path + " must have " + (per_point == 1 ? "one entry" : "one row of replicas") +
                  " per K");
    }
    return c;
  }
  void slice(const Column& c, std::vector<double>& v) const {
    const std::size_t per_point = c.values.size() / m_points;
    const auto first = c.values.begin() + static_cast<std::ptrdiff_t>(m_point * per_point);
    v.assign(first, first + static_cast<std::ptrdiff_t>(per_point));
  }

  const Hdf5File& m_file;
  hid_t m_group;
  std::size_t m_replicas;
  std::vector<Column> m_columns;
  std::size_t m_next = 0, m_point = 0, m_points = 0;
};

// The time series: one dataset per field, [records] or [records x replicas].
class SeriesWriter {
 public:
  SeriesWriter(const Hdf5File& f, hid_t group, std::size_t records, std::size_t replicas)
      : m_file(f), m_group(group), m_records(records), m_replicas(replicas) {}
  void per_record(const char* name, const std::vector<double>& v) {
    m_file.write(m_group, name, v);
  }
  void per_record_replica(const char* name, const std::vector<double>& v) {
    m_file.write_matrix(m_group, name, v, m_records, m_replicas);
  }

 private:
  const Hdf5File& m_file;
  hid_t m_group;
  std::size_t m_records, m_replicas;
};

class SeriesReader {
 public:
  SeriesReader(const Hdf5File& f, hid_t group) : m_file(f), m_group(group) {}
  void per_record(const char* name, std::vector<double>& v) {
    v = m_file.read_double(m_group, name);
  }
  void per_record_replica(const char* name, std::vector<double>& v) {
    std::size_t rows = 0, cols = 0;
    v = m_file.read_matrix(m_group, name, rows, cols);
  }

 private:
  const Hdf5File& m_file;
  hid_t m_group;
};

}  // namespace

void write_results(const Hdf5File& f, const std::vector<PointResult>& points,
                   const TimeSeries& series, int replicas) {
  const auto w = static_cast<std::size_t>(replicas);
  Stacker stacker;
  for (const PointResult& p : points) stacker.add(p);
  const H5Id pg = f.create_group("points");
  for (const Column& c : stacker.columns()) write_column(f, pg.get(), c, points.size(), w);
  const H5Id tg = f.create_group("timeseries");
  SeriesWriter writer(f, tg.get(), series.t.size(), w);
  visit_series_fields(writer, series);
}

void read_results(const Hdf5File& f, std::vector<PointResult>& points, TimeSeries& series,
                  int replicas) {
  const H5Id pg = f.open_group("points");
  Unstacker unstacker(f, pg.get(), static_cast<std::size_t>(replicas));
  points = unstacker.points();
  const H5Id tg = f.open_group("timeseries");
  SeriesReader reader(f, tg.get());
  visit_series_fields(reader, series);
}

namespace {

// Doubles stored for the results: per point and replica 4 values; per record t, K and 3 per
// replica; with node data per point 2 N per replica, 5 N (r, fluctuation, synchronised,
// psi_frequency and slack) and the histogram and rotor samples.
double result_doubles(const SimulationParameters& p, double n) {
  const double points = static_cast<double>(p.K.size());
  const double replicas = static_cast<double>(p.replicas.size());
  const double steps = std::ceil(p.duration / p.h);
  const double records = points * (steps / std::max(1, p.record_stride) + 1.0);
  double doubles = points * (4.0 * replicas + 8.0) + records * (2.0 + 3.0 * replicas);
  if (p.node_data) {
    const double rotor = (p.duration - p.transient) / p.h / std::max(1, p.record_stride) + 1.0;
    doubles += points * (n * (2.0 * replicas + 5.0) + p.phase_bins + 2.0 * rotor);
  }
  return doubles;
}

constexpr double k_metadata_bytes = 1 << 20;

}  // namespace

std::uintmax_t estimated_run_file_bytes(const SimulationParameters& params, NodeIndex n) {
  return static_cast<std::uintmax_t>(8.0 * result_doubles(params, n) + k_metadata_bytes);
}

std::uintmax_t estimated_checkpoint_bytes(const SimulationParameters& params, NodeIndex n) {
  // The results so far plus the state (theta, p), the node-data accumulators (theta_T1,
  // R_node_sum, 8 per-row sums) and the batch sums.
  const double N = static_cast<double>(n), replicas = static_cast<double>(lanes(params));
  double state = 2.0 * N * replicas + 64.0 * replicas;
  if (params.node_data) state += 2.0 * N * replicas + 8.0 * N;
  return static_cast<std::uintmax_t>(8.0 * (result_doubles(params, N) + state) + k_metadata_bytes);
}

nlohmann::json run_parameters(const SimulationParameters& params, const std::string& inputs_json) {
  nlohmann::json j = to_json(params);
  if (!inputs_json.empty()) j.update(nlohmann::json::parse(inputs_json));
  return j;
}

namespace {

// The step of the whole run when every K shares it; with per-K steps (SimulationParameters::steps)
// the top-level attributes say so and /points/integrator, /points/h hold each K's.
StepChoice common_step(const SimulationParameters& params) {
  StepChoice first = step_at(params, 0);  // not const: the return moves it
  for (std::size_t k = 1; k < params.K.size(); ++k) {
    if (!(step_at(params, k) == first)) return {"per K: see /points/integrator", std::nan("")};
  }
  return first;
}

}  // namespace

void write_run_file(const std::string& path, const SimulationResult& result,
                    const SimulationParameters& params, const RunMetadata& meta) {
  AtomicFile out(path);
  {
    const Hdf5File f(out.temp_path(), Hdf5File::Mode::create);
    const hid_t root = f.id();
    f.set_attribute(root, "hmfnet_format", std::string("simulation"));
    // 2: /points/h and /points/integrator; `parameters` is run_parameters (every field).
    f.set_attribute(root, "format_version", std::int64_t{2});
    f.set_attribute(root, "hmfnet_version", std::string(version()));
    f.set_attribute(root, "git_commit", std::string(git_commit()));
    f.set_attribute(root, "parameters", run_parameters(params, meta.inputs_json).dump());
    f.set_attribute(root, "network", meta.network_json);
    f.set_attribute(root, "provenance", meta.provenance_json);
    const StepChoice step = common_step(params);
    f.set_attribute(root, "integrator", step.integrator);
    f.set_attribute(root, "force", result.force_name);
    f.set_attribute(root, "h", step.h);
    f.set_attribute(root, "duration", params.duration);
    f.set_attribute(root, "transient", params.transient);
    f.set_attribute(root, "replicas", static_cast<std::int64_t>(params.replicas.size()));
    f.set_attribute(root, "steps", result.steps);
    f.set_attribute(root, "force_evaluations", result.force_evaluations);
    f.set_attribute(root, "integration_seconds", result.integration_seconds);
    write_results(f, result.points, result.series, static_cast<int>(params.replicas.size()));
    if (meta.Kc > 0.0) {
      const H5Id pg = f.open_group("points");
      std::vector<double> ratio;
      for (const auto& p : result.points) ratio.push_back(p.K / meta.Kc);
      f.write(pg.get(), "K_over_Kc", ratio);
      f.set_attribute(root, "Kc", meta.Kc);
    }
    f.flush();
  }
  out.commit();
}

}  // namespace hmfnet

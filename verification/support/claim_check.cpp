#include "support/claim_check.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/hdf5_file.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet::verification {
namespace {

double now_seconds() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

// NaN (no number, e.g. a qualitative check) becomes JSON null.
nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

// A driver's uncaught exception (bad option, unreadable input, unconverged solve) ends the run
// with one line and exit code 2, not an abort that MPI reports as a crash with a stack dump.
void error_exit() {
  std::fflush(stdout);  // what the driver printed so far, before the error
  const std::exception_ptr current = std::current_exception();
  try {
    if (current) std::rethrow_exception(current);
    std::fprintf(stderr, "verification: error: terminated without an exception\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "verification: error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "verification: error: unknown exception\n");
  }
  std::fflush(stderr);
  std::_Exit(2);
}

void install_error_exit() { std::set_terminate(error_exit); }

}  // namespace

DriverOptions parse_driver_options(int argc, char** argv) {
  DriverOptions o;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    const bool has_value = k + 1 < argc;
    if (arg == "--report-only") {
      o.report_only = true;
    } else if ((arg == "--scale" || arg == "--output") && !has_value) {
      throw ParameterError(arg, "missing value", "--scale ci|full, --output F.h5");
    } else if (arg == "--scale") {
      const std::string scale = argv[++k];
      if (scale != "ci" && scale != "full")
        throw ParameterError("--scale", "'" + scale + "'", "ci, full");
      o.full = scale == "full";
    } else if (arg == "--output") {
      o.output = argv[++k];
    } else {
      throw ParameterError(arg, "unknown option", "--scale ci|full, --output F.h5, --report-only");
    }
  }
  return o;
}

ClaimCheck::ClaimCheck(std::string driver, std::string claim, int argc, char** argv)
    : m_driver(std::move(driver)), m_claim(std::move(claim)), m_start(now_seconds()) {
  install_error_exit();
  m_options = parse_driver_options(argc, argv);
  if (!m_options.output.empty()) require_writable_destination(m_options.output);
  std::printf("claim: %s\n", m_claim.c_str());
}

bool ClaimCheck::within_rel(const std::string& what, double value, double reference, double rel_tol,
                            const std::string& why) {
  const double diff = (value - reference) / reference;
  return record({"check", what, value, reference,
                 "diff " + format(100.0 * diff) + "%, tolerance " + format(100.0 * rel_tol) +
                     "% (" + why + ")",
                 std::abs(diff) <= rel_tol});
}

bool ClaimCheck::within_abs(const std::string& what, double value, double reference, double abs_tol,
                            const std::string& why) {
  return record(
      {"check", what, value, reference,
       "diff " + format(value - reference) + ", tolerance " + format(abs_tol) + " (" + why + ")",
       std::abs(value - reference) <= abs_tol});
}

bool ClaimCheck::holds(const std::string& what, bool ok, const std::string& detail) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return record({"check", what, nan, nan, detail, ok});
}

void ClaimCheck::report(const std::string& what, double value, double paper,
                        const std::string& note) {
  std::printf("  INFO  %s: ours %s, paper %s (diff %s%%) %s\n", what.c_str(), format(value).c_str(),
              format(paper).c_str(), format(100.0 * (value - paper) / paper).c_str(), note.c_str());
  m_records.push_back({"report", what, value, paper, note, true});
}

bool ClaimCheck::record(Record r) {
  if (std::isnan(r.ours)) {
    std::printf("  %s  %s: %s\n", r.pass ? "PASS" : "FAIL", r.what.c_str(), r.detail.c_str());
  } else {
    std::printf("  %s  %s: ours %s, reference %s, %s\n", r.pass ? "PASS" : "FAIL", r.what.c_str(),
                format(r.ours).c_str(), format(r.reference).c_str(), r.detail.c_str());
  }
  m_failed += r.pass ? 0 : 1;
  const bool pass = r.pass;
  m_records.push_back(std::move(r));
  return pass;
}

void ClaimCheck::data(const std::string& name, std::vector<double> values) {
  const std::size_t n = values.size();
  m_series.push_back({name, std::move(values), n, 0, {}});
}

void ClaimCheck::data(const std::string& name, std::vector<double> values, std::size_t rows,
                      std::size_t cols) {
  if (rows * cols != values.size()) {
    throw ParameterError("data " + name, std::to_string(values.size()) + " values",
                         std::to_string(rows) + " x " + std::to_string(cols));
  }
  m_series.push_back({name, std::move(values), rows, cols, {}});
}

void ClaimCheck::data(const std::string& name, std::vector<double> values, std::size_t rows,
                      std::vector<std::string> columns) {
  data(name, std::move(values), rows, columns.size());
  m_series.back().columns = std::move(columns);
}

void ClaimCheck::data(const std::string& name,
                      const std::vector<std::pair<std::string, double>>& named) {
  std::vector<double> values;
  std::vector<std::string> columns;
  for (const auto& [key, value] : named) {
    columns.push_back(key);
    values.push_back(value);
  }
  data(name, std::move(values));
  m_series.back().columns = std::move(columns);
}

void ClaimCheck::note(const std::string& name, std::string value) {
  m_notes.emplace_back(name, std::move(value));
}

void ClaimCheck::account(const SimulationCost& cost) { m_cost += cost; }

int ClaimCheck::exit_code() {
  const double wall = now_seconds() - m_start;
  if (m_cost.evaluations > 0.0) {
    const double paper = paper_evaluations();
    std::printf(
        "  INFO  work: %.4g force evaluations; leap-frog h = 0.01 over the same simulated "
        "time: %.4g (%.3gx); kernel %.4g G entries x lanes in %.1f s (%.3g G/s, %d thread(s))\n",
        m_cost.evaluations, paper, paper / m_cost.evaluations, m_cost.kernel_work * 1e-9,
        m_cost.kernel_seconds,
        m_cost.kernel_seconds > 0.0 ? m_cost.kernel_work * 1e-9 / m_cost.kernel_seconds : 0.0,
        m_cost.threads);
  }
  std::printf("%s: %d check(s) failed (%.1f s)\n", m_failed == 0 ? "VERIFIED" : "NOT VERIFIED",
              m_failed, wall);
  if (!m_options.output.empty()) write_output(wall);
  return m_failed == 0 || m_options.report_only ? 0 : 1;
}

// Layout (read by paper/scripts/hmfdata.py): root attributes driver, claim, scale, passed,
// checks (JSON list of records), hmfnet_version, git_commit, wall_seconds, the cost attributes of
// account() and ranks; /data/NAME datasets (a table's column names in its attribute `columns`, a
// JSON list) and string attributes of /data.
void ClaimCheck::write_output(double wall_seconds) const {
  nlohmann::json checks = nlohmann::json::array();
  for (const Record& r : m_records) {
    checks.push_back({{"kind", r.kind},
                      {"what", r.what},
                      {"ours", number(r.ours)},
                      {"reference", number(r.reference)},
                      {"detail", r.detail},
                      {"pass", r.pass}});
  }
  AtomicFile out(m_options.output);
  {
    const Hdf5File file(out.temp_path(), Hdf5File::Mode::create);
    const hid_t root = file.id();
    file.set_attribute(root, "hmfnet_format", std::string("verification"));
    file.set_attribute(root, "driver", m_driver);
    file.set_attribute(root, "claim", m_claim);
    file.set_attribute(root, "scale", std::string(m_options.full ? "full" : "ci"));
    file.set_attribute(root, "passed", static_cast<std::int64_t>(m_failed == 0));
    file.set_attribute(root, "checks", checks.dump());
    file.set_attribute(root, "hmfnet_version", std::string(version()));
    file.set_attribute(root, "git_commit", std::string(git_commit()));
    file.set_attribute(root, "wall_seconds", wall_seconds);
    file.set_attribute(root, "force_evaluations", m_cost.evaluations);
    file.set_attribute(root, "paper_evaluations", paper_evaluations());
    file.set_attribute(root, "kernel_work", m_cost.kernel_work);
    file.set_attribute(root, "kernel_seconds", m_cost.kernel_seconds);
    file.set_attribute(root, "threads", static_cast<std::int64_t>(m_cost.threads));
    file.set_attribute(root, "ranks", static_cast<std::int64_t>(ParallelSession::ranks()));
    const H5Id group = file.create_group("data");
    for (const Series& s : m_series) {
      if (s.cols == 0) {
        file.write(group.get(), s.name, s.values);
      } else {
        file.write_matrix(group.get(), s.name, s.values, s.rows, s.cols);
      }
      if (!s.columns.empty()) {
        const H5Id set(H5Dopen2(group.get(), s.name.c_str(), H5P_DEFAULT), H5Dclose);
        if (set.get() < 0) file.fail("cannot open /data/" + s.name + " to name its columns");
        file.set_attribute(set.get(), "columns", nlohmann::json(s.columns).dump());
      }
    }
    for (const auto& [name, value] : m_notes) file.set_attribute(group.get(), name, value);
    file.flush();
  }
  out.commit();
}

std::string ClaimCheck::format(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

}  // namespace hmfnet::verification

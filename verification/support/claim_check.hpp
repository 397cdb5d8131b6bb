#pragma once
// Bookkeeping for verification drivers: each check prints one line with our value, the
// reference, the tolerance and where the tolerance comes from, then PASS or FAIL; the driver's
// exit code is non-zero if any check failed.
//
// The same records feed the paper pipeline (paper/CMakeLists.txt): with `--output F.h5` the
// driver also writes every check and every data series it registered, so paper/REPORT.md and the
// figures show exactly the numbers that `ctest -L verification` judged.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "support/simulation_cost.hpp"

namespace hmfnet::verification {

/// Command line shared by every driver: `--scale ci|full`, `--output F.h5`, `--report-only`.
struct DriverOptions {
  bool full = false;         ///< paper scale (label verification-full) instead of CI scale
  std::string output;        ///< HDF5 results for the paper pipeline; empty: none
  bool report_only = false;  ///< exit 0 even when a check fails (the report shows the verdict)
};
/// Throws ParameterError on an unknown option or a missing value.
DriverOptions parse_driver_options(int argc, char** argv);

class ClaimCheck {
 public:
  /// `driver` names the output (and the figure scripts that read it).
  ClaimCheck(std::string driver, std::string claim, int argc, char** argv);

  bool full() const { return m_options.full; }

  /// |value - reference| <= rel_tol |reference|.
  bool within_rel(const std::string& what, double value, double reference, double rel_tol,
                  const std::string& why);
  /// |value - reference| <= abs_tol.
  bool within_abs(const std::string& what, double value, double reference, double abs_tol,
                  const std::string& why);
  /// A condition with its explanation (qualitative claims, orderings).
  bool holds(const std::string& what, bool ok, const std::string& detail);
  /// A number reported beside the paper's, without a pass/fail (the paper's value is not
  /// expected to be reproduced; the reason is printed).
  void report(const std::string& what, double value, double paper, const std::string& note);

  /// Data series for the figures: 1-D, or rows x cols row-major; written under /data/NAME.
  void data(const std::string& name, std::vector<double> values);
  void data(const std::string& name, std::vector<double> values, std::size_t rows,
            std::size_t cols);
  /// A table of rows x columns.size() row-major whose column names are stored beside it (the
  /// attribute `columns` of /data/NAME, a JSON list), so scripts read columns by name and a
  /// reordering here cannot silently move a figure's data.
  void data(const std::string& name, std::vector<double> values, std::size_t rows,
            std::vector<std::string> columns);
  /// Named numbers: a 1-D /data/NAME with their names in its attribute `columns`.
  void data(const std::string& name, const std::vector<std::pair<std::string, double>>& named);
  /// A string attribute of /data (labels, JSON descriptions of the series).
  void note(const std::string& name, std::string value);

  /// Adds one simulation's cost (support/work_account.hpp makes it from a run). Written as root
  /// attributes: force_evaluations and paper_evaluations (those the paper's leap-frog h = 0.01
  /// would have spent on the same simulated time), kernel_work, kernel_seconds and threads;
  /// ranks is always written.
  void account(const SimulationCost& cost);

  /// Prints the verdict, writes --output (atomically) and returns the exit code.
  int exit_code();

  static std::string format(double x);

 private:
  struct Record {
    std::string kind;  // "check" or "report"
    std::string what;
    double ours;
    double reference;
    std::string detail;
    bool pass;
  };
  struct Series {
    std::string name;
    std::vector<double> values;
    std::size_t rows, cols;
    std::vector<std::string> columns;  // empty: unnamed
  };
  bool record(Record r);
  /// Leap-frog h = 0.01 over the same simulated time: one evaluation per step.
  double paper_evaluations() const { return m_cost.simulated_time / 0.01; }
  void write_output(double wall_seconds) const;

  std::string m_driver;
  std::string m_claim;
  DriverOptions m_options;
  std::vector<Record> m_records;
  std::vector<Series> m_series;
  std::vector<std::pair<std::string, std::string>> m_notes;
  int m_failed = 0;
  double m_start;
  SimulationCost m_cost;
};

}  // namespace hmfnet::verification

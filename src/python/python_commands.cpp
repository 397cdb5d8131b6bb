// The commands on a Python network: the services the CLI runs (src/app), so the numbers equal the
// CLI's on the same network and parameters. Each takes its typed request (keyword arguments set
// its fields: python/hmfnet/_arguments.py) and returns its outcome's fields under the names that
// `--json` prints (one field list each, walked by both), the time series as numpy arrays.
#include "python/python_commands.hpp"

#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <signal.h>

#include <csignal>
#include <mutex>
#include <string>
#include <vector>

#include "app/simulate_service.hpp"
#include "app/spectrum_service.hpp"
#include "app/theory_service.hpp"
#include "core/error.hpp"
#include "dynamics/interrupt.hpp"
#include "python/python_network.hpp"

namespace py = pybind11;

namespace hmfnet::python {

namespace {

// records x replicas, row-major, as a 2-D array.
py::array_t<double> matrix(const std::vector<double>& values, std::size_t rows) {
  const std::size_t cols = rows == 0 ? 0 : values.size() / rows;
  py::array_t<double> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

py::array_t<double> vector(const std::vector<double>& values) {
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

// Every field of the time series (point_result.hpp's list) as a numpy array.
struct SeriesArrays {
  py::dict arrays;
  std::size_t records;
  void per_record(const char* name, const std::vector<double>& v) { arrays[name] = vector(v); }
  void per_record_replica(const char* name, const std::vector<double>& v) {
    arrays[name] = matrix(v, records);
  }
};

// One command at a time: MPI, Tpetra and the interrupt flag are process-wide, and two Python
// threads could otherwise enter them together once the GIL is released.
std::mutex g_command_mutex;

// Ctrl-C goes to the simulation's flag while it integrates (the interpreter cannot see it while
// the GIL is released): the run stops at the next record and RunInterrupted becomes
// KeyboardInterrupt. SIGINT's disposition is saved with its flags and restored as it was; SIGTERM
// keeps Python's.
class ScopedInterruptHandler {
 public:
  ScopedInterruptHandler() { sigaction(SIGINT, nullptr, &m_saved); }
  ~ScopedInterruptHandler() {
    if (m_installed) sigaction(SIGINT, &m_saved, nullptr);
    set_interrupt_signal(0);
  }
  ScopedInterruptHandler(const ScopedInterruptHandler&) = delete;
  ScopedInterruptHandler& operator=(const ScopedInterruptHandler&) = delete;

  void install() {
    struct sigaction term {};
    sigaction(SIGTERM, nullptr, &term);
    set_interrupt_signal(0);
    install_interrupt_handlers();
    sigaction(SIGTERM, &term, nullptr);
    m_installed = true;
  }

 private:
  struct sigaction m_saved {};
  bool m_installed = false;
};

// omp_set_num_threads (simulate's --threads) lasts for the process: a Python call must not
// change the thread count of the calls after it.
class ScopedThreadCount {
 public:
  ScopedThreadCount() : m_threads(omp_get_max_threads()) {}
  ~ScopedThreadCount() { omp_set_num_threads(m_threads); }
  ScopedThreadCount(const ScopedThreadCount&) = delete;
  ScopedThreadCount& operator=(const ScopedThreadCount&) = delete;

 private:
  int m_threads;
};

// A visited field as a Python value under its name (app/simulate_service.hpp's lists).
struct DictFields {
  py::dict& out;
  template <class T>
  void field(const char* name, const T& value) {
    out[name] = value;
  }
};

// The outcome of `run` on the network, computed with the GIL released and one command at a time.
template <class Run>
auto without_gil(const Run& run) {
  py::gil_scoped_release release;
  const std::lock_guard<std::mutex> lock(g_command_mutex);
  return run();
}

py::dict spectrum(const PythonNetwork& net, app::SpectrumRequest request) {
  request.input = net.source;
  const app::SpectrumOutcome o =
      without_gil([&] { return app::spectrum(request, net.distributed()); });
  py::dict out;
  DictFields fields{out};
  app::visit_spectrum_fields(fields, o);
  return out;
}

py::dict theory(const PythonNetwork& net, app::TheoryRequest request) {
  request.input = net.source;
  const app::TheoryOutcome o = without_gil([&] { return app::theory(request, net.distributed()); });
  if (!o.not_converged.empty()) throw ConvergenceError(o.not_converged);
  py::dict out;
  DictFields fields{out};
  app::visit_theory_fields(fields, o);
  py::list points, gamma;
  for (const app::TheoryPoint& p : o.points) {
    py::dict point;
    DictFields point_fields{point};
    app::visit_theory_point_fields(point_fields, p);
    points.append(point);
    if (!app::above_threshold(p)) continue;
    py::dict growth;
    DictFields growth_fields{growth};
    app::visit_growth_fields(growth_fields, p);
    gamma.append(growth);
  }
  out["points"] = points;
  out["gamma"] = gamma;
  out["warnings"] = o.warnings;
  return out;
}

py::dict simulate(const PythonNetwork& net, app::SimulateRequest request) {
  request.input = net.source;
  request.progress = false;  // no progress line on a notebook's stderr
  const app::SimulateOutcome o = without_gil([&] {
    const ScopedThreadCount threads;
    ScopedInterruptHandler handler;
    app::SimulateHooks hooks;
    app::prepare_simulate(request);
    hooks.before_integration = [&handler] { handler.install(); };
    return app::simulate(request, net.distributed(), hooks);
  });
  py::dict out;
  DictFields fields{out};
  app::visit_report_fields(fields, o);
  if (!o.points.empty()) {
    py::list points;
    for (const app::PointSummary& p : o.points) {
      py::dict point;
      DictFields point_fields{point};
      app::visit_summary_fields(point_fields, p);
      points.append(point);
    }
    out["points"] = points;
  }
  SeriesArrays series{{}, o.result.series.t.size()};
  visit_series_fields(series, o.result.series);
  out["timeseries"] = series.arrays;
  return out;
}

// The request with every field settable by name; Python's simulate() sets the keyword arguments
// it was given (python/hmfnet/_arguments.py refuses bools where a number is meant).
void bind_simulate_request(py::module_& m) {
  py::class_<app::SimulateRequest>(m, "SimulateRequest")
      .def(py::init<>())
      .def_readwrite("sigma0", &app::SimulateRequest::sigma0)
      .def_readwrite("omega", &app::SimulateRequest::omega)
      .def_readwrite("momenta", &app::SimulateRequest::momenta)
      .def_readwrite("K", &app::SimulateRequest::K)
      .def_readwrite("K_over_Kc", &app::SimulateRequest::K_over_Kc)
      .def_readwrite("K_sweep", &app::SimulateRequest::sweep)
      .def_readwrite("h", &app::SimulateRequest::h)
      .def_readwrite("T", &app::SimulateRequest::T)
      .def_readwrite("transient", &app::SimulateRequest::transient)
      .def_readwrite("seed", &app::SimulateRequest::seed)
      .def_readwrite("replicas", &app::SimulateRequest::replicas)
      .def_readwrite("threads", &app::SimulateRequest::threads)
      .def_readwrite("output", &app::SimulateRequest::output)
      .def_readwrite("checkpoint", &app::SimulateRequest::checkpoint)
      .def_readwrite("force", &app::SimulateRequest::force)
      .def_readwrite("integrator", &app::SimulateRequest::integrator)
      .def_readwrite("precision", &app::SimulateRequest::precision)
      .def_readwrite("device", &app::SimulateRequest::device)
      .def_readwrite("resume", &app::SimulateRequest::resume)
      .def_readwrite("node_data", &app::SimulateRequest::node_data)
      .def_readwrite("restart_each_K", &app::SimulateRequest::restart_each_K)
      .def_readwrite("K_across_replicas", &app::SimulateRequest::K_across_replicas)
      .def_readwrite("record_stride", &app::SimulateRequest::record_stride)
      .def_readwrite("energy_tolerance", &app::SimulateRequest::energy_tolerance)
      .def_readwrite("rotor_node", &app::SimulateRequest::rotor_node)
      .def_readwrite("phase_bins", &app::SimulateRequest::phase_bins);
}

void bind_spectrum_request(py::module_& m) {
  py::class_<app::SpectrumRequest>(m, "SpectrumRequest")
      .def(py::init<>())
      .def_readwrite("sigma0", &app::SpectrumRequest::sigma0)
      .def_readwrite("tolerance", &app::SpectrumRequest::tolerance)
      .def_readwrite("lambda2", &app::SpectrumRequest::lambda2);
}

void bind_theory_request(py::module_& m) {
  py::class_<app::TheoryRequest>(m, "TheoryRequest")
      .def(py::init<>())
      .def_readwrite("sigma0", &app::TheoryRequest::sigma0)
      .def_readwrite("momenta", &app::TheoryRequest::momenta)
      .def_readwrite("K", &app::TheoryRequest::K)
      .def_readwrite("K_over_Kc", &app::TheoryRequest::K_over_Kc)
      .def_readwrite("tolerance", &app::TheoryRequest::tolerance);
}

}  // namespace

void bind_commands(py::module_& m) {
  bind_spectrum_request(m);
  m.def("_spectrum", &spectrum, py::arg("network"), py::arg("request"));
  bind_theory_request(m);
  m.def("_theory", &theory, py::arg("network"), py::arg("request"));
  bind_simulate_request(m);
  m.def("_simulate", &simulate, py::arg("network"), py::arg("request"));
}

}  // namespace hmfnet::python

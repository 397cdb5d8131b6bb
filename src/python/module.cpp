// The `hmfnet._hmfnet` extension module: the C++ library behind the Python package
// `hmfnet` (python/hmfnet/__init__.py adds keyword arguments, scipy/networkx input and the
// results file reader). One MPI + Kokkos session lives as long as the interpreter: a Python
// process is one MPI rank (a singleton, no mpirun needed).
#include <pybind11/pybind11.h>

#include <memory>

#include "app/provenance.hpp"
#include "core/error.hpp"
#include "dynamics/interrupt.hpp"
#include "dynamics/simulation.hpp"
#include "parallel/parallel_session.hpp"
#include "python/python_commands.hpp"
#include "python/python_network.hpp"

namespace py = pybind11;

namespace {

std::unique_ptr<hmfnet::ParallelSession> g_session;

void start_session() {
  static int argc = 1;
  static char name[] = "python";
  static char* argv_storage[] = {name, nullptr};
  static char** argv = argv_storage;
  g_session = std::make_unique<hmfnet::ParallelSession>(&argc, &argv);
  hmfnet::app::set_command_line("python: hmfnet module");
}

// ParameterError (a std::invalid_argument) becomes ValueError by pybind11's own rule: a value that
// a request's check refuses (src/app: validate) is a ValueError with the CLI's words.
void register_errors(py::module_& m) {
  // A file or matrix that cannot be read, named with FILE:LINE (entry k of a Python matrix).
  py::register_exception<hmfnet::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<hmfnet::ConvergenceError>(m, "ConvergenceError", PyExc_RuntimeError);
  // NaN or an energy error past --energy-tolerance: the step is too large for the method.
  py::register_exception<hmfnet::SimulationBlowUp>(m, "SimulationBlowUp", PyExc_ArithmeticError);
  // pybind11 takes exactly void (*)(std::exception_ptr).
  // NOLINTNEXTLINE(performance-unnecessary-value-param)
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const hmfnet::RunInterrupted& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    } catch (const hmfnet::CollectiveError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });
}

}  // namespace

PYBIND11_MODULE(_hmfnet, m) {
  m.doc() = "hmfnet: the Hamiltonian Mean Field model of coupled rotors on networks (C++ core)";
  start_session();
  // The session ends before the interpreter's own teardown, while the library is still loaded.
  py::module_::import("atexit").attr("register")(py::cpp_function([] { g_session.reset(); }));
  register_errors(m);
  hmfnet::python::bind_network(m);
  hmfnet::python::bind_commands(m);
}

// `hmfnet simulate`: the command line's face of the simulate service (app/simulate_service.hpp):
// options to a request, the outcome to text or JSON.
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/simulate_service.hpp"
#include "cli/command_options.hpp"
#include "cli/commands.hpp"
#include "cli/read_flags.hpp"
#include "core/error.hpp"
#include "core/json_fields.hpp"
#include "dynamics/interrupt.hpp"

namespace hmfnet::cli {

namespace {

std::string report_json(const app::SimulateOutcome& o) {
  nlohmann::json out;
  JsonFields fields{out};
  app::visit_report_fields(fields, o);
  for (const app::PointSummary& p : o.points) {
    nlohmann::json point;
    JsonFields point_fields{point};
    app::visit_summary_fields(point_fields, p);
    out["points"].push_back(point);
  }
  return out.dump();
}

std::string report_text(const app::SimulateOutcome& o) {
  std::ostringstream text;
  text << "N = " << o.n << ", nnz = " << o.nnz << ", lambda = " << o.lambda << ", K_c = " << o.Kc
       << " (" << o.force << " force, " << (o.device == "cpu" ? "" : "on " + o.device + ", ")
       << o.nnz_steps_per_second / 1e9 << " Gnnz*steps/s)\n"
       << "       K    K/K_c     <R>_t       sem   max dE/E  P drift\n";
  for (const app::PointSummary& p : o.points) {
    char line[128];
    std::snprintf(line, sizeof line, "%8.4g %8.4f %9.5f %9.2e %10.2e %8.1e\n", p.K, p.K_over_Kc,
                  p.R_mean, p.R_sem, p.energy_rel_error_max, p.momentum_drift);
    text << line;
  }
  return text.str();
}

void run(SimulateFlags& f) {
  app::SimulateHooks hooks;
  f.request.progress = !f.quiet && !f.json && ::isatty(2);
  // A value out of range is a command-line error like any the grammar finds: the same one line
  // ending in "(see --help)" and exit code 2 (main.cpp), from the request's own check.
  as_command_line_error([&] { app::prepare_simulate(f.request); });  // validate(f.request) first
  DistributedInput input = f.read.read_distributed(f.request.input);
  hooks.before_integration = install_interrupt_handlers;
  const app::SimulateOutcome o = app::simulate(f.request, std::move(input), hooks);
  if (is_root()) std::cout << (f.json ? report_json(o) + '\n' : report_text(o)) << std::flush;
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  static SimulateFlags f;
  add_simulate_options(app, f, [] { run(f); });
}

}  // namespace hmfnet::cli

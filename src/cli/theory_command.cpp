// `hmfnet theory`: the command line's face of the theory service (app/theory_service.hpp): the
// paper's predictions for one network and momentum spread sigma0, as a table or JSON.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/theory_service.hpp"
#include "cli/command_options.hpp"
#include "cli/commands.hpp"
#include "cli/read_flags.hpp"
#include "core/error.hpp"
#include "core/json_fields.hpp"

namespace hmfnet::cli {

namespace {

std::string report_json(const app::TheoryOutcome& o) {
  nlohmann::json out;
  JsonFields fields{out};
  app::visit_theory_fields(fields, o);
  out["gamma"] = nlohmann::json::array();
  out["points"] = nlohmann::json::array();
  for (const app::TheoryPoint& p : o.points) {
    nlohmann::json point;
    JsonFields point_fields{point};
    app::visit_theory_point_fields(point_fields, p);
    out["points"].push_back(point);
    if (!app::above_threshold(p)) continue;
    nlohmann::json growth;
    JsonFields growth_fields{growth};
    app::visit_growth_fields(growth_fields, p);
    out["gamma"].push_back(growth);
  }
  return out.dump();
}

void print_text(std::ostream& out, const app::TheoryOutcome& o) {
  out << std::setprecision(6) << "lambda             " << o.lambda << "\n"
      << "K_c                " << o.Kc << " (linear threshold, " << o.momenta
      << " momenta, sigma0 = " << o.sigma0 << ")\n"
      << "K_c equilibrium    " << o.Kc_equilibrium << " (where paper eq. (33) leaves R = 0)\n"
      << "G                  " << o.G << "\n"
      << "R_hat (K -> inf)   " << o.R_hat_iteration << " (paper eq. (39), " << o.R_hat_iterations
      << " iterations), " << o.R_hat_degree_approx << " (degree approximation, paper eq. (42))\n\n"
      << std::setw(12) << "K" << std::setw(10) << "K/K_c" << std::setw(12) << "R" << std::setw(12)
      << "G*sqrt" << std::setw(12) << "sigma^2" << std::setw(12) << "gamma" << std::setw(7)
      << "iter" << std::setw(12) << "residual"
      << "  status\n";
  for (const app::TheoryPoint& p : o.points) {
    out << std::setw(12) << p.K << std::setw(10) << p.K_over_Kc << std::setw(12) << p.R
        << std::setw(12) << p.R_onset << std::setw(12) << p.sigma2 << std::setw(12) << p.gamma
        << std::setw(7) << p.iterations << std::setw(12) << p.residual << "  " << p.status << "\n";
  }
}

void run(const TheoryFlags& f) {
  const app::TheoryOutcome o = app::theory(f.request, f.read.read_distributed(f.request.input));
  if (!is_root()) return;  // rank 0 prints the report, then the failure once
  for (const std::string& w : o.warnings) std::cerr << w << '\n';
  if (f.json) {
    std::cout << report_json(o) << '\n';
  } else {
    print_text(std::cout, o);
  }
  std::cout << std::flush;
  if (!o.not_converged.empty()) throw ConvergenceError(o.not_converged);
}

}  // namespace

void add_theory_command(CLI::App& app) {
  static TheoryFlags f;
  add_theory_options(app, f, [] { run(f); });
}

}  // namespace hmfnet::cli

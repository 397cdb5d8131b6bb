// `hmfnet spectrum`: the command line's face of the spectrum service (app/spectrum_service.hpp):
// lambda, Perron vector summaries, rho, G, structure, K_c, as text or JSON.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/spectrum_service.hpp"
#include "cli/command_options.hpp"
#include "cli/commands.hpp"
#include "cli/read_flags.hpp"
#include "core/json_fields.hpp"

namespace hmfnet::cli {

namespace {

void print_text(std::ostream& out, const NetworkSummary& s) {
  out << std::setprecision(8) << "nodes              " << s.n << "\n"
      << "edges              " << s.edges << " (nnz " << s.nnz << ", self-loops " << s.self_loops
      << (s.weighted ? ", weighted" : "") << ")\n"
      << "mean degree        " << s.mean_degree << " (max " << s.max_degree << ")\n"
      << "lambda             " << s.lambda << " (residual " << s.lambda_residual << ", "
      << s.eigen_iterations << " iterations, " << s.eigen_seconds << " s)\n"
      << "rho                " << s.rho << "\n"
      << "G                  " << s.G << "\n";
  if (std::isnan(s.lambda2) && std::isfinite(s.lambda2_lower)) {
    out << "lambda_2           in [" << s.lambda2_lower << ", " << s.lambda2_upper
        << "] (Lanczos bounds, " << s.lambda2_bound_steps
        << " steps; the upper one with probability >= 1 - " << s.lambda2_bound_failure << ")";
    if (std::isfinite(s.second_mode_ratio)) {
      out << ": lambda / lambda_2 >= " << s.second_mode_ratio;
    }
    out << ", Perron vector error <= " << s.eigenvector_error_bound << "\n";
  } else if (std::isnan(s.lambda2)) {
    // Few distinct eigenvalues (a star has three) defeat Krylov-Schur for a second pair.
    out << "lambda_2           not found (no second eigenpair passed its residual check)\n";
  } else {
    out << "lambda_2           " << s.lambda2;
    if (std::isfinite(s.second_mode_ratio)) {
      out << " (lambda / lambda_2 = " << s.second_mode_ratio << ",";
    } else {
      out << " (";
    }
    out << " Perron vector error <= " << s.eigenvector_error_bound << ")\n";
  }
  out << "components         " << s.components << " (largest " << s.largest_component << ")\n"
      << "bipartite          " << (s.bipartite ? "yes" : "no") << "\n";
  if (s.sigma0 > 0.0) out << "K_c (sigma0 = " << s.sigma0 << ")  " << s.Kc << "\n";
  for (const auto& w : s.warnings) out << "warning: " << w << "\n";
}

std::string report_json(const app::SpectrumOutcome& o) {
  nlohmann::json out;
  JsonFields fields{out};
  app::visit_spectrum_fields(fields, o);
  return out.dump();
}

void run(const SpectrumFlags& f) {
  const app::SpectrumOutcome o = app::spectrum(f.request, f.read.read_distributed(f.request.input));
  if (!is_root()) return;
  if (f.json) {
    std::cout << report_json(o) << std::endl;
  } else {
    print_text(std::cout, o.summary);
  }
}

}  // namespace

void add_spectrum_command(CLI::App& app) {
  static SpectrumFlags f;
  add_spectrum_options(app, f, [] { run(f); });
}

}  // namespace hmfnet::cli

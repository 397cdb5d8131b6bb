#pragma once
// The checks shared by the onset drivers (onset_er_sf, onset_rewired, onset_sigma0): per curve,
// the measured onset (onset_sweep.hpp) against eq:criticalKFirstOrder; per family, that the
// onsets line up on the collapsing axis and not on the alternative one; and the figure arrays.
// The tolerances are derived in onset_sweep.hpp and in each driver's header block.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/claim_check.hpp"
#include "support/onset_sweep.hpp"

namespace hmfnet::verification {

inline double range(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
}

// For one network: the onset must be resolved (>= 3 equilibrated points in the fit window);
// x_on against 1 (eq:criticalKFirstOrder) and against the same rule on the theory curve (same
// points, same weights) are reported, not checked: near onset the simulated R^2(x) is nearly
// straight while the equilibrium theory's bends (measured at CI scale, N = 1000, 600 time units
// per K: R = 0.213, 0.30, 0.36 at x = 1.2, 1.35, 1.5 against 0.258, 0.321, 0.364), so the two
// extrapolations differ by 0.08-0.26 whatever the window; the paper's claim is about the
// simulated onsets lining up, which the family checks test. Returns the curve.
inline OnsetCurve check_onset(ClaimCheck& check, const std::string& name, const Network& net,
                              double sigma0, const SweepProtocol& p) {
  OnsetCurve c = measure_onset(net, sigma0, p);
  check.account(c.cost);
  std::string grid;
  for (std::size_t k = 0; k < c.x.size(); ++k) {
    char cell[32];
    std::snprintf(cell, sizeof cell, " %.2f:%.3f", c.x[k], c.R[k]);
    grid += cell;
    if (c.segments[k] > 1) grid += "x" + std::to_string(static_cast<int>(c.segments[k]));
    grid += c.fitted[k] != 0.0 ? "*" : (c.equilibrated[k] != 0.0 ? "e" : "");
  }
  std::printf(
      "  INFO  %s: lambda %.2f, K_c %.4g, R0 %.4f, %g time units; x:<R> (xm: m segments, "
      "e: equilibrated, *: fitted)%s\n",
      name.c_str(), c.lambda, c.Kc, c.R0, c.cost.simulated_time, grid.c_str());
  std::printf(
      "  INFO  %s: x_on %.3f +- %.3f (%d points), same rule on theory %.3f, on the theory at the "
      "sweep's (E, P) %.3f\n",
      name.c_str(), c.x_on, c.x_on_err, c.points, c.x_on_theory, c.x_on_theory_ep);
  if (!std::isnan(c.prefix_repeat)) {
    check.holds(name + ": refined sweep repeats the first sweep up to the first midpoint",
                c.prefix_repeat == 0.0,
                "largest |d<R>| " + ClaimCheck::format(c.prefix_repeat) +
                    " (same seeds and K sequence: bit-identical, onset_grid.hpp)");
  }
  if (std::isnan(c.x_on) || std::isnan(c.x_on_theory)) {
    check.holds(name + ": onset resolved", false,
                "fewer than 3 equilibrated grid points with excess in [0.1, 0.35] after the "
                "refinement of onset_grid.hpp: " +
                    std::to_string(c.points));
    return c;
  }
  check.holds(name + ": onset resolved", true,
              std::to_string(c.points) + " equilibrated points in the fit window");
  check.report(name + ": onset lambda K_on / (2 sigma0^2 N) vs eq:criticalKFirstOrder", c.x_on, 1.0,
               "(fit se " + ClaimCheck::format(c.x_on_err) + ")");
  check.report(name + ": onset vs the same rule on the equilibrium theory", c.x_on, c.x_on_theory,
               "(not reproduced near onset: the simulated R^2 is straighter, see "
               "onset_checks.hpp)");
  check.report(name + ": onset vs the same rule on the theory at the sweep's own (E, P)", c.x_on,
               c.x_on_theory_ep,
               "(the energy path of the sweep removed: what is left is the dynamics' lag)");
  return c;
}

/// Checks (b) and (c) for one family. x_on is the onset on the collapsing axis (lambda K, or
/// K / sigma0^2 for one network); `other[i]` scales K_on to the alternative axis the check must
/// reject (1: plain K; ||d||: the mean-degree scaling).
/// (b) the simulated onsets line up: their range is at most the range the same rule gives on the
///     theory curves (the collapse the theory itself predicts, G differs between networks) plus
///     2 sqrt(2) x the largest fit se (~95% for the difference of two onsets).
/// (c) they line up better than on the other axis; checked only where the two axes differ by
///     more than that noise (max/min of the scale factor between them - 1 > 2 sqrt(2) max se)
///     and the two measured spreads (max/min of the onsets on each axis) differ by more than it
///     too, in either direction (a two-sided test); otherwise reported as not resolved.
inline void check_lines_up(ClaimCheck& check, const std::string& family,
                           const std::vector<OnsetCurve>& curves, const std::vector<double>& other,
                           const std::string& axis) {
  std::vector<double> xs, theory, K_other, scale;
  double err = 0.0;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const OnsetCurve& c = curves[i];
    xs.push_back(c.x_on);
    theory.push_back(c.x_on_theory);
    K_other.push_back(c.x_on * c.Kc * other[i]);
    scale.push_back(c.Kc * other[i]);
    err = std::max(err, c.x_on_err);
  }
  const double noise = 2.0 * std::sqrt(2.0) * err;
  check.holds(family + ": onsets line up in " + axis, range(xs) <= range(theory) + noise,
              "range of x_on " + ClaimCheck::format(range(xs)) + " <= theory's range " +
                  ClaimCheck::format(range(theory)) + " + 2 sqrt2 max se " +
                  ClaimCheck::format(noise));
  const auto rel = [](const std::vector<double>& v) {
    return (*std::max_element(v.begin(), v.end())) / (*std::min_element(v.begin(), v.end()));
  };
  const std::string detail = "max/min of the onset on the other axis " +
                             ClaimCheck::format(rel(K_other)) + " vs on " + axis + " " +
                             ClaimCheck::format(rel(xs)) + "; the axes differ by a factor " +
                             ClaimCheck::format(rel(scale));
  // The two spreads carry the same fit noise (K_other is x_on times a fixed factor), so their
  // order is a result only when they differ by more than it; otherwise either verdict is a draw
  // of the noise (at ci scale a round-off change of lambda flipped it: x_on 0.948 +- 0.044 vs
  // 0.966 +- 0.150 for the same network).
  const double margin = rel(K_other) - rel(xs);
  if (rel(scale) - 1.0 > noise && std::abs(margin) > noise) {
    check.holds(family + ": onsets do not line up on the other axis", margin > 0.0, detail);
  } else if (rel(scale) - 1.0 > noise) {
    check.report(family + ": which axis lines up better is not resolved at this scale",
                 rel(K_other), rel(xs),
                 "(" + detail + "; the spreads differ by " + ClaimCheck::format(margin) +
                     ", within 2 sqrt2 max se " + ClaimCheck::format(noise) + ")");
  } else {
    check.report(family + ": other axis not resolvable at this scale", rel(K_other), rel(xs),
                 "(" + detail + " < 1 + 2 sqrt2 max se)");
  }
}

/// Figure arrays PREFIX_{K,R,R_err,R_theory,segments,equilibrated,fitted} (curves x grid) and
/// per-curve lambda, sigma0, onsets.
inline void add_onset_figure_data(ClaimCheck& check, const std::string& prefix,
                                  const std::vector<OnsetCurve>& curves,
                                  const std::string& labels) {
  const std::size_t rows = curves.size(), cols = grid_columns(curves);
  check.data(prefix + "_K", stack(curves, &OnsetCurve::K), rows, cols);
  check.data(prefix + "_R", stack(curves, &OnsetCurve::R), rows, cols);
  check.data(prefix + "_R_err", stack(curves, &OnsetCurve::R_err), rows, cols);
  check.data(prefix + "_R_theory", stack(curves, &OnsetCurve::R_theory), rows, cols);
  check.data(prefix + "_R_theory_ep", stack(curves, &OnsetCurve::R_theory_ep), rows, cols);
  check.data(prefix + "_segments", stack(curves, &OnsetCurve::segments), rows, cols);
  check.data(prefix + "_equilibrated", stack(curves, &OnsetCurve::equilibrated), rows, cols);
  check.data(prefix + "_fitted", stack(curves, &OnsetCurve::fitted), rows, cols);
  std::vector<double> lambda, sigma0, x_on, x_on_err, x_th, x_th_ep;
  for (const OnsetCurve& c : curves) {
    lambda.push_back(c.lambda);
    sigma0.push_back(c.sigma0);
    x_on.push_back(c.x_on);
    x_on_err.push_back(c.x_on_err);
    x_th.push_back(c.x_on_theory);
    x_th_ep.push_back(c.x_on_theory_ep);
  }
  check.data(prefix + "_lambda", lambda);
  check.data(prefix + "_sigma0", sigma0);
  check.data(prefix + "_x_on", x_on);
  check.data(prefix + "_x_on_err", x_on_err);
  check.data(prefix + "_x_on_theory", x_th);
  check.data(prefix + "_x_on_theory_ep", x_th_ep);
  check.note(prefix + "_labels", labels);
}

}  // namespace hmfnet::verification

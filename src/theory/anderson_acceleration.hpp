#pragma once
// Anderson acceleration of a fixed-point iteration x = g(x) (D. G. Anderson, J. ACM 12, 547
// (1965)), in the form with a mixing parameter of Walker & Ni, SIAM J. Numer. Anal. 49, 1715
// (2011). It is what makes the self-consistent solvers fast near K_c, where plain iteration
// contracts by ~1 - 2(K/K_c - 1) per step, and on bipartite networks, where the mode of A at
// -lambda makes plain iteration oscillate.
//
// With f = g(x) - x and the last m differences dX_j = x_{j+1} - x_j, dF_j = f_{j+1} - f_j, step k
// solves min_c ||f_k - dF c||_2 and moves to
//   x_{k+1} = x_k + beta f_k - (dX + beta dF) c.
// memory m = 0 is the damped iteration x_{k+1} = x_k + beta f_k (beta = 1: plain iteration).
// The 2-norm weighs every component of x alike: callers scale their unknowns to comparable size.
//
// Safeguards: the least-squares problem is solved by column-pivoted QR that ignores directions
// whose pivot is below 1e-12 of the largest (a nearly dependent history). An extrapolated point
// whose residual exceeds `restart_growth` times the best seen, or is not finite, is rejected: the
// history is dropped and the iteration continues from the current iterate with damped steps,
// memory * (number of rejections so far) of them, before it extrapolates again. If the best
// residual has not halved within `stagnation_window` iterations, extrapolation stops for good.
// So a problem on which extrapolation fails degrades to the damped iteration instead of cycling.
#include <functional>
#include <limits>
#include <vector>

namespace hmfnet {

struct AndersonOptions {
  int memory = 5;               ///< m >= 0, differences kept (0: damped iteration)
  double damping = 1.0;         ///< beta in (0, 1]
  double tolerance = 1e-10;     ///< on the problem's own residual measure
  int max_iterations = 1000;    ///< evaluations of g, >= 1
  double restart_growth = 1e4;  ///< reject when residual > restart_growth * best residual
  /// Largest extrapolated step in the max-norm (longer steps are shortened to it, keeping their
  /// direction); infinity: no limit. A trust region for maps with a spurious root far away.
  double max_step = std::numeric_limits<double>::infinity();
  /// If the best residual has not halved in this many iterations, extrapolation stops for good
  /// and the iteration finishes damped (damped_fallback in the result).
  int stagnation_window = 40;
};

/// gx = g(x) (gx has the size of x); returns the convergence measure of the pair (x, g(x)), >= 0.
/// Non-finite values (x outside the domain of g) are allowed and count as not converged.
using FixedPointMap = std::function<double(const std::vector<double>& x, std::vector<double>& gx)>;

struct FixedPointResult {
  bool converged = false;
  /// Converged: the first iterate whose residual met the tolerance. Otherwise the last accepted
  /// iterate: a diagnostic, never an answer.
  std::vector<double> x;
  std::vector<double> gx;  ///< g(x)
  double residual = std::numeric_limits<double>::infinity();
  int iterations = 0;            ///< evaluations of g
  int restarts = 0;              ///< rejected extrapolations
  bool damped_fallback = false;  ///< stagnation ended the extrapolation (see stagnation_window)
};

/// Throws ParameterError for bad options, an empty map or an empty x0.
FixedPointResult anderson_fixed_point(const FixedPointMap& map, std::vector<double> x0,
                                      const AndersonOptions& options = {});

}  // namespace hmfnet

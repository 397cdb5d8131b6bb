// Anderson acceleration on maps whose fixed points and convergence behaviour are known.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "theory/anderson_acceleration.hpp"

using namespace hmfnet;

namespace {

// g(x) = D x + b with D diagonal (eigenvalues `diag`), residual max|g(x) - x|: fixed point
// x_i = b_i / (1 - d_i).
FixedPointMap linear_map(const std::vector<double>& diag, const std::vector<double>& b) {
  return [diag, b](const std::vector<double>& x, std::vector<double>& gx) {
    double res = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      gx[i] = diag[i] * x[i] + b[i];
      res = std::max(res, std::abs(gx[i] - x[i]));
    }
    return res;
  };
}

double max_error(const std::vector<double>& x, const std::vector<double>& diag,
                 const std::vector<double>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) e = std::max(e, std::abs(x[i] - b[i] / (1 - diag[i])));
  return e;
}

}  // namespace

TEST_CASE(
    "Anderson solves a slow linear contraction in far fewer steps than plain iteration "
    "[n=50 spectral radius 0.99]",
    "[theory]") {
  std::vector<double> diag(50), b(50, 1.0);
  for (std::size_t i = 0; i < diag.size(); ++i) diag[i] = 0.99 * static_cast<double>(i) / 49.0;
  AndersonOptions plain;
  plain.memory = 0;
  plain.max_iterations = 10000;
  AndersonOptions accelerated;
  const FixedPointResult slow =
      anderson_fixed_point(linear_map(diag, b), std::vector<double>(50), plain);
  const FixedPointResult fast =
      anderson_fixed_point(linear_map(diag, b), std::vector<double>(50), accelerated);
  INFO("plain: " << slow.iterations << " iterations, Anderson: " << fast.iterations);
  REQUIRE(slow.converged);
  REQUIRE(fast.converged);
  // Plain iteration contracts by 0.99 per step: log(1e-10 / 100) / log(0.99) ~ 2750 steps.
  // Anderson(5) acts like restarted GMRES on the 50 spread eigenvalues (measured: ~290 steps).
  REQUIRE(slow.iterations > 2000);
  REQUIRE(fast.iterations * 5 < slow.iterations);
  REQUIRE(max_error(fast.x, diag, b) < 1e-6);
}

TEST_CASE("Damping and Anderson converge where plain iteration oscillates [eigenvalue -0.999]",
          "[theory]") {
  const std::vector<double> diag{-0.999, -0.99}, b{1.0, 1.0};
  AndersonOptions plain;
  plain.memory = 0;
  plain.max_iterations = 2000;
  const FixedPointResult oscillating = anderson_fixed_point(linear_map(diag, b), {0.0, 0.0}, plain);
  REQUIRE_FALSE(oscillating.converged);
  REQUIRE(oscillating.residual > 1e-10);
  AndersonOptions damped = plain;
  damped.damping = 0.5;  // eigenvalues 1 - 0.5 (1 + 0.999) = 5e-4 and 5e-3
  REQUIRE(anderson_fixed_point(linear_map(diag, b), {0.0, 0.0}, damped).iterations < 10);
  const FixedPointResult accelerated = anderson_fixed_point(linear_map(diag, b), {0.0, 0.0});
  REQUIRE(accelerated.converged);
  REQUIRE(accelerated.iterations < 10);
}

TEST_CASE("An iteration that runs out of steps is reported unconverged [max_iterations 10]",
          "[theory]") {
  AndersonOptions options;
  options.memory = 0;
  options.max_iterations = 10;
  const FixedPointResult r = anderson_fixed_point(linear_map({0.99}, {1.0}), {0.0}, options);
  REQUIRE_FALSE(r.converged);
  REQUIRE(r.iterations == 10);
  REQUIRE(r.residual > options.tolerance);
}

TEST_CASE("Extrapolated steps are shortened to max_step [g = 2x]", "[theory]") {
  // g(x) = 2x has the repelling fixed point 0, which the secant step finds at once; with
  // max_step 0.25 no step may be longer.
  std::vector<double> visited;
  const FixedPointMap g = [&](const std::vector<double>& x, std::vector<double>& gx) {
    visited.push_back(x[0]);
    gx[0] = 2.0 * x[0];
    return std::abs(gx[0] - x[0]);
  };
  AndersonOptions options;
  options.max_step = 0.25;
  const FixedPointResult r = anderson_fixed_point(g, {1.0}, options);
  REQUIRE(r.converged);
  REQUIRE(std::abs(r.x[0]) <= options.tolerance);
  // The first step is a damped step (no history yet): 1 -> 2. Extrapolated steps follow.
  for (std::size_t k = 2; k < visited.size(); ++k) {
    INFO("step " << k << ": " << visited[k - 1] << " -> " << visited[k]);
    REQUIRE(std::abs(visited[k] - visited[k - 1]) <= 0.25 + 1e-15);
  }
  REQUIRE(r.restarts == 0);
}

TEST_CASE("A map that returns NaN is never reported converged [NaN everywhere]", "[theory]") {
  const FixedPointMap g = [](const std::vector<double>&, std::vector<double>& gx) {
    gx[0] = std::nan("");
    return std::nan("");
  };
  AndersonOptions options;
  options.max_iterations = 20;
  const FixedPointResult r = anderson_fixed_point(g, {1.0}, options);
  REQUIRE_FALSE(r.converged);
  REQUIRE(r.iterations == 20);
}

TEST_CASE("Anderson refuses meaningless options [bad input]", "[theory]") {
  const FixedPointMap g = linear_map({0.5}, {1.0});
  AndersonOptions bad;
  bad.damping = 0.0;
  REQUIRE_THROWS_AS(anderson_fixed_point(g, {0.0}, bad), std::invalid_argument);
  bad = AndersonOptions{};
  bad.memory = -1;
  REQUIRE_THROWS_AS(anderson_fixed_point(g, {0.0}, bad), std::invalid_argument);
  REQUIRE_THROWS_AS(anderson_fixed_point(g, {}, AndersonOptions{}), std::invalid_argument);
  REQUIRE_THROWS_AS(anderson_fixed_point(FixedPointMap{}, {0.0}, AndersonOptions{}),
                    std::invalid_argument);
}

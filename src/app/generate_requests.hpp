#pragma once
// What `generate er|sf|sbm|complete|regular` is asked (the CLI's options, Python's
// hmfnet.generate keywords), each checked by one function in the CLI's words: the ranges, the
// options that exclude each other, and the parameters that can draw no edge whatever the seed
// (every reader refuses a network with no edges). Plain data: the CLI grammar binds to it in the
// fuzz build too. `output` is the CLI's file; Python leaves it empty.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

namespace hmfnet::app {

/// Erdos-Renyi G(N, q); q given directly or as the mean degree (N - 1) q.
struct ErRequest {
  int n = 0;
  std::optional<double> q, mean_degree;
  std::uint64_t seed = 0;
  std::string output;
};

/// Scale-free Chung-Lu network with power-law targets; d_min given directly or from the mean.
struct SfRequest {
  int n = 0;
  double alpha = 0.0;
  std::optional<double> d_min, mean_degree;
  double cutoff = std::numeric_limits<double>::infinity();
  std::string link = "capped";
  std::uint64_t seed = 0;
  std::string output;
};

/// Two-block stochastic block model, 2 half nodes.
struct SbmRequest {
  int half = 0;
  double p_in = 0.0, p_out = 0.0;
  std::uint64_t seed = 0;
  std::string output;
};

/// The complete graph K_N, held implicitly.
struct CompleteRequest {
  std::int64_t n = 0;
  bool self_loops = false;
  std::string output;
};

/// Random d-regular graph.
struct RegularRequest {
  int n = 0;
  int degree = 0;
  std::uint64_t seed = 0;
  std::string output;
};

/// Each throws ParameterError naming the first value refused (app/option_checks.hpp).
void validate(const ErRequest& r);
void validate(const SfRequest& r);
void validate(const SbmRequest& r);
void validate(const CompleteRequest& r);
void validate(const RegularRequest& r);

}  // namespace hmfnet::app

#pragma once
// Scale-free networks as in the paper (Sec. numericalExperiments): Chung-Lu random graphs
// (Chung, Lu & Vu 2003) whose target degrees w_n are drawn from the power law eq:powerlaw,
// P(d) ~ d^-alpha for d > d_min (continuous Pareto, optionally truncated at a cutoff).
//
// Link probability variants, all functions of x = w_n w_m / S with S = sum_n w_n:
//   capped   p = min(1, x)          plain Chung-Lu; the cap binds when w_n w_m > S, which for
//                                   N = 10^4 and alpha < 3 happens for the hubs: they get fewer
//                                   links than their target and the graph becomes
//                                   disassortative (rho < 1)
//   poisson  p = 1 - exp(-x)        Norros & Reittu (2006)
//   odds     p = x / (1 + x)        Britton, Deijfen & Martin-Lof (2006)
// No self-loops and no multi-edges. Generated in O(N + M) by the algorithm of Miller & Hagberg
// (2011): nodes sorted by decreasing target, geometric skipping with the current probability
// as an upper bound, thinning by the ratio. Node n draws from random stream n of the seed.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "network/edge_source.hpp"
#include "network/network.hpp"

namespace hmfnet {

enum class LinkProbability { capped, poisson, odds };

LinkProbability link_probability_from_name(const std::string& name);
std::string link_probability_name(LinkProbability link);

struct PowerLaw {
  double alpha = 2.5;                                       ///< exponent, > 2 (finite mean)
  double d_min = 33;                                        ///< lower end, > 0
  double cutoff = std::numeric_limits<double>::infinity();  ///< upper end, > d_min
};

/// Mean of the power law: d_min (alpha-1)/(alpha-2) times the truncation factor
/// (1 - x^(alpha-2)) / (1 - x^(alpha-1)), x = d_min / cutoff (1 without a cutoff).
double power_law_mean(const PowerLaw& law);

/// d_min giving mean `mean_degree` (closed form without cutoff: d_min = D (alpha-2)/(alpha-1);
/// with a cutoff, a bracketed root). For alpha = 2.5, 2.8, 3.1, 3.5, 3.8 and D = 100 this gives
/// 33.3, 44.4, 52.4, 60, 64.3 (the paper's Table II).
double power_law_d_min_for_mean(double alpha, double mean_degree,
                                double cutoff = std::numeric_limits<double>::infinity());

/// N targets drawn by inverse transform from random stream `stream` of `seed`.
std::vector<double> power_law_targets(NodeIndex n, const PowerLaw& law, std::uint64_t seed);

/// Chung-Lu graph with the given expected degrees (all >= 0).
Network chung_lu(const std::vector<double>& targets, LinkProbability link, std::uint64_t seed);

/// The same network unit by unit (unit a: the pairs of the a-th largest target with the smaller
/// ones), for generating it by rows over ranks. Holds the order, the sorted targets and the
/// work prefix (20 B/node).
/// Throws as chung_lu.
std::unique_ptr<EdgeSource> chung_lu_source(const std::vector<double>& targets,
                                            LinkProbability link, std::uint64_t seed);

}  // namespace hmfnet

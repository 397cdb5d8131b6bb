#pragma once
// The quasi-stationary start and the life rule shared by qss_lifetime (K_N) and qss_networks
// (the same start carried to a network): the homogeneous water-bag of Yamaguchi, Barre, Bouchet,
// Dauxois & Ruffo (Physica A 337 (2004) 36) at U = 0.69 on K_N at K = 1 (Antoni-Ruffo units),
// i.e. sigma0^2 = 2 U - 1 (U = sigma0^2 / 2 + (1 - M^2) / 2 at M = 0), and the half-way passage
// of the replica-mean R(t) (passage_time.hpp) with its smoothing and its bootstrap.
#include <cmath>

namespace hmfnet::verification::qss {

constexpr double k_U = 0.69;
constexpr int k_replicas = 16;
constexpr double k_smooth = 50.0;  ///< running-mean width and initial window, time units
constexpr int k_bootstrap = 200;   ///< resamples of the replicas for a passage's se

inline double sigma0() { return std::sqrt(2.0 * k_U - 1.0); }

}  // namespace hmfnet::verification::qss

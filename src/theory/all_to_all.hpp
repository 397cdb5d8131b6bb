#pragma once
// eq:rSigmaBesselMain when every node sees the same neighbourhood: d-regular graphs and the
// all-to-all network A_nm = 1 (self-loops included, lambda = N). Then r_n = r for all n,
// R = N r / d (eq:globalOrderParam) and r = (d/N) v(K r / mu) gives R = v(x). With lambda = d,
// K = kappa K_c = 2 kappa sigma0^2 N / d and U0 = 0, the variance equation is
// mu = sigma0^2 + K r v = sigma0^2 (1 + 2 kappa R^2), hence
//   R = v(2 kappa R / (1 + 2 kappa R^2)),   mu / sigma0^2 = 1 + 2 kappa R^2,
// a curve R(K/K_c) that depends on nothing else.
//
// Antoni & Ruffo (1995): A_nm = 1 with K = 1 is their HMF model H = sum p^2/2 +
// (1/2N) sum (1 - cos(theta_m - theta_n)) up to the constant. There M = R, T = mu, and the
// canonical equation M = I1(M/T)/I0(M/T) is the first line; T = sigma0^2 + M^2 is energy
// conservation from an incoherent start (U/N = T/2 + (1 - M^2)/2 with U/N = sigma0^2/2 + 1/2).
// K_c = 2 sigma0^2 = 1 gives T_c = 1/2 (U_c/N = 3/4).
//
// K -> infinity (eq:KtoInfinity): 2 kappa R / (1 + 2 kappa R^2) -> 1/R, so R_hat = v(1/R_hat)
// (eq:rd with every d_m equal gives the same equation).

namespace hmfnet {

/// R on the all-to-all curve for K/K_c >= 0: 0 for K/K_c <= 1 (incoherent), else the unique root
/// in (0, 1) by TOMS 748 to full double precision.
double all_to_all_order_parameter(double K_over_Kc);

/// mu / sigma0^2 = 1 + 2 (K/K_c) R^2 on the same curve.
double all_to_all_variance_ratio(double K_over_Kc);

/// R_hat = v(1/R_hat), the K -> infinity limit of the curve (~0.60).
double all_to_all_large_k_order_parameter();

}  // namespace hmfnet

#pragma once
// Bookkeeping for verification drivers: each check prints one line with our value, the
// reference, the tolerance and where the tolerance comes from, then PASS or FAIL; the driver's
// exit code is non-zero if any check failed.
#include <cmath>
#include <cstdio>
#include <string>

namespace hmfnet::verification {

class ClaimCheck {
 public:
  explicit ClaimCheck(std::string claim) : m_claim(std::move(claim)) {
    std::printf("claim: %s\n", m_claim.c_str());
  }

  /// |value - reference| <= rel_tol |reference|.
  bool within_rel(const std::string& what, double value, double reference, double rel_tol,
                  const std::string& why) {
    const double diff = (value - reference) / reference;
    return record(std::abs(diff) <= rel_tol, what, value, reference,
                  "diff " + format(100.0 * diff) + "%, tolerance " + format(100.0 * rel_tol) +
                      "% (" + why + ")");
  }

  /// A condition with its explanation (qualitative claims, orderings).
  bool holds(const std::string& what, bool ok, const std::string& detail) {
    std::printf("  %s  %s: %s\n", ok ? "PASS" : "FAIL", what.c_str(), detail.c_str());
    m_failed += ok ? 0 : 1;
    return ok;
  }

  /// A number reported beside the paper's, without a pass/fail (the paper's value is not
  /// expected to be reproduced; the reason is printed).
  void report(const std::string& what, double value, double paper, const std::string& note) {
    std::printf("  INFO  %s: ours %s, paper %s (diff %s%%) %s\n", what.c_str(),
                format(value).c_str(), format(paper).c_str(),
                format(100.0 * (value - paper) / paper).c_str(), note.c_str());
  }

  int exit_code() const {
    std::printf("%s: %d check(s) failed\n", m_failed == 0 ? "VERIFIED" : "NOT VERIFIED", m_failed);
    return m_failed == 0 ? 0 : 1;
  }

  static std::string format(double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", x);
    return buffer;
  }

 private:
  bool record(bool ok, const std::string& what, double value, double reference,
              const std::string& detail) {
    std::printf("  %s  %s: ours %s, reference %s, %s\n", ok ? "PASS" : "FAIL", what.c_str(),
                format(value).c_str(), format(reference).c_str(), detail.c_str());
    m_failed += ok ? 0 : 1;
    return ok;
  }

  std::string m_claim;
  int m_failed = 0;
};

/// `--scale full` selects the paper's sizes; the default `ci` runs what fits in CI.
inline bool full_scale(int argc, char** argv) {
  for (int k = 1; k + 1 < argc; ++k) {
    if (std::string(argv[k]) == "--scale") return std::string(argv[k + 1]) == "full";
  }
  return false;
}

}  // namespace hmfnet::verification

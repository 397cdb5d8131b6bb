#pragma once
// `spectrum`'s work on a network already read: lambda and its eigenpair's summaries, lambda_2 or
// its bounds, rho, G, structure and K_c (analysis/network_summary.hpp). The CLI prints the
// outcome, Python converts it: both walk one list of its fields (visit_spectrum_fields).
#include <vector>

#include "analysis/network_summary.hpp"
#include "app/spectrum_request.hpp"
#include "parallel/distributed_read.hpp"

namespace hmfnet::app {

struct SpectrumOutcome {
  NetworkSummary summary;
  int ranks = 1;
  std::vector<double> peak_rss_mb_per_rank;
};

/// Validates the request first. Collective over the MPI ranks; every rank gets the outcome.
SpectrumOutcome spectrum(const SpectrumRequest& request, const DistributedInput& input);

/// The outcome's fields as `spectrum --json` prints them: the summary's
/// (visit_network_summary_fields), then the run's.
template <class Visitor>
void visit_spectrum_fields(Visitor& v, const SpectrumOutcome& o) {
  visit_network_summary_fields(v, o.summary);
  v.field("ranks", o.ranks);
  v.field("peak_rss_mb_per_rank", o.peak_rss_mb_per_rank);
}

}  // namespace hmfnet::app

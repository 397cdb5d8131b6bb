#include "app/generate_requests.hpp"

#include <string>

#include "app/option_checks.hpp"
#include "core/error.hpp"
#include "network/chung_lu.hpp"

namespace hmfnet::app {

namespace {

constexpr std::int64_t k_max_nodes = 2147483647;  // NodeIndex is a 32-bit signed integer

// Options that set the same quantity two ways: exactly one of them.
void require_one_of(const char* option, bool given, const char* other, bool other_given) {
  require_not_both(option, given, other, other_given);
  if (!given && !other_given) {
    throw ParameterError("one of " + std::string(option) + " or " + other + " is required");
  }
}

// A network of one node has no pair to link (the generators make no self-loops).
void require_two_nodes(int n) {
  if (n < 2) {
    throw ParameterError("--n", "value " + std::to_string(n) + " is not allowed",
                         ">= 2; one node has no pair to link, and every reader refuses a "
                         "network with no edges");
  }
}

// No generator makes a self-loop or a multi-edge, so no node has more than n - 1 neighbours: a
// degree above that cannot be drawn. (Chung-Lu with the capped link returned a mean degree of 45
// for 100 asked on 50 nodes. Below n - 1 its hubs are still capped and the mean drawn falls short
// of the target: network/chung_lu.hpp; `generate` prints the mean drawn.)
void require_degree_at_most_n_minus_one(const char* option, double degree, int n) {
  if (degree > n - 1) {
    throw ParameterError(option, "value " + shortest_text(degree) + " is not allowed",
                         "<= n - 1 = " + std::to_string(n - 1) + " with --n " + std::to_string(n) +
                             "; a node has at most n - 1 neighbours");
  }
}

}  // namespace

void validate(const ErRequest& r) {
  require_in_range("--n", r.n, 1, k_max_nodes);
  if (r.q) require_probability("--q", *r.q);
  if (r.mean_degree) require_non_negative("--mean-degree", *r.mean_degree);
  require_one_of("--q", r.q.has_value(), "--mean-degree", r.mean_degree.has_value());
  require_two_nodes(r.n);
  if (r.mean_degree) require_degree_at_most_n_minus_one("--mean-degree", *r.mean_degree, r.n);
  const bool by_q = r.q.has_value();
  if ((by_q ? *r.q : *r.mean_degree) == 0.0) {
    throw ParameterError(by_q ? "--q" : "--mean-degree", "value 0 is not allowed",
                         std::string(by_q ? "0 < q <= 1" : "> 0") +
                             "; it links no pair, and every reader refuses a network with no "
                             "edges");
  }
}

void validate(const SfRequest& r) {
  require_in_range("--n", r.n, 1, k_max_nodes);
  require_greater_than("--alpha", r.alpha, 2.0);
  if (r.d_min) require_positive("--dmin", *r.d_min);
  if (r.mean_degree) require_positive("--mean-degree", *r.mean_degree);
  require_positive_or_inf("--cutoff", r.cutoff);
  require_member("--link", r.link, {"capped", "poisson", "odds"});
  require_one_of("--dmin", r.d_min.has_value(), "--mean-degree", r.mean_degree.has_value());
  require_two_nodes(r.n);
  if (r.d_min) {
    // The targets' mean, which d_min sets (eq:powerlaw), is what must be drawable.
    const double mean = power_law_mean({r.alpha, *r.d_min, r.cutoff});
    if (mean > r.n - 1) {
      throw ParameterError("--dmin", "value " + shortest_text(*r.d_min) + " is not allowed",
                           "a mean target degree of " + shortest_text(mean) +
                               " > n - 1 = " + std::to_string(r.n - 1) + " with --n " +
                               std::to_string(r.n) + " and --alpha " + shortest_text(r.alpha) +
                               "; a node has at most n - 1 neighbours");
    }
  }
  if (r.mean_degree) require_degree_at_most_n_minus_one("--mean-degree", *r.mean_degree, r.n);
}

void validate(const SbmRequest& r) {
  require_in_range("--half", r.half, 1, k_max_nodes / 2);
  require_probability("--p-in", r.p_in);
  require_probability("--p-out", r.p_out);
  if (r.p_in == 0.0 && r.p_out == 0.0) {
    throw ParameterError("--p-in, --p-out", "values 0 and 0 are not allowed",
                         "p_in > 0 or p_out > 0; they link no pair, and every reader refuses a "
                         "network with no edges");
  }
  if (r.half == 1 && r.p_out == 0.0) {
    throw ParameterError("--p-out", "value 0 is not allowed with --half 1",
                         "> 0; blocks of one node have no pair inside, and every reader refuses "
                         "a network with no edges");
  }
}

void validate(const CompleteRequest& r) { require_in_range("--n", r.n, 2, k_max_nodes); }

// d >= 1 gives n d / 2 edges exactly: a regular draw is never empty. The pairing's own limit
// n d even is network/random_regular.hpp's.
void validate(const RegularRequest& r) {
  require_in_range("--n", r.n, 1, k_max_nodes);
  require_in_range("--degree", r.degree, 0, k_max_nodes - 1);
  require_two_nodes(r.n);
  if (r.degree == 0) {
    throw ParameterError("--degree", "value 0 is not allowed",
                         "1 <= d <= n - 1 = " + std::to_string(r.n - 1) +
                             "; d = 0 gives no edges, and every reader refuses a network with no "
                             "edges");
  }
  require_degree_at_most_n_minus_one("--degree", r.degree, r.n);
}

}  // namespace hmfnet::app

// Verification: Table I of the paper (tab:booktabs), largest eigenvalue of Erdos-Renyi networks.
//
// Claim: ER networks with N = 10^4 and mean degree ||d|| = 100, 50, 30, 20, 10 have
//   lambda = 101, 51.1, 31.1, 20.1, 11.1 (and lambda ~ ||d|| + 1 in general);
//   at full scale also N = 2.5e4, ||d|| = 5000, printed as 4999 (an ER graph of that density
//   has lambda ~ ||d|| + 1 = 5001: we report the difference, PAPER_NOTES.md).
// Erratum found here: for ||d|| = 20 the paper prints 20.1, but every other row follows
//   lambda = ||d|| + 1.1 and ER theory gives ||d|| + 1 (21.1): we measure 21.17 on every seed.
//   That row is checked against ||d|| + 1 and the paper's 20.1 is reported beside it.
// Run:   verification_table1_er_lambda [--scale ci|full]   (ctest -L verification)
// Reference: the paper's printed lambda.
// Tolerance: 1%. The paper prints 3 significant digits (rounding up to 0.5%), and lambda of
//   G(N, q) fluctuates by O(sqrt(q(1-q))) << 1 between realisations (Furedi & Komlos 1981), while
//   the realised mean degree differs from ||d|| by O(sqrt(2 ||d|| / N)) ~ 0.1 for ||d|| = 100.
#include <cstdio>
#include <string>
#include <vector>

#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"

using namespace hmfnet;

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  verification::ClaimCheck check("table1_er_lambda",
                                 "Table I: lambda of Erdos-Renyi networks (lambda ~ ||d|| + 1)",
                                 argc, argv);
  const bool full = check.full();
  struct Row {
    NodeIndex n;
    double mean_degree;
    double paper_lambda;
    bool misprinted;  // paper's value contradicts lambda ~ ||d|| + 1 (see header)
  };
  const Row rows[] = {{10000, 100, 101, false}, {10000, 50, 51.1, false},
                      {10000, 30, 31.1, false}, {10000, 20, 20.1, true},
                      {10000, 10, 11.1, false}, {25000, 5000, 4999, true}};
  const std::uint64_t seed = 2024;
  int status = 0;
  {
    std::vector<double> table;  // rows of: N, ||d||, realised ||d||, lambda, paper lambda
    for (const Row& row : rows) {
      if (row.mean_degree > 1000 && !full) continue;  // 1.25e8 nnz: full scale only
      // Step 1: the network, seeded; Step 2: lambda with Anasazi; Step 3: compare.
      const Network net =
          erdos_renyi({row.n, erdos_renyi_probability(row.n, row.mean_degree), seed});
      const DistributedNetwork distributed(net);
      const PerronResult perron = perron_eigenpair(distributed);
      char what[96];
      std::snprintf(what, sizeof what, "lambda N=%d <d>=%g (realised <d>=%.3f, residual %.1e)",
                    row.n, row.mean_degree, mean_degree(net), perron.residual);
      if (row.misprinted) {
        check.report(what, perron.lambda, row.paper_lambda,
                     "(paper's value contradicts lambda ~ ||d|| + 1; checked against that)");
        check.within_rel(std::string(what) + " vs realised ||d||+1", perron.lambda,
                         mean_degree(net) + 1.0, 0.01, "ER: lambda ~ ||d|| + 1 + O(1/||d||)");
      } else {
        check.within_rel(what, perron.lambda, row.paper_lambda, 0.01,
                         "3 printed digits; realisation spread O(0.1)");
      }
      table.insert(table.end(), {static_cast<double>(row.n), row.mean_degree, mean_degree(net),
                                 perron.lambda, row.paper_lambda});
    }
    check.data("table", table, table.size() / 5,
               {"N", "mean degree", "realised mean degree", "lambda", "paper lambda"});
    status = check.exit_code();
  }
  return status;
}

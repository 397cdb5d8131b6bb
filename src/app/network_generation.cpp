#include "app/network_generation.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <utility>

#include "app/provenance.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/network_file.hpp"
#include "network/chung_lu.hpp"
#include "network/erdos_renyi.hpp"
#include "network/random_regular.hpp"
#include "network/stochastic_block.hpp"
#include "parallel/distributed_generation.hpp"
#include "parallel/distributed_network_file.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet::app {

namespace {

// Every reader refuses a network with no edges (network/network_builder.cpp, io/network_hdf5.cpp),
// so a generator must not write one. Parameters that can only give none are refused by the
// request's check (generate_requests.cpp); a draw that came out empty although edges were possible
// (N = 2, q = 0.01) is refused after generating, before anything is written, through
// ParallelSession::agree: one report.
[[noreturn]] void refuse_empty_draw(const std::string& options, NodeIndex n, std::uint64_t seed) {
  throw ParameterError(options,
                       "the network drawn (N = " + std::to_string(n) + ", seed " +
                           std::to_string(seed) + ") has no edges",
                       "parameters that draw at least one edge, since every reader refuses a "
                       "network with no edges; raise them, or try another --seed");
}

// What one generator makes: its edges by rows (the distributed HDF5 path), the same network whole
// on one rank (the text path; possibly faster), the provenance its file records, and the refusal
// of a draw that came out with no edges (naming the options that set the edge density).
struct Generation {
  std::shared_ptr<const EdgeSource> source;
  std::function<Network()> whole;
  std::string provenance;
  std::function<void()> refuse_empty;
};

std::function<void()> empty_draw_refusal(std::string options, NodeIndex n, std::uint64_t seed) {
  return [options = std::move(options), n, seed] { refuse_empty_draw(options, n, seed); };
}

Generation generation(const ErRequest& r) {
  validate(r);
  const double q = r.q ? *r.q : erdos_renyi_probability(r.n, *r.mean_degree);
  const ErdosRenyiParameters params{r.n, q, r.seed};
  return {erdos_renyi_source(params), [params] { return erdos_renyi(params); },
          provenance("generate er", {{"n", r.n}, {"q", q}, {"seed", r.seed}}),
          empty_draw_refusal(r.q ? "--q" : "--mean-degree", r.n, r.seed)};
}

Generation generation(const SfRequest& r) {
  validate(r);
  const double d_min =
      r.d_min ? *r.d_min : power_law_d_min_for_mean(r.alpha, *r.mean_degree, r.cutoff);
  const PowerLaw law{r.alpha, d_min, r.cutoff};
  std::shared_ptr<const EdgeSource> source = chung_lu_source(
      power_law_targets(r.n, law, r.seed), link_probability_from_name(r.link), r.seed);
  nlohmann::json p = {
      {"n", r.n}, {"alpha", r.alpha}, {"d_min", d_min}, {"link", r.link}, {"seed", r.seed}};
  p["cutoff"] = std::isinf(r.cutoff) ? nlohmann::json("none") : nlohmann::json(r.cutoff);
  return {source, [source] { return network_from_source(*source); }, provenance("generate sf", p),
          empty_draw_refusal(r.d_min ? "--dmin" : "--mean-degree", r.n, r.seed)};
}

Generation generation(const SbmRequest& r) {
  validate(r);
  std::shared_ptr<const EdgeSource> source =
      two_block_sbm_source({r.half, r.p_in, r.p_out, r.seed});
  return {source, [source] { return network_from_source(*source); },
          provenance("generate sbm",
                     {{"half", r.half}, {"p_in", r.p_in}, {"p_out", r.p_out}, {"seed", r.seed}}),
          empty_draw_refusal("--p-in, --p-out", 2 * r.half, r.seed)};
}

Generation generation(const RegularRequest& r) {
  validate(r);
  const RandomRegularParameters params{r.n, r.degree, r.seed};
  return {random_regular_source(params), [params] { return random_regular(params); },
          provenance("generate regular", {{"n", r.n}, {"degree", r.degree}, {"seed", r.seed}}),
          empty_draw_refusal("--degree", r.n, r.seed)};
}

template <class Request>
GeneratedNetwork whole_network(const Request& r) {
  const Generation g = generation(r);
  Network net = g.whole();
  if (net.nnz() == 0) g.refuse_empty();
  return {std::move(net), g.provenance};
}

// Generates and writes the network of `g` to `path`.
GeneratedFile write_generation(const Generation& g, const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  GeneratedFile file;
  file.path = path;
  file.n = g.source->nodes();
  if (format_from_extension(path) == NetworkFormat::hdf5) {
    const RowBlock block = generate_distributed(*g.source);
    std::vector<std::uint64_t> total{static_cast<std::uint64_t>(block.nnz())};
    ParallelSession::sum_in_place(total);
    file.nnz = static_cast<EdgeOffset>(total[0]);
    // Every rank holds the same sum: agree reports the refusal once, not once per rank.
    ParallelSession::agree([&] {
      if (file.nnz == 0) g.refuse_empty();
    });
    write_distributed_network_hdf5(path, block, g.provenance);
  } else {
    // Rank 0 alone builds and writes it; a failure there ends every rank.
    ParallelSession::agree([&] {
      if (ParallelSession::rank() != 0) return;
      const Network net = g.whole();
      file.nnz = net.nnz();
      if (file.nnz == 0) g.refuse_empty();
      write_network(path, net, g.provenance);
    });
  }
  file.edges = file.nnz / 2;
  file.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  file.ranks = ParallelSession::ranks();
  file.peak_rss_mb_per_rank = ParallelSession::peak_memory_mb();  // collective
  return file;
}

template <class Request>
GeneratedFile generate_stored(const Request& r) {
  format_from_extension(r.output);  // an unknown extension is refused before any work
  require_writable_destination(r.output);
  // Every rank checks the same parameters: agree reports a refusal once, not once per rank.
  Generation g;
  ParallelSession::agree([&] { g = generation(r); });
  return write_generation(g, r.output);
}

}  // namespace

GeneratedNetwork generated_network(const ErRequest& r) { return whole_network(r); }
GeneratedNetwork generated_network(const SfRequest& r) { return whole_network(r); }
GeneratedNetwork generated_network(const SbmRequest& r) { return whole_network(r); }
GeneratedNetwork generated_network(const RegularRequest& r) { return whole_network(r); }

GeneratedFile generate_file(const ErRequest& r) { return generate_stored(r); }
GeneratedFile generate_file(const SfRequest& r) { return generate_stored(r); }
GeneratedFile generate_file(const SbmRequest& r) { return generate_stored(r); }
GeneratedFile generate_file(const RegularRequest& r) { return generate_stored(r); }

GeneratedFile generate_file(const CompleteRequest& r) {
  validate(r);
  const auto start = std::chrono::steady_clock::now();
  const CompleteGraph graph = CompleteGraph::make(r.n, r.self_loops);
  require_complete_graph_format(r.output);
  require_writable_destination(r.output);
  if (ParallelSession::rank() == 0) {
    write_complete_graph(
        r.output, graph,
        provenance("generate complete", {{"n", r.n}, {"self_loops", r.self_loops}}));
  }
  GeneratedFile file;
  file.path = r.output;
  file.n = graph.n;
  file.edges = graph.edges();
  file.nnz = graph.nnz();
  file.implicit = true;
  file.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  file.ranks = ParallelSession::ranks();
  return file;
}

}  // namespace hmfnet::app

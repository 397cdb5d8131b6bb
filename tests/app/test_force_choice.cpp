// The force choice (app/force_choice.hpp) has two doors: the file read by the CLI and Python
// (DistributedInput, K_N named by the reader) and a network the verification drivers and
// benchmarks distribute themselves (K_N recognised by its having no stored rows). Both must pick
// the same force with the same bits and refuse the same choices in the same words, so that a
// driver checks the force a user's run gets.
#include <catch2/catch.hpp>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/force_choice.hpp"
#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/rotor_state.hpp"
#include "network/complete_graph.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/distributed_read.hpp"

using namespace hmfnet;

namespace {

// The message of the ParameterError `choose` throws, or "accepted".
std::string refusal(const std::function<void()>& choose) {
  try {
    choose();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "accepted";
}

// g of `force` at an incoherent start of two replicas on this rank's rows.
std::vector<double> field(CouplingForce& force, const DistributedNetwork& d) {
  const RotorState s =
      initial_state(d.first_row(), d.local_size(), {{6.0, 0.35, 1}, {6.0, 0.35, 2}});
  ForceEvaluation f(force);
  f.update(s);
  return f.g();
}

DistributedInput complete_input(const CompleteGraph& graph) {
  DistributedInput input;
  input.network = std::make_unique<DistributedNetwork>(graph);
  input.complete = graph;
  return input;
}

DistributedInput stored_input(const Network& net) {
  DistributedInput input;
  input.network = std::make_unique<DistributedNetwork>(net);
  return input;
}

}  // namespace

TEST_CASE("Force choice: K_N held implicitly, the same rank-one force through either door [N=300]",
          "[app][force_choice]") {
  for (const bool loops : {false, true}) {
    INFO("self-loops " << loops);
    const CompleteGraph graph = CompleteGraph::make(300, loops);
    const DistributedInput input = complete_input(graph);
    const DistributedNetwork d(graph);
    for (const std::string force : {"auto", "rank-one"}) {
      INFO("force " << force);
      const auto from_input = app::choose_force(force, "float64", input);
      const auto from_network = app::choose_force(force, "float64", d);
      REQUIRE(std::string(from_network->name()) == "rank-one");
      REQUIRE(std::string(from_input->name()) == from_network->name());
      REQUIRE(field(*from_network, d) == field(*from_input, *input.network));
    }
  }
}

TEST_CASE("Force choice: a stored network, the same force through either door [ER, stored K_N]",
          "[app][force_choice]") {
  const Network er = erdos_renyi({400, 0.05, 3});
  const Network complete = CompleteGraph::make(40, false).materialise();
  struct Case {
    const Network* net;
    std::string force, precision, name;
  };
  // A stored K_N is a a^T: auto gives it the exact O(N) force; sparse still names the kernel.
  const std::vector<Case> cases = {
      {&er, "auto", "float64", "sparse"},         {&er, "sparse", "float64", "sparse"},
      {&er, "auto", "float32", "sparse-float32"}, {&er, "sparse", "float32", "sparse-float32"},
      {&complete, "auto", "float64", "rank-one"}, {&complete, "rank-one", "float64", "rank-one"},
      {&complete, "sparse", "float64", "sparse"}};
  for (const Case& c : cases) {
    INFO("N " << c.net->size() << ", force " << c.force << ", precision " << c.precision);
    const DistributedInput input = stored_input(*c.net);
    const DistributedNetwork d(*c.net);
    const auto from_input = app::choose_force(c.force, c.precision, input);
    const auto from_network = app::choose_force(c.force, c.precision, d);
    REQUIRE(std::string(from_network->name()) == c.name);
    REQUIRE(std::string(from_input->name()) == c.name);
    REQUIRE(field(*from_network, d) == field(*from_input, *input.network));
  }
}

TEST_CASE("Force choice: both doors refuse the same choices in the same words [K_N, ER]",
          "[app][force_choice]") {
  const CompleteGraph graph = CompleteGraph::make(50, false);
  const DistributedInput complete = complete_input(graph);
  const DistributedInput er = stored_input(erdos_renyi({200, 0.05, 4}));
  struct Case {
    const DistributedInput* input;
    std::string force, precision;
  };
  const std::vector<Case> cases = {{&complete, "sparse", "float64"},
                                   {&complete, "auto", "float32"},
                                   {&er, "rank-one", "float64"},
                                   {&er, "rank-one", "float32"},
                                   {&er, "auto", "float16"}};
  for (const Case& c : cases) {
    INFO("force " << c.force << ", precision " << c.precision);
    const std::string from_input =
        refusal([&] { app::choose_force(c.force, c.precision, *c.input); });
    const std::string from_network =
        refusal([&] { app::choose_force(c.force, c.precision, *c.input->network); });
    REQUIRE(from_input != "accepted");
    REQUIRE(from_network == from_input);
  }
}

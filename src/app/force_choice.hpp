#pragma once
// Which coupling force integrates a network (the CLI's --force and --precision, Python's force=
// and precision=, and the force each verification driver and benchmark names): the complete
// graph held implicitly has only the O(N) rank-one force; under "auto" a network with A = a a^T
// gets it too (exact, O(N) per step), and every other network the sparse kernel at the asked
// precision. One choice for every caller, so a driver checks the force a user's run gets.
#include <memory>
#include <string>

#include "dynamics/coupling_force.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/distributed_read.hpp"

namespace hmfnet::app {

/// `force`: auto, sparse or rank-one; `precision`: float64 or float32. Throws ParameterError when
/// the network cannot take the choice (sparse on the implicit K_N, rank-one on a network that is
/// not a a^T, float32 with the rank-one force). Collective (the rank-one test reads every row).
std::unique_ptr<CouplingForce> choose_force(const std::string& force, const std::string& precision,
                                            const DistributedInput& input);

/// The same choice for a network the caller distributed itself (the verification drivers and
/// benchmarks): K_N held implicitly (DistributedNetwork(CompleteGraph)) is recognised by its
/// having no stored rows. The force may keep a reference to `network`, which must outlive it.
/// Same errors as above; collective.
std::unique_ptr<CouplingForce> choose_force(const std::string& force, const std::string& precision,
                                            const DistributedNetwork& network);

}  // namespace hmfnet::app

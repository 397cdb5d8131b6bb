#include "app/read_request.hpp"

#include "app/option_checks.hpp"

namespace hmfnet::app {

void validate(const ReadRequest& r) {
  require_member("--index-base", r.index_base, {0, 1});
  require_non_negative("--nodes", r.nodes);
}

ReadOptions read_options(const ReadRequest& r) {
  ReadOptions o;
  o.asymmetry = r.symmetrize ? AsymmetryPolicy::symmetrize : AsymmetryPolicy::reject;
  o.edge_list_base = r.index_base;
  o.edge_list_nodes = r.nodes;
  return o;
}

}  // namespace hmfnet::app

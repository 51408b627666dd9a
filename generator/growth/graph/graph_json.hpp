#pragma once
// The branch graph as JSON (format "arbor-graph/1", documented in docs/graph-format.md).
#include <string>

#include "branch_graph.hpp"

namespace arbor {

// Reads and validates a graph; every refusal is an InputError (GraphError for what makes it no tree) naming
// `file`, the node id or field, and what is allowed.
BranchGraph readBranchGraphJson(const std::string& text, const std::string& file);

std::string writeBranchGraphJson(const BranchGraph& graph);

}  // namespace arbor

#pragma once
// Space colonization behind the growth-model interface: a "space-colonization" JSON file as a TreeModel
// (docs/space-colonization-format.md), grown to the end, its enabled nodes a branch graph, then a skeleton.
#include <cstdint>
#include <string>

#include "colonizer.hpp"
#include "growth/graph/branch_graph.hpp"
#include "growth/growth_model.hpp"
#include "space_colonization.hpp"

namespace arbor {

inline constexpr const char* kSpaceColonizationModel = "space-colonization";

// Reads a model file (InputError naming the field, exit 2). Refuses options.naturalAngles: no angle rules here.
TreeModel readSpaceColonizationModel(const std::string& text, const std::string& file, const ModelReadOptions& options = {});

// The parameters behind a model with its edits; nullptr when another model grew it.
const sc::SpaceColonization* spaceColonizationOf(const TreeModel& model);

// The model's trunk, obstacles and clouds, not grown yet; the points' seed is the file's + seed - 1.
sc::Colonizer startColonizer(const sc::SpaceColonization& model, std::uint64_t seed);

// The enabled nodes as a branch graph: the trunk at least trunkWidth thick (the pipe model does the rest in
// graphToSkeleton), and one leaf on every node at most leafDepth segments above a tip (the last orders' twigs).
BranchGraph colonizationGraph(const sc::Colonizer& colonizer, const sc::SpaceColonization& model);

GraphOptions colonizationGraphOptions(const sc::SpaceColonization& model);

}  // namespace arbor

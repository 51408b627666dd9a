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

// A random valid model for stress tests, the same for the same seed: one to four clouds of random shapes, half
// extents (about 0.8 to 3 m) and point counts (200 to 2,000) over a trunk they reach, influence and kill radii scaled to
// D and to the points' spacing, up to two box or sphere obstacles clear of the trunk, random radii and leaves.
TreeModel randomSpaceColonizationModel(std::uint64_t seed);

// The parameters behind a model with its edits; nullptr when another model grew it.
const sc::SpaceColonization* spaceColonizationOf(const TreeModel& model);

// The model's trunk, obstacles and clouds, not grown yet; the points' seed is the file's + seed - 1.
sc::Colonizer startColonizer(const sc::SpaceColonization& model, std::uint64_t seed);

// The enabled nodes as a branch graph: the trunk at least trunkWidth thick (the pipe model does the rest in
// graphToSkeleton), and one leaf on every node at most leafDepth segments above a tip (the last orders' twigs).
BranchGraph colonizationGraph(const sc::Colonizer& colonizer, const sc::SpaceColonization& model);

GraphOptions colonizationGraphOptions(const sc::SpaceColonization& model);

// The colonizer's state as an arbor-graph/1 file (docs/graph-format.md): the enabled nodes, each with its
// pipe-model radius from the model's radii.tip and radii.exponent (the format carries neither), and the leaves.
// Node ages are not written: the format has no field for them.
std::string writeColonizationGraph(const sc::Colonizer& colonizer, const sc::SpaceColonization& model);

// Throws GenerationError (exit 2) once the colonizer holds more nodes than the limit allows: growth checks
// between slices, so a tree past it is refused before it has used all the time and memory.
void requireNodeLimit(const sc::Colonizer& colonizer, const sc::SpaceColonization& model, const TreeLimits& limits);

// The colonizer's state as the skeleton the model grows (its enabled nodes, pipe-model radii, leaves), seed
// recorded; GenerationError past the leaf limit.
Skeleton colonizationSkeleton(const sc::Colonizer& colonizer, const sc::SpaceColonization& model, std::uint64_t seed, const TreeLimits& limits);

}  // namespace arbor

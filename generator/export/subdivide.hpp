#pragma once
// Catmull-Clark subdivision with OpenSubdiv, for artists who want the smooth surface as plain quads
// (the engine tessellates on the GPU instead and never needs this).
#include <cstddef>

#include "growth/tree_limits.hpp"
#include "mesh/quad_mesh.hpp"

namespace arbor {

// Refines `mesh` uniformly `levels` times (1..6; the quad count grows 4^levels) with edge-only boundary
// interpolation, so an open ring at the trunk base stays where it is instead of shrinking.
//
// Positions are projected onto the limit surface; normals come from the limit tangents; tangents are the
// refined input tangents at the limit, made orthogonal to the normal (still "along the branch"). uvw and
// radius are interpolated with the same vertex weights, level is interpolated and rounded to the nearest.
// Quads keep the input's counter-clockwise-from-outside orientation. openBoundary, when the input has one,
// becomes the refined ring in the same order and direction (2^levels times as many vertices).
//
// Needs positions, tangents, uvw, radius and level for every vertex (normals are recomputed and may be
// empty). Throws std::invalid_argument for a malformed mesh, openBoundary or level count, and
// std::runtime_error for anything OpenSubdiv reports as an error or warning and for non-manifold edges or
// vertices (which OpenSubdiv would otherwise accept silently), so a bad mesh is never smoothed into
// something plausible-looking. Calls are serialised internally: OpenSubdiv's callbacks are process-wide.
// A result of more than maxQuads quads is refused (LimitError) before anything is refined.
QuadMesh subdivide(const QuadMesh& mesh, int levels, std::size_t maxQuads = TreeLimits{}.quads);

}  // namespace arbor

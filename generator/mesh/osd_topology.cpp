#include "osd_topology.hpp"

#include <climits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <opensubdiv/far/error.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

namespace arbor {

namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;
using RefinerFactory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;

std::recursive_mutex diagnosticsMutex;  // the callbacks are process-wide: one owner at a time
std::string reportedMessages;

void collectError(Far::ErrorType, const char* message) {
  reportedMessages += reportedMessages.empty() ? "" : "; ";
  reportedMessages += message;
}

void collectWarning(const char* message) { collectError(Far::FAR_RUNTIME_ERROR, message); }

// OpenSubdiv refines non-manifold topology without complaint, but in a tree mesh it is always a builder bug.
void requireManifold(const Far::TopologyLevel& base, const char* context) {
  for (Far::Index e = 0; e < base.GetNumEdges(); ++e) {
    if (!base.IsEdgeNonManifold(e)) continue;
    const auto ends = base.GetEdgeVertices(e);
    throw std::runtime_error(std::string(context) + ": the edge between vertices " + std::to_string(ends[0]) + " and " +
                             std::to_string(ends[1]) + " is non-manifold (" + std::to_string(base.GetEdgeFaces(e).size()) +
                             " faces, or faces of opposite orientation, or a repeated vertex)");
  }
  for (Far::Index v = 0; v < base.GetNumVertices(); ++v) {
    if (base.IsVertexNonManifold(v)) {
      throw std::runtime_error(std::string(context) + ": vertex " + std::to_string(v) +
                               " is non-manifold (faces around it do not form one fan)");
    }
  }
}

}  // namespace

namespace detail {

OsdDiagnostics::OsdDiagnostics() {
  diagnosticsMutex.lock();
  reportedMessages.clear();
  Far::SetErrorCallback(&collectError);
  Far::SetWarningCallback(&collectWarning);
}

OsdDiagnostics::~OsdDiagnostics() {
  // OpenSubdiv cannot say which callback was there before; null restores its own printing default.
  Far::SetErrorCallback(nullptr);
  Far::SetWarningCallback(nullptr);
  diagnosticsMutex.unlock();
}

void OsdDiagnostics::throwIfReported(const char* context, const char* stage) const {
  if (!reportedMessages.empty()) {
    throw std::runtime_error(std::string(context) + ": OpenSubdiv " + stage + ": " + reportedMessages);
  }
}

}  // namespace detail

std::unique_ptr<Far::TopologyRefiner> makeTopologyRefiner(const QuadMesh& mesh, const char* context) {
  for (std::size_t f = 0; f < mesh.quads.size(); ++f) {
    for (const std::uint32_t v : mesh.quads[f]) {
      if (v >= mesh.vertexCount()) {  // OpenSubdiv does not check, and would read out of bounds
        throw std::invalid_argument(std::string(context) + ": quad " + std::to_string(f) + " refers to vertex " +
                                    std::to_string(v) + " of " + std::to_string(mesh.vertexCount()));
      }
    }
  }
  if (mesh.quads.size() > INT_MAX / 4 || mesh.vertexCount() > INT_MAX) {
    throw std::invalid_argument(std::string(context) + ": too many quads or vertices for OpenSubdiv's int indices");
  }
  std::vector<int> faceSizes(mesh.quads.size(), 4);
  std::vector<int> faceVertices;
  faceVertices.reserve(mesh.quads.size() * 4);
  for (const auto& q : mesh.quads) {
    for (const std::uint32_t v : q) faceVertices.push_back(static_cast<int>(v));
  }
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = static_cast<int>(mesh.vertexCount());
  descriptor.numFaces = static_cast<int>(mesh.quads.size());
  descriptor.numVertsPerFace = faceSizes.data();
  descriptor.vertIndicesPerFace = faceVertices.data();

  Sdc::Options scheme;
  scheme.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  RefinerFactory::Options options(Sdc::SCHEME_CATMARK, scheme);
  options.validateFullTopology = true;  // checks OpenSubdiv skips by default; findings arrive through the callbacks

  std::unique_ptr<Far::TopologyRefiner> refiner;
  withOsdDiagnostics(context, "rejected the mesh", [&] { refiner.reset(RefinerFactory::Create(descriptor, options)); });
  if (!refiner) throw std::runtime_error(std::string(context) + ": OpenSubdiv could not build a refiner for the mesh");
  requireManifold(refiner->GetLevel(0), context);
  return refiner;
}

}  // namespace arbor

#pragma once
// OpenSubdiv's view of a QuadMesh: a Catmull-Clark topology refiner, built with full validation and with
// every OpenSubdiv diagnostic turned into an exception (it would otherwise print and go on).
#include <memory>

#include <opensubdiv/far/topologyRefiner.h>

#include "quad_mesh.hpp"

namespace arbor {

// Throws std::invalid_argument for indices out of range, std::runtime_error (starting with `context`)
// when OpenSubdiv reports a problem or the mesh is not manifold. Boundaries interpolate edges only.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> makeTopologyRefiner(const QuadMesh& mesh, const char* context);

// Runs `work` with OpenSubdiv's error and warning callbacks collecting messages, and throws them after it
// returns (OpenSubdiv must not be unwound through). One caller at a time: the callbacks are process-wide.
template <class Work>
void withOsdDiagnostics(const char* context, const char* stage, Work&& work);

namespace detail {
class OsdDiagnostics {
 public:
  OsdDiagnostics();
  ~OsdDiagnostics();
  OsdDiagnostics(const OsdDiagnostics&) = delete;
  OsdDiagnostics& operator=(const OsdDiagnostics&) = delete;
  void throwIfReported(const char* context, const char* stage) const;
};
}  // namespace detail

template <class Work>
void withOsdDiagnostics(const char* context, const char* stage, Work&& work) {
  const detail::OsdDiagnostics diagnostics;
  work();
  diagnostics.throwIfReported(context, stage);
}

}  // namespace arbor

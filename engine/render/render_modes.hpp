#pragma once
// The render modes, one row each: what the CLI, the viewer panel, the benchmark and the renderer know of a
// mode comes from this table (a new mode is a new row, its shaders and its enumerator).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace arbor::render {

enum class RenderMode { Flat, PN, ACC };

// What a tessellated mode draws per patch.
enum class PatchPrimitive { None, Triangle, Quad };

struct SpirvCode {
  const std::uint32_t* words = nullptr;
  std::size_t bytes = 0;
};

struct RenderModeInfo {
  RenderMode mode;
  const char* name;          // as the CLI, the panel, the benchmark and CSV files spell it
  const char* summary;       // one line for --help and the panel's tooltip
  PatchPrimitive primitive;  // None: the triangulated mesh drawn indexed, without tessellation
  std::uint32_t controlVec4s;  // control record per patch (interface.h); 0 for untessellated modes
  SpirvCode vertex, control, evaluation;  // control and evaluation empty when untessellated
  SpirvCode build;           // compute: control points once per mesh (tessellated modes)
  SpirvCode corners;         // vertex: patches whose factors are all 1, drawn without the tessellator
  std::uint32_t cornerVertices;  // vertices per such patch (two triangles for a quad)
  bool captures;             // the evaluation stage can write the points it evaluates (tests; ARBOR_SPEC_CAPTURE)
};

constexpr std::size_t kRenderModeCount = 3;
const std::array<RenderModeInfo, kRenderModeCount>& renderModes();
const RenderModeInfo& renderModeInfo(RenderMode mode);
inline const char* renderModeName(RenderMode mode) { return renderModeInfo(mode).name; }
inline bool isTessellated(RenderMode mode) { return renderModeInfo(mode).primitive != PatchPrimitive::None; }
std::optional<RenderMode> findRenderMode(std::string_view name);
// "flat, pn, acc": for error messages and help texts.
std::string renderModeList();

}  // namespace arbor::render

#include "render_modes.hpp"

#include "spirv_acc_control_comp.h"
#include "spirv_acc_corners_vert.h"
#include "spirv_acc_tesc.h"
#include "spirv_acc_tese.h"
#include "spirv_flat_vert.h"
#include "spirv_patch_vert.h"
#include "spirv_pn_control_comp.h"
#include "spirv_pn_corners_vert.h"
#include "spirv_pn_tesc.h"
#include "spirv_pn_tese.h"
#include "interface.h"

namespace arbor::render {

namespace {

template <std::size_t N>
constexpr SpirvCode code(const std::uint32_t (&words)[N]) {
  return SpirvCode{words, sizeof(words)};
}

}  // namespace

const std::array<RenderModeInfo, kRenderModeCount>& renderModes() {
  static const std::array<RenderModeInfo, kRenderModeCount> modes{{
      {RenderMode::Flat, "flat", "the quad mesh as triangles, no tessellation", PatchPrimitive::None, 0, code(spirv_flat_vert), {}, {}, {}, {}, 0, false},
      {RenderMode::PN, "pn", "PN-triangles: a cubic triangle per mesh triangle (Vlachos et al. 2001)", PatchPrimitive::Triangle,
       ARBOR_PN_CONTROL_VEC4S, code(spirv_patch_vert), code(spirv_pn_tesc), code(spirv_pn_tese), code(spirv_pn_control_comp),
       code(spirv_pn_corners_vert), 3, false},
      {RenderMode::ACC, "acc", "approximate Catmull-Clark: a bicubic patch per quad (Loop & Schaefer 2008)", PatchPrimitive::Quad,
       ARBOR_ACC_CONTROL_VEC4S, code(spirv_patch_vert), code(spirv_acc_tesc), code(spirv_acc_tese), code(spirv_acc_control_comp),
       code(spirv_acc_corners_vert), 6, true},
  }};
  return modes;
}

const RenderModeInfo& renderModeInfo(RenderMode mode) { return renderModes()[static_cast<std::size_t>(mode)]; }

std::optional<RenderMode> findRenderMode(std::string_view name) {
  for (const RenderModeInfo& m : renderModes()) {
    if (name == m.name) return m.mode;
  }
  return std::nullopt;
}

std::string renderModeList() {
  std::string list;
  for (const RenderModeInfo& m : renderModes()) list += (list.empty() ? "" : ", ") + std::string(m.name);
  return list;
}

}  // namespace arbor::render

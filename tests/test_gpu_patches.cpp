// The GPU-driven patch path (issue 17): control points built once per mesh by compute against the CPU
// references, the culling pass against the test's own frustum and normal-cone computation, bucketed draws
// against the unbucketed path, every draw within lavapipe's limits, and culling that changes no pixel.
#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <set>

#include "image/image_compare.hpp"
#include "mesh/tree_mesh.hpp"
#include "patches/acc.hpp"
#include "patches/pn_triangle.hpp"
#include "tree/wind.hpp"
#include "mesh_support.hpp"
#include "render_support.hpp"
#include "test_support.hpp"

using namespace arbor;

namespace {

constexpr std::uint32_t kWidth = 96, kHeight = 128;

// One frame of `preset` framed whole in `session`, which holds the tree afterwards.
render::FrameResult drawOnce(render::RenderSession& session, const render::RenderSettings& settings, const render::Camera* camera = nullptr) {
  const float aspect = static_cast<float>(kWidth) / static_cast<float>(kHeight);
  return session.render(camera ? *camera : render::frameBounds(render::plantedBounds(*session.tree()), 25.0f, 6.0f, aspect), settings);
}

double worstRelative(const glm::vec3& gpu, const glm::dvec3& cpu) {
  const glm::dvec3 d = glm::dvec3(gpu) - cpu;
  return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) / (1.0 + glm::length(cpu));
}

// Tessellated vertices of one patch at these outer factors, inner levels as the control stages set them
// (the finer outer level along each direction), counted as the Vulkan spec's equal spacing makes them.
std::uint64_t tessellatedVertices(bool quad, const std::array<std::uint32_t, 4>& f) {
  if (quad) {
    std::uint64_t inner0 = std::max(f[1], f[3]), inner1 = std::max(f[0], f[2]);
    const bool allOne = inner0 == 1 && inner1 == 1 && f[0] == 1 && f[2] == 1;
    if (allOne) return 4;
    inner0 = std::max<std::uint64_t>(inner0, 2), inner1 = std::max<std::uint64_t>(inner1, 2);  // 1 + epsilon rounds up
    return f[0] + f[1] + f[2] + f[3] + (inner0 - 1) * (inner1 - 1);
  }
  const std::uint64_t inner = std::max({f[0], f[1], f[2]});
  if (inner == 1) return 3;
  // Inside the outer ring, the rings of a uniform triangle at the inner level: all its points but its own 3 L.
  const std::uint64_t uniform = inner % 2 == 0 ? 1 + 3 * inner * (inner + 2) / 4 : 3 * ((inner + 1) / 2) * ((inner + 1) / 2);
  return f[0] + f[1] + f[2] + uniform - 3 * inner;
}

// Triangles the tessellator makes of one patch at these outer factors (equal spacing, inner levels as above):
// the inner grid or rings, and on each side a strip of (outer + inner side) triangles between the two.
std::uint64_t tessellatedTriangles(bool quad, const std::array<std::uint32_t, 4>& f) {
  if (quad) {
    std::uint64_t inner0 = std::max(f[1], f[3]), inner1 = std::max(f[0], f[2]);
    if (inner0 == 1 && inner1 == 1) return 2;
    inner0 = std::max<std::uint64_t>(inner0, 2), inner1 = std::max<std::uint64_t>(inner1, 2);
    // Sides u = 0 and u = 1 run along v (inner level 1), v = 0 and v = 1 along u (inner level 0).
    return 2 * (inner0 - 2) * (inner1 - 2) + (f[0] + inner1 - 2) + (f[1] + inner0 - 2) + (f[2] + inner1 - 2) + (f[3] + inner0 - 2);
  }
  const std::uint64_t inner = std::max({f[0], f[1], f[2]});
  if (inner == 1) return 1;
  const std::uint64_t l = inner - 2;  // the rings inside are a uniform triangle of this level
  const std::uint64_t rings = l == 0 ? 0 : (3 * l * l - l % 2) / 2;
  return rings + (f[0] + l) + (f[1] + l) + (f[2] + l);
}

// Triangles the inspected draws of the last frame make, from their factors.
std::uint64_t trianglesFromFactors(const std::vector<render::PatchDraw>& draws, bool quad) {
  std::uint64_t triangles = 0;
  for (const render::PatchDraw& d : draws) {
    for (const auto& [patch, factors] : d.patches) triangles += d.tessellated ? tessellatedTriangles(quad, factors) : (quad ? 2 : 1);
  }
  return triangles;
}

}  // namespace

TEST_CASE("compute-built ACC and PN control points equal the CPU references on every preset", "[render][patches]") {
  for (const std::string& preset : test::presetNames()) {
    INFO(preset);
    const TreeMesh tree = test::meshOf(preset, 1, 2);
    const PatchSet patches = buildPatches(tree.mesh);
    render::RenderSession session(test::vulkan(), kWidth, kHeight, VK_SAMPLE_COUNT_1_BIT, test::textures());
    session.setTree(tree.mesh, patches);
    render::RenderSettings settings;
    settings.tessLevel = 2.0f;
    drawOnce(session, settings);
    settings.mode = render::RenderMode::PN;
    drawOnce(session, settings);

    const std::vector<glm::vec4> acc = session.renderer().readControl(*session.tree(), render::RenderMode::ACC);
    REQUIRE(acc.size() == patches.size() * ARBOR_ACC_CONTROL_VEC4S);
    const auto position = [&](std::uint32_t v) { return glm::dvec3(tree.mesh.positions[v]); };
    const auto texture = [&](std::uint32_t v) { return glm::dvec3(tree.mesh.uvw[v]); };
    const auto radius = [&](std::uint32_t v) { return glm::dvec3(tree.mesh.radius[v], 0.0, 0.0); };
    double worstPoint = 0.0, worstAttribute = 0.0, worstNormal = 0.0;
    for (std::size_t p = 0; p < patches.size(); ++p) {
      if (patches.kind[p] == PatchKind::Fallback) continue;
      const glm::vec4* record = acc.data() + p * ARBOR_ACC_CONTROL_VEC4S;
      const auto points = accControlPoints(patches, p, position);
      const auto uvw = accControlPoints(patches, p, texture);
      const auto radii = accControlPoints(patches, p, radius);
      for (int i = 0; i < 16; ++i) {
        worstPoint = std::max(worstPoint, worstRelative(glm::vec3(record[i]), points[i]));
        worstAttribute = std::max(worstAttribute, worstRelative(glm::vec3(record[16 + i]), uvw[i]));
        worstAttribute = std::max(worstAttribute, std::abs(record[i].w - radii[i].x));
      }
      for (int c = 0; c < 4; ++c) {
        worstNormal = std::max(worstNormal, glm::length(glm::dvec3(record[32 + c]) - accCornerNormal(patches, p, c, position)));
        CHECK(glm::vec3(record[36 + c]) == tree.mesh.uvw[patches.pointsOf(p)[c]]);
      }
    }
    // Single precision against double: a few units in the last place of the largest coordinate.
    CHECK(worstPoint < 2e-6);
    CHECK(worstAttribute < 2e-6);
    // Limit normals are cross products of tangent sums: on thin twigs far from the origin single precision
    // keeps about three digits of them.
    CHECK(worstNormal < 3e-3);

    const std::vector<glm::vec4> pn = session.renderer().readControl(*session.tree(), render::RenderMode::PN);
    const auto triangles = triangulate(tree.mesh);
    REQUIRE(pn.size() == triangles.size() * ARBOR_PN_CONTROL_VEC4S);
    double worstPn = 0.0, worstPnNormal = 0.0;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      std::array<glm::dvec3, 3> corner, normal;
      for (int i = 0; i < 3; ++i) {
        corner[i] = glm::dvec3(tree.mesh.positions[triangles[t][i]]);
        normal[i] = glm::normalize(glm::dvec3(tree.mesh.normals[triangles[t][i]]));
      }
      const PnTriangle reference = pnTriangle(corner, normal);
      const glm::vec4* record = pn.data() + t * ARBOR_PN_CONTROL_VEC4S;
      for (int i = 0; i < 3; ++i) worstPn = std::max(worstPn, worstRelative(glm::vec3(record[i]), reference.points[i]));
      for (int i = 0; i < 7; ++i) worstPn = std::max(worstPn, worstRelative(glm::vec3(record[3 + i]), reference.points[3 + i]));
      for (int i = 0; i < 3; ++i) {
        worstPnNormal = std::max(worstPnNormal, glm::length(glm::dvec3(record[13 + i]) - reference.edgeNormals[i]));
        CHECK(glm::vec3(record[16 + i]) == tree.mesh.uvw[triangles[t][i]]);
      }
    }
    CHECK(worstPn < 2e-6);
    CHECK(worstPnNormal < 2e-5);
  }
}

TEST_CASE("the culling pass drops exactly the patches outside the view or facing away", "[render][patches]") {
  const TreeMesh tree = test::meshOf("quaking-aspen", 1, 2);
  const PatchSet patches = buildPatches(tree.mesh);
  render::RenderSession session(test::vulkan(), kWidth, kHeight, VK_SAMPLE_COUNT_1_BIT, test::textures());
  session.setTree(tree.mesh, patches);
  session.renderer().setInspection(true);
  // The framed tree through a narrower lens: much of the crown is outside the view, far sides face away.
  render::Camera camera = render::frameBounds(render::plantedBounds(*session.tree()), 25.0f, 6.0f, static_cast<float>(kWidth) / kHeight);
  camera.fovY /= 3.0f;
  render::RenderSettings settings;
  settings.tessLevel = 2.0f;
  const render::FrameResult frame = drawOnce(session, settings, &camera);
  std::set<std::uint32_t> drawn;
  for (const render::PatchDraw& d : session.renderer().inspectDraws()) {
    for (const auto& [patch, factors] : d.patches) CHECK(drawn.insert(patch).second);  // each patch once
  }
  CHECK(drawn.size() == frame.gpu.patchesDrawn);
  CHECK(frame.gpu.patchesDrawn + frame.gpu.patchesCulled == patches.size());

  // The test's own computation, in double precision from the CPU reference's points: the control points' box
  // against the clip planes, and the cone of the 144 cross products of row and column differences.
  const glm::dmat4 model(render::plantedModel(*session.tree()));
  const glm::dmat4 viewProj = glm::dmat4(render::projectionMatrix(camera, static_cast<float>(kWidth) / kHeight)) * glm::dmat4(render::viewMatrix(camera));
  const glm::dvec3 eye = glm::dvec3(glm::inverse(model) * glm::dvec4(glm::dvec3(camera.eye), 1.0));
  const auto position = [&](std::uint32_t v) { return glm::dvec3(tree.mesh.positions[v]); };
  std::size_t agreed = 0, borderline = 0, wrong = 0, culledFrustum = 0, culledBack = 0;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    std::array<glm::dvec3, 16> b{};
    if (patches.kind[p] == PatchKind::Fallback) {
      const std::uint32_t* c = patches.pointsOf(p);
      for (int i = 0; i < 16; ++i) {
        const double s = (i % 4) / 3.0, t = (i / 4) / 3.0;
        b[i] = glm::mix(glm::mix(position(c[0]), position(c[1]), s), glm::mix(position(c[3]), position(c[2]), s), t);
      }
    } else {
      b = accControlPoints(patches, p, position);
    }
    glm::dvec3 lo = b[0], hi = b[0];
    for (const glm::dvec3& q : b) lo = glm::min(lo, q), hi = glm::max(hi, q);
    // How far outside the frustum (> 0: outside one plane by that much, in clip units over w).
    double outside = -1e30;
    for (int axis = 0; axis < 3; ++axis) {
      double below = 1e30, above = 1e30;
      for (int k = 0; k < 8; ++k) {
        const glm::dvec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        const glm::dvec4 c = viewProj * model * glm::dvec4(corner, 1.0);
        const double scale = std::abs(c.w) + 1e-9;
        below = std::min(below, ((axis == 2 ? 0.0 : -c.w) - c[axis]) / scale);
        above = std::min(above, (c[axis] - c.w) / scale);
      }
      outside = std::max({outside, below, above});
    }
    // The normal cone and how far the patch is from facing away (> 0: facing away by that margin).
    glm::dvec3 sum(0.0);
    std::vector<glm::dvec3> candidates;
    for (int i = 0; i < 12; ++i) {
      const glm::dvec3 du = b[(i / 3) * 4 + i % 3 + 1] - b[(i / 3) * 4 + i % 3];
      for (int j = 0; j < 12; ++j) {
        const glm::dvec3 dv = b[(j / 4 + 1) * 4 + j % 4] - b[(j / 4) * 4 + j % 4];
        const glm::dvec3 c = glm::cross(du, dv);
        if (glm::dot(c, c) > 1e-30) candidates.push_back(glm::normalize(c)), sum += candidates.back();
      }
    }
    double away = -1.0;
    if (glm::length(sum) > 1e-6) {
      const glm::dvec3 axis = glm::normalize(sum);
      double lowest = 1.0;
      for (const glm::dvec3& c : candidates) lowest = std::min(lowest, glm::dot(axis, c));
      if (lowest > 0.0) {
        const double sine = std::sqrt(1.0 - lowest * lowest);
        const glm::dvec3 centre = 0.5 * (lo + hi), d = centre - eye;
        const double r = 0.5 * glm::length(hi - lo);
        away = (glm::dot(axis, d) - r - sine * (glm::length(d) + r)) / (glm::length(d) + r);
      }
    }
    const bool cull = outside > 0.0 || away > 0.0;
    // Within rounding of a decision (the GPU works in single precision and keeps a little slack): either way.
    const bool close = std::abs(outside) < 1e-4 || std::abs(away) < 2e-3;
    const bool kept = drawn.count(static_cast<std::uint32_t>(p)) > 0;
    if (cull) (outside > 0.0 ? culledFrustum : culledBack)++;
    if (close) ++borderline;
    else if (kept == !cull) ++agreed;
    else ++wrong;
  }
  INFO("agreed " << agreed << ", borderline " << borderline << ", culled by the frustum " << culledFrustum << ", facing away " << culledBack);
  CHECK(wrong == 0);
  CHECK(borderline * 200 < patches.size());
  CHECK(culledFrustum > patches.size() / 10);  // the view really cuts the tree ...
  CHECK(culledBack > 20);                      // ... and the trunk's far side really turns away
}

TEST_CASE("bucketed draws give the unbucketed picture and triangles, and no draw passes lavapipe's limits", "[render][patches]") {
  const TreeMesh tree = test::meshOf("black-tupelo", 1, 2);
  const PatchSet patches = buildPatches(tree.mesh);
  render::RenderSession session(test::vulkan(), kWidth, kHeight, VK_SAMPLE_COUNT_1_BIT, test::textures());
  session.setTree(tree.mesh, patches);
  session.renderer().setInspection(true);
  // The whole tree in view: lavapipe's primitive statistics count only what is not culled against the view,
  // so with everything inside they are the tessellator's exact output, which the factors also give.
  for (render::RenderMode mode : {render::RenderMode::ACC, render::RenderMode::PN}) {
    INFO(render::renderModeName(mode));
    const bool quad = mode == render::RenderMode::ACC;
    render::RenderSettings settings;
    settings.mode = mode;
    settings.adaptivePixels = 0.5f;  // factors from 1 up to the trunk's dozens
    const render::FrameResult bucketed = drawOnce(session, settings);
    const Image picture = session.image();
    const std::vector<render::PatchDraw> draws = session.renderer().inspectDraws();
    CHECK(bucketed.gpu.triangles == trianglesFromFactors(draws, quad));
    std::size_t tessellatedDraws = 0, largest = 0, patchesDrawn = 0;
    for (const render::PatchDraw& d : draws) {
      patchesDrawn += d.patches.size();
      if (!d.tessellated) continue;
      ++tessellatedDraws;
      std::uint64_t vertices = 0;
      for (const auto& [patch, factors] : d.patches) vertices += tessellatedVertices(quad, factors);
      largest = std::max<std::size_t>(largest, vertices);
      if (test::vulkan().isLavapipe()) {
        CHECK(vertices <= 65535);
        CHECK(d.patches.size() <= 4096);
      }
    }
    INFO("tessellated draws " << tessellatedDraws << ", the largest " << largest << " vertices");
    CHECK(patchesDrawn == bucketed.gpu.patchesDrawn);
    CHECK(tessellatedDraws > 1);
    CHECK(largest > 4000);  // the buckets fill their draws (unbucketed ones hold 15 patches)

    settings.bucketed = false;
    const render::FrameResult unbucketed = drawOnce(session, settings);
    CHECK(bucketed.gpu.triangles == unbucketed.gpu.triangles);
    CHECK(compareImages(picture, session.image(), 0).pixelsOverThreshold == 0);
    if (test::vulkan().isLavapipe()) CHECK(bucketed.gpu.draws * 4 < unbucketed.gpu.draws);  // each draw sized for its bucket
  }
}

TEST_CASE("culling changes no pixel, with uniform and adaptive factors", "[render][patches]") {
  const TreeMesh tree = test::meshOf("quaking-aspen", 1, 3);
  const PatchSet patches = buildPatches(tree.mesh);
  render::RenderSession session(test::vulkan(), kWidth, kHeight, VK_SAMPLE_COUNT_1_BIT, test::textures());
  session.setTree(tree.mesh, patches);
  const render::Camera camera = render::parseCamera("0.8,-2.5,1.2,0,0,5,60");
  for (float adaptive : {0.0f, 3.0f}) {
    INFO("adaptive " << adaptive);
    render::RenderSettings settings;
    settings.tessLevel = 3.0f;
    settings.adaptivePixels = adaptive;
    const render::FrameResult culled = drawOnce(session, settings, &camera);
    const Image picture = session.image();
    settings.cull = false;
    const render::FrameResult all = drawOnce(session, settings, &camera);
    CHECK(all.gpu.patchesCulled == 0);
    CHECK(culled.gpu.patchesCulled > patches.size() / 20);
    CHECK(compareImages(picture, session.image(), 0).pixelsOverThreshold == 0);
  }
}

TEST_CASE("with wind the control points are the CPU wind model's posed cage refined, and at rest again once it stops", "[render][patches][wind]") {
  const test::WindyTree tree = test::windyTree("quaking-aspen", 3);
  const Skeleton& skeleton = tree.skeleton;
  const TreeGeometry& geometry = tree.geometry;
  const QuadMesh& mesh = geometry.mesh.mesh;
  const PatchSet& patches = geometry.patches;
  render::RenderSession session(test::vulkan(), kWidth, kHeight, VK_SAMPLE_COUNT_1_BIT, test::textures());
  session.setTree(mesh, patches, skeleton.leaves, geometry.impostors, &geometry.wind);
  render::RenderSettings settings;
  settings.tessLevel = 2.0f;
  settings.wind.strength = 2.0;
  settings.wind.azimuth = 130.0;
  settings.windSeconds = 2.7;
  drawOnce(session, settings);

  // The cage posed on the CPU (generator/tree/wind.cpp), then ACC's control points of it.
  std::vector<glm::dvec3> posed(mesh.vertexCount());
  double largest = 0.0;
  for (std::size_t v = 0; v < posed.size(); ++v) {
    const glm::vec3 offset = windOffset(mesh.positions[v], geometry.wind.mesh[v], settings.wind, geometry.wind.height, geometry.wind.phase, settings.windSeconds);
    posed[v] = glm::dvec3(mesh.positions[v]) + glm::dvec3(offset);
    largest = std::max(largest, static_cast<double>(glm::length(offset)));
  }
  CHECK(largest > 0.1);  // the wind moved the tree noticeably
  auto compare = [&](const std::function<glm::dvec3(std::uint32_t)>& position) {
    const std::vector<glm::vec4> acc = session.renderer().readControl(*session.tree(), render::RenderMode::ACC);
    REQUIRE(acc.size() == patches.size() * ARBOR_ACC_CONTROL_VEC4S);
    double worst = 0.0;
    for (std::size_t p = 0; p < patches.size(); ++p) {
      if (patches.kind[p] == PatchKind::Fallback) continue;
      const auto points = accControlPoints(patches, p, position);
      for (int i = 0; i < 16; ++i) worst = std::max(worst, worstRelative(glm::vec3(acc[p * ARBOR_ACC_CONTROL_VEC4S + static_cast<std::size_t>(i)]), points[static_cast<std::size_t>(i)]));
    }
    return worst;
  };
  // GLSL's single-precision sines against double: a few parts in a million of the tree's size.
  CHECK(compare([&](std::uint32_t v) { return posed[v]; }) < 2e-5);
  settings.wind.strength = 0.0;
  drawOnce(session, settings);
  CHECK(compare([&](std::uint32_t v) { return glm::dvec3(mesh.positions[v]); }) < 2e-6);
}

TEST_CASE("the wind moves the picture, leaves and fake branches with it, and still air draws the tree as without wind", "[render][wind]") {
  const test::WindyTree tree = test::windyTree("quaking-aspen", 3, 2);
  const Skeleton& skeleton = tree.skeleton;
  const TreeGeometry& geometry = tree.geometry;
  render::RenderSession session(test::vulkan(), kWidth, kHeight, VK_SAMPLE_COUNT_1_BIT, test::textures());
  session.setTree(geometry.mesh.mesh, geometry.patches, skeleton.leaves, geometry.impostors, &geometry.wind);
  const float aspect = static_cast<float>(kWidth) / static_cast<float>(kHeight);
  const render::Camera camera = render::frameBounds(render::plantedBounds(*session.tree()), 25.0f, 6.0f, aspect);
  render::RenderSettings settings;
  settings.leaves = true;
  settings.impostors = true;
  for (const render::RenderMode mode : {render::RenderMode::Flat, render::RenderMode::ACC}) {
    INFO(render::renderModeName(mode));
    settings.mode = mode;
    settings.wind = WindSettings{};
    session.render(camera, settings);
    const Image still = session.image();
    settings.wind.strength = 0.0;
    settings.windSeconds = 3.0;
    session.render(camera, settings);
    CHECK(compareImages(still, session.image(), 0).pixelsOverThreshold == 0);
    settings.wind.strength = 2.0;
    session.render(camera, settings);
    CHECK(compareImages(still, session.image(), 8).pixelsOverThreshold > 50);
  }
}

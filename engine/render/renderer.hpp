#pragma once
// Records a frame of sky, ground and trees in any render mode. Tessellated modes build each mesh's control
// points once (compute), then every frame a compute pass culls patches, sets their factors and sorts them into
// indirect draws sized for the device; the tessellation stages only evaluate. Measures what the GPU did.
#include <array>
#include <unordered_map>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "camera.hpp"
#include "gpu_tree.hpp"
#include "image/png_io.hpp"
#include "pipelines.hpp"
#include "vk/texture.hpp"

namespace arbor::render {

// The renderer's textures: bark colour and height (tileable), the leaf atlas.
struct TreeTextures {
  Image barkColor, barkHeight, leafAtlas;
  // The bark sampler's largest anisotropy (1: trilinear only). At 8 lavapipe spends about a third of the viewer's
  // frame on bark lookups (docs/PERFORMANCE.md), so the viewer asks for 1 there.
  float barkAnisotropy = 8.0f;
};

struct RenderSettings {
  RenderMode mode = RenderMode::ACC;
  float tessLevel = 8.0f;        // uniform tessellation factor (1..64)
  float adaptivePixels = 0.0f;   // > 0: factors aim at edges of this many pixels instead
  float maxLevel = 64.0f;
  float displacement = 0.0f;     // s in (d - b) r s
  float displacementBias = 0.5f; // b
  float seamFade = 0.2f;         // |w| below which displacement and bump fade out
  float textureRepeat = 1.0f;    // texture repeats per unit of v
  bool wireframe = false;        // outline the tessellated triangles over the surface
  bool ground = true;
  bool cull = true;              // skip patches outside the view, and (undisplaced) those facing away
  bool bucketed = true;          // size each draw for its patches' own factors (false: all for the largest)
  bool cornerPatches = true;     // patches whose factors are all 1 skip the tessellator (the same picture)
  bool leaves = false;            // draw the leaves
  float leafDensity = 1.0f;       // share of the leaves drawn (0..1), the first of the random order
  float leafLodDistance = 0.0f;   // > 0: all leaves up to this distance (m), then thinning with distance squared
  std::uint32_t shadowLeaves = 0; // self-shadowing: each leaf tests the first this many leaves
  bool impostors = false;         // draw the fake branches
  bool ceiling = false;           // ACC mode with trivial stages: the device's bare tessellation rate (bench)
  float groundRadius = 0.0f;     // > 0: the ground fades into the horizon this far from the eye (forests)
  bool revealBackFaces = false;  // draw back faces too, in magenta: on a closed surface any that shows is a crack
  std::uint32_t patchesPerDraw = 0;  // > 0: at most this many patches per draw, one bucket (tests); 0: what the driver needs
  glm::vec3 lightDirection{0.45f, -0.6f, 0.75f};
  float lightIntensity = 1.0f;
  // Wind (docs/wind.md) on trees uploaded with wind records: the control cage is posed every frame.
  WindSettings wind;
  double windSeconds = 0.0;       // the scene's clock
};

struct FrameStats {
  std::uint64_t triangles = 0;   // primitives that reached clipping (pipeline statistics), tree only
  double gpuMilliseconds = 0.0;  // tree draws, from timestamps
  std::uint32_t draws = 0;       // tree draws, the GPU's indirect ones counted
  std::uint64_t patchesDrawn = 0, patchesCulled = 0;  // tessellated instances, after the culling pass
  bool hasTriangles = false, hasTime = false;
};

// Points the ACC evaluation stage wrote when capture is on (tests), in object space.
struct CapturedPoint {
  std::uint32_t patch;
  float u, v;
  glm::vec3 position;   // on the ACC patch
  glm::vec3 displaced;  // after displacement (equal to position without it)
  glm::vec3 uvw;        // texture coordinates there: seam-safe u, v, flip coordinate
};

// One indirect draw of the last frame and the patches it drew (tests): patch index and outer factors.
struct PatchDraw {
  std::uint32_t instance = 0;
  bool tessellated = true;  // false: the draw of factor-1 patches without the tessellator
  std::vector<std::pair<std::uint32_t, std::array<std::uint32_t, 4>>> patches;
};

// One tree of a scene: which of the renderer's trees (setTrees) it is and where it stands.
struct TreeInstance {
  std::uint32_t tree = 0;
  glm::mat4 model{1.0f};
  // Far away: the mesh drawn flat at its limit positions (ACC's factor 1 without the tessellator), the fake
  // branches as the tree's sketch (one per stem segment, no twigs).
  bool far = false;
};

class TreeRenderer {
 public:
  TreeRenderer(const vk::VulkanContext& context, VkRenderPass renderPass, VkSampleCountFlagBits samples,
               const TreeTextures& textures);
  ~TreeRenderer();
  TreeRenderer(const TreeRenderer&) = delete;
  TreeRenderer& operator=(const TreeRenderer&) = delete;

  static constexpr std::uint32_t kMaxTrees = 64;
  // Frames that may be recorded while earlier ones still run: each has its own uniforms, queries, patch lists
  // and descriptor sets. beginFrame may reuse a frame's resources only when the frame kFramesInFlight before it
  // has completed (the caller's fences see to that).
  static constexpr std::uint32_t kFramesInFlight = 2;
  // Both wait until the device is idle: frames in flight may still read the previous trees.
  void setTree(const GpuTree* tree);                        // one tree, or none (sky and ground only)
  void setTrees(const std::vector<const GpuTree*>& trees);  // a scene's distinct trees, at most kMaxTrees
  // Captures up to `capacity` evaluated ACC points in the next frames (0 turns it off).
  void setCapture(std::uint32_t capacity);
  std::vector<CapturedPoint> captured() const;

  // A tree's control records (interface.h) for `mode`, or with `hulls` its culling hulls, read back from the GPU
  // (tests); empty until a frame has drawn the tree in that mode.
  std::vector<glm::vec4> readControl(const GpuTree& tree, RenderMode mode, bool hulls = false) const;
  // Bytes of the control points and hulls built so far for `mode`, all trees together (GpuTree::bytes has the rest).
  std::size_t controlBytes(RenderMode mode) const;

  // Keeps this frame's patch lists and draw commands readable by the host (tests; slower on discrete GPUs).
  void setInspection(bool on);
  // With inspection on, after the frame completed: every indirect draw of the last frame with its patches.
  std::vector<PatchDraw> inspectDraws() const;

  // Before the render pass begins: reset the queries, upload the scene, build missing control points, cull and
  // bucket the tessellated instances' patches into this frame's draws. `instances` as draw will get them.
  void beginFrame(VkCommandBuffer cmd, const Camera& camera, VkExtent2D extent, const RenderSettings& settings,
                  const std::vector<TreeInstance>& instances);
  // Inside the render pass: sky, ground and every instance (statistics and time cover all of them).
  void draw(VkCommandBuffer cmd, VkExtent2D extent, const RenderSettings& settings, const std::vector<TreeInstance>& instances);
  // Inside the render pass, after draw: `count` LineVertex ends (pairs) from `vertices`, placed by `model`,
  // depth-tested against the scene. Not counted in the statistics.
  void drawLines(VkCommandBuffer cmd, VkBuffer vertices, std::uint32_t count, const glm::mat4& model);
  // Of the frame begun last, once its commands have completed.
  FrameStats stats() const;
  // Of the latest frame known to have completed: the one whose resources the last beginFrame reused, that is
  // kFramesInFlight frames back (for a display that does not wait for each frame).
  FrameStats completedStats() const { return completed_; }

  // Patches per draw in each bucket, and how many buckets: lavapipe wraps its 16-bit indices beyond 65535
  // tessellated vertices and garbles patches beyond 4096 input vertices per draw; other devices take one draw.
  struct DrawSizes {
    bool bucketed = false;                // by largest factor; else every tessellated patch in bucket 1
    std::array<std::uint32_t, 8> perDraw{};  // buckets 1 and up (bucket 0 is one draw without the tessellator)
  };
  DrawSizes drawSizes(const RenderSettings& settings) const;

 private:
  // A distinct tree's control points and hulls per tessellated mode, built on first use; per frame in flight,
  // the compute set that reads them with that frame's lists.
  struct TreeControl {
    std::array<vk::Buffer, kRenderModeCount> control, hulls;
    vk::Buffer posed;  // the cage moved by the wind this frame (wind.comp), which the control passes then read
    std::array<bool, kFramesInFlight> boundPosed{};  // whether that frame's set reads the posed cage
    std::array<bool, kRenderModeCount> posedBuild{};  // control points last built from a posed cage (rebuilt at rest)
    std::array<VkDescriptorSet, kFramesInFlight> computeSet{};
    std::array<int, kFramesInFlight> boundMode{-1, -1};  // the mode whose control buffers that frame's sets point at
    std::array<std::uint64_t, kFramesInFlight> boundGeneration{};  // the frame buffers' generation they point at
  };
  // One tessellated instance's slice of a frame's lists.
  struct InstancePlan {
    std::uint32_t tree = 0, primitives = 0, listBase = 0, counterBase = 0, commandBase = 0, maxCommands = 0;
  };
  // What one frame in flight owns.
  struct FrameSlot {
    vk::Buffer scene;                       // the Scene uniforms
    std::vector<VkDescriptorSet> sets;      // one per tree; the first also serves sky and ground
    VkQueryPool statistics = VK_NULL_HANDLE, timestamps = VK_NULL_HANDLE;
    // Surviving patches per bucket, counters, draw commands; and the counters read back.
    vk::Buffer visible, counts, commands, countsReadback;
    std::uint64_t generation = 0;           // bumped when those buffers are reallocated
    std::vector<InstancePlan> plans;
    std::vector<int> planOf;                // per instance of the frame: its plan, or -1 when drawn untessellated
    RenderMode mode = RenderMode::ACC;
    std::uint32_t draws = 0;
    bool drewTree = false;
    bool used = false;                      // has recorded a frame
  };

  glm::vec3 eye_{0.0f};  // of the frame begun last: leaf draws are cut to what thinning keeps
  FrameSlot& slot() { return slots_[current_]; }
  const FrameSlot& slot() const { return slots_[current_]; }
  FrameStats statsOf(const FrameSlot& frame) const;
  void writeSet(const FrameSlot& frame, VkDescriptorSet set, const GpuTree* tree);
  void bindControl(std::uint32_t tree, RenderMode mode, bool posed);
  void ensureFrameBuffers(FrameSlot& frame, std::size_t entries, std::size_t counters, std::size_t commands);
  bool drawnTessellated(const TreeInstance& instance, const RenderSettings& s) const;

  const vk::VulkanContext& context_;
  Pipelines pipelines_;
  vk::GpuImage barkColor_, barkHeight_, leafAtlas_;
  VkSampler sampler_ = VK_NULL_HANDLE, leafSampler_ = VK_NULL_HANDLE;
  vk::Buffer capture_;
  vk::Buffer cardIndices_;  // kCardsPerDraw cards' triangles (cards.hpp), shared by every leaf and fake-branch draw
  std::uint32_t captureCapacity_ = 0;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::vector<const GpuTree*> trees_;
  std::unordered_map<std::uint64_t, TreeControl> controls_;  // by GpuTree::id
  VkDescriptorPool computePool_ = VK_NULL_HANDLE;
  std::array<FrameSlot, kFramesInFlight> slots_;
  std::uint32_t current_ = 0;  // the slot of the frame begun last
  std::uint64_t framesBegun_ = 0;
  FrameStats completed_;
  bool inspect_ = false;
};

}  // namespace arbor::render

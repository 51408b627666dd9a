#include "growth_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <imgui.h>

#include "assets.hpp"
#include "common/atomic_file.hpp"
#include "tree/build_tree.hpp"
#include "files/tree_file.hpp"
#include "view_panel.hpp"
#include "common/input_error.hpp"
#include "growth/graph/branch_graph.hpp"
#include "growth/space_colonization/space_colonization.hpp"
#include "render/gpu_tree.hpp"
#include "tree/forest_trees.hpp"
#include "wireframes.hpp"

namespace arbor::viewer {

namespace {


const sc::SpaceColonization& requireColonization(const TreeModel& model) {
  const sc::SpaceColonization* m = spaceColonizationOf(model);
  if (!m) throw std::invalid_argument("the modeller takes a space-colonization model");
  return *m;
}

// The edited model as the file reader would take it: written out and read back, so every rule of the format holds.
sc::SpaceColonization checked(const sc::SpaceColonization& m) {
  sc::SpaceColonization back = sc::readSpaceColonization(sc::writeSpaceColonization(m), m.file);
  back.file = m.file;
  return back;
}

std::string eventText(const WindowEvent& e) { return std::to_string(e.frame) + ":" + e.action; }

template <typename T>
void requireIndex(const std::vector<T>& list, const WindowEvent& e, const char* what) {
  const auto i = static_cast<std::size_t>(e.numbers[0]);
  if (i >= list.size())
    throw InputError(eventText(e), "--events", "no " + std::string(what) + " " + std::to_string(i) + "; the model has " + std::to_string(list.size()) +
                                                 " (indices from 0)");
}

sc::CloudShape cloudShape(const WindowEvent& e) {
  for (auto s : {sc::CloudShape::Sphere, sc::CloudShape::Ellipsoid, sc::CloudShape::Cone, sc::CloudShape::Box})
    if (e.text == sc::cloudShapeName(s)) return s;
  throw InputError(eventText(e), "--events", "cloud shape '" + e.text + "': allowed sphere, ellipsoid, cone, box");
}

sc::ObstacleShape obstacleShape(const WindowEvent& e) {
  for (auto s : {sc::ObstacleShape::Box, sc::ObstacleShape::Sphere})
    if (e.text == sc::obstacleShapeName(s)) return s;
  throw InputError(eventText(e), "--events", "obstacle shape '" + e.text + "': allowed box, sphere (mesh obstacles come from model files)");
}

Vec3 vec(const std::vector<double>& n, std::size_t first) { return Vec3(n[first], n[first + 1], n[first + 2]); }

// Where a new cloud or obstacle appears when the panel adds one: above the tree's top, the size of its crown.
Vec3 aboveTree(const sc::Colonizer& c) {
  double top = 0;
  for (const sc::Node& n : c.nodes()) top = std::max(top, n.position.z);
  return Vec3(c.settings().trunkBase.x, c.settings().trunkBase.y, top);
}

}  // namespace

bool isModellerEvent(const WindowEvent& e) {
  static const char* const actions[] = {"open", "save", "export", "grow", "pause", "step", "finish", "rewind", "reset", "regenerate",
                                        "add-cloud", "move-cloud", "resize-cloud", "remove-cloud",
                                        "add-obstacle", "move-obstacle", "resize-obstacle", "remove-obstacle"};
  return std::any_of(std::begin(actions), std::end(actions), [&](const char* a) { return e.action == a; });
}

sc::SpaceColonization editedModel(const sc::SpaceColonization& model, const WindowEvent& e) {
  sc::SpaceColonization m = model;
  const std::vector<double>& n = e.numbers;
  const std::string& a = e.action;
  if (a == "add-cloud") {
    sc::AttractionCloud c;
    c.shape = cloudShape(e);
    c.center = vec(n, 0);
    c.size = vec(n, 3);
    if (n.size() > 6) {
      if (n[6] < 1 || n[6] > 1e6 || n[6] != std::floor(n[6])) throw InputError(eventText(e), "--events", "points: a whole number from 1 to 1000000");
      c.points = static_cast<std::uint32_t>(n[6]);
    }
    if (n.size() > 7) c.influence = n[7];
    if (n.size() > 8) c.kill = n[8];
    m.clouds.push_back(c);
  } else if (a == "move-cloud" || a == "resize-cloud" || a == "remove-cloud") {
    requireIndex(m.clouds, e, "cloud");
    const auto i = static_cast<std::size_t>(n[0]);
    if (a == "move-cloud") m.clouds[i].center = vec(n, 1);
    if (a == "resize-cloud") m.clouds[i].size = vec(n, 1);
    if (a == "remove-cloud") m.clouds.erase(m.clouds.begin() + static_cast<std::ptrdiff_t>(i));
  } else if (a == "add-obstacle") {
    sc::Obstacle o;
    o.shape = obstacleShape(e);
    o.center = vec(n, 0);
    o.size = vec(n, 3);
    m.obstacles.push_back(o);
  } else if (a == "move-obstacle" || a == "resize-obstacle" || a == "remove-obstacle") {
    requireIndex(m.obstacles, e, "obstacle");
    const auto i = static_cast<std::size_t>(n[0]);
    if (a != "remove-obstacle" && m.obstacles[i].shape == sc::ObstacleShape::Mesh)
      throw InputError(eventText(e), "--events", "obstacle " + std::to_string(i) + " is a mesh from " + m.obstacles[i].file + "; it can only be removed");
    if (a == "move-obstacle") m.obstacles[i].center = vec(n, 1);
    if (a == "resize-obstacle") m.obstacles[i].size = vec(n, 1);
    if (a == "remove-obstacle") m.obstacles.erase(m.obstacles.begin() + static_cast<std::ptrdiff_t>(i));
  } else {
    return m;
  }
  try {
    return checked(m);
  } catch (const InputError& error) {
    throw InputError(eventText(e), "--events", std::string("the model refuses the edit: ") + error.what());
  }
}

void GrowthScene::checkEvents(const TreeModel& model, const std::vector<WindowEvent>& events) {
  std::vector<WindowEvent> ordered;
  for (const WindowEvent& e : events)
    if (isSceneEvent(e)) ordered.push_back(e);
  std::stable_sort(ordered.begin(), ordered.end(), [](const WindowEvent& a, const WindowEvent& b) { return a.frame < b.frame; });
  sc::SpaceColonization m = requireColonization(model);
  for (const WindowEvent& e : ordered) {
    if (!isModellerEvent(e)) throw InputError(eventText(e), "--events", "not an event of the modeller");
    if (e.action == "save" || e.action == "export") continue;  // their paths are checked with every scene's
    if (e.action == "open") {
      const TreeModel next = cli::loadModelArgument(e.text);
      const sc::SpaceColonization* opened = spaceColonizationOf(next);
      if (!opened)
        throw InputError(e.text, "--events", std::string("open: a ") + next.model() + " model; the modeller opens space-colonization models only");
      m = *opened;
    } else {
      m = editedModel(m, e);
    }
  }
}

GrowthScene::GrowthScene(const TreeModel& model, std::uint64_t seed) : seed_(seed) {
  for (const std::string& name : cli::presetNames()) {
    try {
      if (spaceColonizationOf(cli::loadModelArgument(name))) presets_.push_back(name);
    } catch (const std::exception&) {
      // a preset that does not load is not offered here; `arbor species --list` reports it
    }
  }
  open(model);
}

void GrowthScene::open(const TreeModel& model) {
  model_ = requireColonization(model);
  pathInput_ = model_.file;
  restart();
  colonizer_->growToEnd();  // as `arbor generate` grows it; rewind from here
  highestAge_ = colonizer_->age();
  growing_ = false;
}

void GrowthScene::restart() {
  colonizer_ = std::make_unique<sc::Colonizer>(startColonizer(model_, seed_));
  highestAge_ = 0;
  treeChanged_ = linesChanged_ = true;
}

void GrowthScene::goToAge(std::uint32_t age) {
  if (age < colonizer_->age()) colonizer_->rewind(age);
  while (colonizer_->age() < age && !colonizer_->finished()) colonizer_->step(1);
  treeChanged_ = linesChanged_ = true;
}

void GrowthScene::apply(const sc::SpaceColonization& edited, const WindowEvent& e) {
  const std::string& a = e.action;
  const auto i = e.numbers.empty() ? std::size_t{0} : static_cast<std::size_t>(e.numbers[0]);
  sc::Colonizer& c = *colonizer_;
  if (a == "add-cloud") c.addCloud(edited.clouds.back());
  if (a == "move-cloud" || a == "resize-cloud") c.replaceCloud(i, edited.clouds[i]);
  if (a == "remove-cloud") c.removeCloud(i);
  if (a == "add-obstacle") c.addObstacle(edited.obstacles.back());
  if (a == "move-obstacle" || a == "resize-obstacle") c.replaceObstacle(i, edited.obstacles[i]);
  if (a == "remove-obstacle") c.removeObstacle(i);
  model_ = edited;
  treeChanged_ = linesChanged_ = true;
}

bool GrowthScene::handle(const WindowEvent& e) {
  if (!isModellerEvent(e)) return false;
  const std::string& a = e.action;
  if (a == "open") open(cli::loadModelArgument(e.text));
  else if (a == "save") save(e.text);
  else if (a == "export") exportMesh(e.text);
  else if (a == "grow") growing_ = true;
  else if (a == "pause") growing_ = false;
  else if (a == "step") colonizer_->step(static_cast<std::size_t>(e.numbers[0]));
  else if (a == "finish") colonizer_->growToEnd();
  else if (a == "rewind") goToAge(static_cast<std::uint32_t>(e.numbers[0]));
  else if (a == "reset") restart();
  else if (a == "regenerate") {
    restart();
    colonizer_->growToEnd();
  } else apply(editedModel(model_, e), e);
  treeChanged_ = linesChanged_ = true;
  return true;
}

bool GrowthScene::replaceCloud(std::size_t index, const sc::AttractionCloud& cloud) {
  sc::SpaceColonization edited = model_;
  edited.clouds.at(index) = cloud;
  try {
    edited = checked(edited);
  } catch (const InputError& error) {
    message_ = error.what();
    return false;
  }
  colonizer_->replaceCloud(index, edited.clouds[index]);
  model_ = edited;
  message_.clear();
  treeChanged_ = linesChanged_ = true;
  return true;
}

bool GrowthScene::tryEdit(const WindowEvent& e) {
  try {
    apply(editedModel(model_, e), e);
    message_.clear();
    return true;
  } catch (const InputError& error) {
    message_ = error.what();
    return false;
  }
}

void GrowthScene::save(const std::string& path) {
  // The model as it stands: clouds and obstacles where the artist left them (growth replays them from the start).
  writeFileAtomically(path, sc::writeSpaceColonization(model_));
  std::printf("wrote %s (the model)\n", path.c_str());
  std::fflush(stdout);
}

void GrowthScene::exportMesh(const std::string& path) {
  const Skeleton skeleton = colonizationSkeleton(*colonizer_, model_, seed_, TreeLimits{});
  writeTreeFile(path, skeleton, model_.name, TreeFileOptions{});
  std::printf("wrote %s (the mesh at age %u)\n", path.c_str(), colonizer_->age());
  std::fflush(stdout);
}

void GrowthScene::start(const vk::VulkanContext& context, render::TreeRenderer& renderer) {
  context_ = &context;
  rebuildTree(renderer);
}

void GrowthScene::stop() {
  forest_.reset();
  lines_ = vk::Buffer();
}

std::string GrowthScene::summary() const {
  return "modeller: " + model_.name + ", " + std::to_string(colonizer_->nodes().size()) + " nodes";
}

void GrowthScene::update(render::TreeRenderer& renderer) {
  if (growing_) {
    colonizer_->step(static_cast<std::size_t>(stepSize_));
    if (colonizer_->finished()) growing_ = false;
    treeChanged_ = linesChanged_ = true;
  }
  highestAge_ = std::max(highestAge_, colonizer_->age());
  if (treeChanged_) rebuildTree(renderer);
}

void GrowthScene::rebuildTree(render::TreeRenderer& renderer) {
  treeChanged_ = false;
  const Skeleton skeleton = graphToSkeleton(colonizationGraph(*colonizer_, model_), colonizationGraphOptions(model_));
  ForestTreesOptions options;
  options.labels = {model_.name};
  options.sources = {TreeSource(model_.name, skeleton)};
  options.trees = 1;
  options.seeds = 1;
  options.details = static_cast<int>(render::kDetailLevels);
  const std::vector<DetailedTree> trees = growForestTrees(options, [](const std::string&) {});  // rebuilt every frame it grows: no progress lines
  auto forest = std::make_unique<render::Forest>(*context_, trees, 1, 1);
  renderer.setTrees(forest->gpuTrees());
  forest_ = std::move(forest);
  linesChanged_ = true;
}

void GrowthScene::rebuildLines() {
  linesChanged_ = false;
  Lines lines;
  if (showWireframes_) {
    for (std::size_t i = 0; i < model_.clouds.size(); ++i) addCloud(lines, model_.clouds[i], cloudColor(i));
    for (const sc::Obstacle& o : model_.obstacles) addObstacle(lines, o, kObstacleColor);
    addDisabledBranches(lines, *colonizer_);
  }
  if (showPoints_) addLivePoints(lines, *colonizer_, 0.3 * model_.segmentLength);
  lineCount_ = static_cast<std::uint32_t>(lines.size());
  if (lines.empty()) return;
  const std::size_t bytes = lines.size() * sizeof(render::LineVertex);
  if (lines_.size() < bytes) lines_ = vk::hostBuffer(*context_, bytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  std::memcpy(lines_.mapped(), lines.data(), bytes);
}

void GrowthScene::drawLines(VkCommandBuffer cmd, render::TreeRenderer& renderer) {
  if (linesChanged_) rebuildLines();  // the panel toggles them between updates
  // The lines are in the model's coordinates; the tree stands sunk by its planting depth like every tree.
  renderer.drawLines(cmd, lines_.handle(), lineCount_, render::plantedModel(forest_->trees().front().detail[0]));
}

render::Bounds GrowthScene::workingBounds() const {
  Vec3 lo(1e30), hi(-1e30);
  const auto box = [&](const Vec3& a, const Vec3& b) {
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  };
  for (const sc::AttractionCloud& c : model_.clouds) {
    const Vec3 half = c.shape == sc::CloudShape::Box ? 0.5 * c.size : c.shape == sc::CloudShape::Ellipsoid ? c.size : Vec3(c.size.x);
    if (c.shape == sc::CloudShape::Cone) box(c.center - Vec3(c.size.x, c.size.x, 0), c.center + Vec3(c.size.x, c.size.x, c.size.z));
    else box(c.center - half, c.center + half);
  }
  for (const sc::Obstacle& o : model_.obstacles) {
    if (o.shape == sc::ObstacleShape::Mesh && o.mesh) box(o.mesh->low, o.mesh->high);
    else if (o.shape == sc::ObstacleShape::Box) box(o.center - 0.5 * o.size, o.center + 0.5 * o.size);
    else box(o.center - Vec3(o.size.x), o.center + Vec3(o.size.x));
  }
  for (const sc::Node& n : colonizer_->nodes()) box(n.position, n.position);
  lo.z = std::max(lo.z, model_.trunkBase.z);  // the camera looks at the tree above the ground, not at what lies below it
  const glm::mat4 planted = render::plantedModel(forest_->trees().front().detail[0]);
  return render::Bounds{glm::vec3(planted * glm::vec4(glm::vec3(lo), 1.0f)), glm::vec3(planted * glm::vec4(glm::vec3(hi), 1.0f))};
}

render::Camera GrowthScene::overview(float aspect) const { return render::frameBounds(workingBounds(), 25.0f, 10.0f, aspect); }

std::vector<render::Camera> GrowthScene::tour(float aspect) const {
  return {overview(aspect), render::frameBounds(workingBounds(), 115.0f, 10.0f, aspect), render::frameBounds(workingBounds(), 205.0f, 10.0f, aspect)};
}

std::string GrowthScene::status() const {
  const sc::Colonizer& c = *colonizer_;
  const auto enabled = std::count_if(c.nodes().begin(), c.nodes().end(), [](const sc::Node& n) { return n.enabled; });
  char text[200];
  std::snprintf(text, sizeof text, "age %u, %zu nodes (%ld enabled), %zu live points, %zu clouds, %zu obstacles, %s", c.age(), c.nodes().size(),
                static_cast<long>(enabled), c.livePoints(), model_.clouds.size(), model_.obstacles.size(),
                growing_ ? "growing" : c.finished() ? "finished" : "paused");
  return text;
}

void GrowthScene::panel(ViewState&) {
  if (!ImGui::CollapsingHeader("space colonization", ImGuiTreeNodeFlags_DefaultOpen)) return;
  // Open: a preset from the list, or any model file by path.
  const std::string current = model_.name;
  if (ImGui::BeginCombo("preset", current.c_str())) {
    for (const std::string& name : presets_)
      if (ImGui::Selectable(name.c_str())) open(cli::loadModelArgument(name));
    ImGui::EndCombo();
  }
  char path[512];
  std::snprintf(path, sizeof path, "%s", pathInput_.c_str());
  if (ImGui::InputText("file", path, sizeof path)) pathInput_ = path;
  ImGui::SameLine();
  if (ImGui::Button("open")) {
    try {
      const TreeModel model = cli::loadModelArgument(pathInput_);
      if (!spaceColonizationOf(model)) throw std::invalid_argument(pathInput_ + ": a " + std::string(model.model()) + " model, not space colonization");
      open(model);
      message_.clear();
    } catch (const std::exception& e) {
      message_ = e.what();
    }
  }
  ImGui::TextWrapped("%s", status().c_str());
  if (ImGui::Button(growing_ ? "pause" : "grow")) growing_ = !growing_;
  ImGui::SameLine();
  if (ImGui::Button("step")) {
    colonizer_->step(static_cast<std::size_t>(stepSize_));
    treeChanged_ = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("finish")) {
    colonizer_->growToEnd();
    treeChanged_ = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("reset")) restart();
  ImGui::SliderInt("nodes per step", &stepSize_, 1, 5000);
  int age = static_cast<int>(colonizer_->age());
  if (ImGui::SliderInt("age", &age, 0, static_cast<int>(std::max(highestAge_, colonizer_->age())))) goToAge(static_cast<std::uint32_t>(age));
  auto gravity = static_cast<float>(model_.gravity);
  if (ImGui::SliderFloat("gravity", &gravity, 0.0f, 2.0f)) {
    model_.gravity = gravity;
    colonizer_->setGravity(gravity);  // from the next step on; rewind to regrow with it
  }
  if (ImGui::Checkbox("attraction points", &showPoints_)) linesChanged_ = true;
  ImGui::SameLine();
  if (ImGui::Checkbox("wireframes", &showWireframes_)) linesChanged_ = true;

  // Each cloud and obstacle: drag to move or resize; the edit applies when the model's rules allow it.
  const auto editor = [&](const char* kind, std::size_t i, Vec3 center, Vec3 size, bool movable) {
    ImGui::PushID(static_cast<int>(i));
    float c[3] = {static_cast<float>(center.x), static_cast<float>(center.y), static_cast<float>(center.z)};
    float s[3] = {static_cast<float>(size.x), static_cast<float>(size.y), static_cast<float>(size.z)};
    WindowEvent e;
    e.numbers = {static_cast<double>(i), 0, 0, 0};
    if (movable && ImGui::DragFloat3("centre", c, 0.02f)) {
      e.action = std::string("move-") + kind;
      e.numbers = {static_cast<double>(i), c[0], c[1], c[2]};
    }
    if (movable && ImGui::DragFloat3("size", s, 0.02f, 0.01f, 1000.0f)) {
      e.action = std::string("resize-") + kind;
      e.numbers = {static_cast<double>(i), s[0], s[1], s[2]};
    }
    if (ImGui::Button("remove")) e.action = std::string("remove-") + kind;
    if (!e.action.empty()) tryEdit(e);
    ImGui::PopID();
  };
  if (ImGui::TreeNodeEx("clouds", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (std::size_t i = 0; i < model_.clouds.size() && i < 64; ++i) {
      const sc::AttractionCloud& cl = model_.clouds[i];
      const glm::vec3 color = cloudColor(i);
      ImGui::TextColored(ImVec4(color.r, color.g, color.b, 1.0f), "cloud %zu: %s, %u points", i, sc::cloudShapeName(cl.shape), cl.points);
      editor("cloud", i, cl.center, cl.size, true);
      // Shape, point count and radii: the same cloud index, its points sampled anew.
      ImGui::PushID(static_cast<int>(1000 + i));
      sc::AttractionCloud changed = cl;
      int shape = static_cast<int>(cl.shape), points = static_cast<int>(cl.points);
      auto influence = static_cast<float>(cl.influence), kill = static_cast<float>(cl.kill);
      bool edited = ImGui::Combo("shape", &shape, "sphere\0ellipsoid\0cone\0box\0");
      edited |= ImGui::InputInt("points", &points, 100, 1000);
      edited |= ImGui::DragFloat("influence", &influence, 0.01f, 0.01f, 100.0f);
      edited |= ImGui::DragFloat("kill", &kill, 0.01f, 0.001f, 100.0f);
      ImGui::PopID();
      if (edited) {
        changed.shape = static_cast<sc::CloudShape>(shape);
        changed.points = static_cast<std::uint32_t>(std::clamp(points, 1, 1000000));
        changed.influence = influence;
        changed.kill = kill;
        replaceCloud(i, changed);
      }
    }
    if (ImGui::Button("add sphere cloud")) {
      WindowEvent e;
      e.action = "add-cloud";
      e.text = "sphere";
      const Vec3 at = aboveTree(*colonizer_);
      const double r = std::max(0.5, 10 * model_.segmentLength);
      const sc::AttractionCloud like = model_.clouds.empty() ? sc::AttractionCloud{} : model_.clouds.front();
      e.numbers = {at.x, at.y, at.z + r, r, r, r, 1000, like.influence, like.kill};
      tryEdit(e);
    }
    ImGui::TreePop();
  }
  if (ImGui::TreeNodeEx("obstacles", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (std::size_t i = 0; i < model_.obstacles.size() && i < 64; ++i) {
      const sc::Obstacle& o = model_.obstacles[i];
      ImGui::TextColored(ImVec4(kObstacleColor.r, kObstacleColor.g, kObstacleColor.b, 1.0f), "obstacle %zu: %s%s%s", i, sc::obstacleShapeName(o.shape),
                         o.file.empty() ? "" : " ", o.file.c_str());
      editor("obstacle", i, o.center, o.size, o.shape != sc::ObstacleShape::Mesh);
    }
    for (const char* shape : {"box", "sphere"}) {
      if (shape[0] == 's') ImGui::SameLine();
      if (ImGui::Button((std::string("add ") + shape + " obstacle").c_str())) {
        WindowEvent e;
        e.action = "add-obstacle";
        e.text = shape;
        const Vec3 at = aboveTree(*colonizer_);
        const double r = std::max(0.3, 5 * model_.segmentLength);
        e.numbers = {at.x + 2 * r, at.y, 0.5 * at.z, r, r, r};
        tryEdit(e);
      }
    }
    ImGui::TreePop();
  }
  fileButtons(outputPath_, fileStatus_, [&](const std::string& p) { save(p); }, [&](const std::string& p) { exportMesh(p); });
  if (!message_.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "refused:");
    ImGui::TextWrapped("%s", message_.c_str());
  }
}

}  // namespace arbor::viewer

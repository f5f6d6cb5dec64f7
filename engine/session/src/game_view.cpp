#include "platon/session/game_view.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "platon/core/debug_view.h"

namespace platon::session {

script::GameStatus statusOf(core::Scene& scene) {
  const auto* scripts = dynamic_cast<const script::ScriptSystem*>(scene.findSystem("scripting"));
  return scripts ? scripts->status() : script::GameStatus{};
}

// A time in frames as a clock: 1:05.25, or 1:05 as par times are written.
std::string clockText(uint64_t frames, bool hundredths) {
  char text[32];
  const uint64_t seconds = frames / 60;
  std::snprintf(text, sizeof text, "%llu:%02llu", static_cast<unsigned long long>(seconds / 60),
                static_cast<unsigned long long>(seconds % 60));
  std::string clock = text;
  if (hundredths) {
    std::snprintf(text, sizeof text, ".%02llu", static_cast<unsigned long long>(frames % 60 * 100 / 60));
    clock += text;
  }
  return clock;
}

std::vector<std::string> hudLines(const core::Scene& scene, const script::GameStatus& status) {
  std::vector<std::string> lines{scene.manifest().name + "    " + clockText(status.time) + "    deaths " +
                                 std::to_string(status.deaths)};
  if (!status.message.empty()) lines.push_back(status.message);
  return lines;
}

core::Display* displayOf(core::Scene& scene) {
  core::System* rendering = scene.findSystem("rendering");
  return rendering ? rendering->display() : nullptr;
}

void GameView::step(core::Scene& scene, const script::GameStatus& status, double stepSeconds) {
  if (&scene != scene_ || !stage_ || (stage_->flat && status.face != flatPart_)) {
    stage_ = core::stageView(scene, status.face);
    scene_ = &scene;
    flatPart_ = status.face;
  }
  face_ = status.face;
  openTags_ = status.openTags;
  const camera::CameraTarget target =
      core::cameraTarget(*stage_, scene, status.face, static_cast<float>(status.x), static_cast<float>(status.y));
  previous_ = camera_.pose();
  if (!placed_) {
    camera_.set(target, 1280, 720);
    previous_ = camera_.pose();
  } else {
    camera_.lerp(target, stepSeconds);
  }
  if (placed_) feedback_.step(scene, status);  // not the placing call: no frame was played
  redraw(scene);
  if (!placed_) previousDrawing_ = drawing_;
  placed_ = true;
}

void GameView::idle(core::Scene& scene) {
  previous_ = camera_.pose();
  feedback_.advance();
  redraw(scene);
}

void GameView::redraw(core::Scene& scene) {
  std::swap(previousDrawing_, drawing_);
  drawing_.clear();
  scene.draw(drawing_);
  feedback_.draw(drawing_);
  if (debug_) core::drawDebug(scene, drawing_);
  ++steps_;
}

core::DrawList GameView::drawing(double alpha) const {
  return core::DrawList::between(previousDrawing_, drawing_, static_cast<float>(alpha));
}

core::View GameView::view(const core::Scene& scene, double alpha) const {
  core::View v;
  v.title = scene.manifest().name;
  v.stage = stage_;
  v.face = face_;
  v.openTags = openTags_;
  v.camera = camera::CameraPose::between(previous_, camera_.pose(), alpha);
  if (const double shake = feedback_.shake(); shake > 0) {  // across the view, a fixed wobble
    const double t = static_cast<double>(steps_) + alpha;
    v.camera.centre +=
        v.camera.orientation * Eigen::Vector3d(std::sin(t * 2.3), std::cos(t * 1.7), 0) * (shake * v.camera.distance);
  }
  v.verticalFov = camera_.settings().verticalFov;
  return v;
}

}  // namespace platon::session

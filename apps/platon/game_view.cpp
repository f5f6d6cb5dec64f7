#include "game_view.h"

namespace platon::app {

void GameView::step(const core::Scene& scene, const script::GameStatus& status, double stepSeconds) {
  if (&scene != scene_ || !stage_ || (stage_->flat && status.face != flatPart_)) {
    stage_ = core::stageView(scene, status.face);
    scene_ = &scene;
    flatPart_ = status.face;
  }
  face_ = status.face;
  const camera::CameraTarget target =
      core::cameraTarget(*stage_, scene, status.face, static_cast<float>(status.x), static_cast<float>(status.y));
  previous_ = camera_.pose();
  if (!placed_) {
    camera_.set(target, 1280, 720);
    previous_ = camera_.pose();
    placed_ = true;
  } else {
    camera_.lerp(target, stepSeconds);
  }
}

core::View GameView::view(const core::Scene& scene, double alpha) const {
  core::View v;
  v.title = scene.manifest().name;
  v.stage = stage_;
  v.face = face_;
  v.camera = camera::CameraPose::between(previous_, camera_.pose(), alpha);
  v.verticalFov = camera_.settings().verticalFov;
  return v;
}

}  // namespace platon::app

// The picture's state that outlives a frame: the stage as drawn (built again when the scene is
// reloaded) and the camera, stepped once per simulation step so that it is the same at any frame
// rate and in any screenshot of frame N; the renderer draws between its last two poses.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "platon/camera/camera.h"
#include "platon/core/display.h"
#include "platon/core/scene.h"
#include "platon/script/script_system.h"
#include "platon/session/feedback.h"

namespace platon::session {

// The scene's scripting status (the default when it has no scripts) and its display (null when
// it is not shown in a window).
script::GameStatus statusOf(core::Scene& scene);
core::Display* displayOf(core::Scene& scene);
// A time in frames as a clock: 1:05.25, or 1:05 as par times are written.
std::string clockText(uint64_t frames, bool hundredths = true);
// The heads-up lines of a level being played, the same in the game, `platon play` and
// `platon shot`: its name, clock and deaths, then its latest message (the game's says "goal
// reached" when it is).
std::vector<std::string> hudLines(const core::Scene& scene, const script::GameStatus& status);

class GameView {
 public:
  // After each simulation step (and once before the first: it places the camera at once).
  void step(core::Scene& scene, const script::GameStatus& status, double stepSeconds);
  // A step of the picture alone (the level-complete screen): the scene as it stands, the feedback's
  // particles moving on.
  void idle(core::Scene& scene);
  // The frame's view, `alpha` of the way from the previous step's camera to this one's.
  core::View view(const core::Scene& scene, double alpha) const;
  // What the scripts drew, `alpha` of the way from the previous step's picture to this one's.
  core::DrawList drawing(double alpha) const;
  const camera::Camera& camera() const { return camera_; }
  // The events' particles, flashes, shake and freezes (feedback.h).
  Feedback& feedback() { return feedback_; }
  // The debug overlay (core/debug_view.h) over the picture, from the next step on.
  void setDebug(bool on) { debug_ = on; }
  bool debug() const { return debug_; }

 private:
  // The step's picture: the scene's shapes and the feedback's, the last one kept to draw between.
  void redraw(core::Scene& scene);

  std::shared_ptr<const core::StageView> stage_;
  const core::Scene* scene_ = nullptr;  // the scene stage_ was built for (a reload makes another)
  physics::MapPartId flatPart_ = 0;
  camera::Camera camera_;
  camera::CameraPose previous_;
  core::DrawList previousDrawing_{true}, drawing_{true};
  physics::MapPartId face_ = 0;
  std::vector<uint32_t> openTags_;
  bool placed_ = false;
  Feedback feedback_;
  uint64_t steps_ = 0;  // the shake's phase
  bool debug_ = false;
};

}  // namespace platon::session

#include "platon/core/run.h"

#include "platon/core/live_scene.h"
#include "platon/core/scene.h"

namespace platon::core {

Run::Run(LiveScene& live) : live_(&live) {}
Run::Run(Scene& scene) : scene_(&scene) {}

Scene& Run::scene() { return live_ ? live_->scene() : *scene_; }

std::optional<ConsoleAnswer> Run::console(const std::string& code) {
  Scene& s = scene();
  for (size_t i = 0; i < s.systemCount(); ++i) {
    if (Console* c = s.system(i).console()) {
      ConsoleAnswer answer = c->run(code);
      if (recorder_) recorder_->console(code);
      return answer;
    }
  }
  return std::nullopt;
}

std::optional<std::string> Run::step(Buttons held) {
  const InputFrame input{held, static_cast<Buttons>(held & ~previous_)};
  previous_ = held;
  ++frame_;
  std::optional<std::string> error;
  if (live_)
    error = live_->step(input);
  else
    scene_->step(input);
  if (recorder_) recorder_->frame(held, scene().world().stateHash());
  return error;
}

void Run::record(const RunRecording& how) {
  recorder_.emplace(how.scene, how.hashEvery, how.sceneFiles);
  recorder_->setStart(how.start);
  recorder_->setSpeed(how.speed);
  recorder_->setActions(ActionNames(scene().actions()));
}

std::optional<Replay> Run::stopRecording() {
  std::optional<Replay> replay = recorded();
  recorder_.reset();
  return replay;
}

std::optional<Replay> Run::recorded() const {
  if (!recorder_) return std::nullopt;
  return recorder_->replay();
}

ReplayInput::ReplayInput(const Replay& replay, const Scene& scene)
    : replay_(replay), map_(replay.actions, scene.actions()) {}

Buttons ReplayInput::next(Run& run, const std::function<void(const std::string&, const ConsoleAnswer&)>& typed) {
  const uint64_t coming = run.frame() + 1;
  for (; nextLine_ < replay_.console.size() && replay_.console[nextLine_].frame <= coming; ++nextLine_) {
    const std::string& code = replay_.console[nextLine_].code;
    const std::optional<ConsoleAnswer> answer = run.console(code);
    if (typed) typed(code, answer.value_or(ConsoleAnswer{false, "this scene has no console (no scripts)"}));
  }
  return coming <= replay_.frames() ? map_(replay_.held[coming - 1]) : 0;
}

}  // namespace platon::core

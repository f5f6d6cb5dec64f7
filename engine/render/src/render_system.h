// The rendering system: a window showing the face the player is on, its map lines coloured by tag,
// what the scripts drew (core::DrawList), the heads-up lines and the error overlay. The window
// opens on first use and is shared with the new version of the system on a hot reload (kept by
// whichever version stays live, even when a later system refuses the reload), so a reload never
// reopens it.
#pragma once
#include <memory>
#include <optional>

#include "platon/core/display.h"
#include "platon/core/system.h"

namespace platon::render {

class RenderSystem final : public core::System, public core::Display {
 public:
  RenderSystem();
  ~RenderSystem() override;

  void carryOver(core::Scene& scene, core::System& previous) override;
  core::Display* display() override { return this; }

  core::WindowInput pollEvents() override;
  void resize(int width, int height) override;
  void present(const core::View& view, const core::DrawList& draw) override;
  std::vector<uint8_t> capture(int& width, int& height) override;
  void saveScreenshot(const std::string& path) override;
  std::vector<std::string> setBindings(const core::KeyBindings& bindings) override;
  void setFullscreen(bool on) override;
  void setVsync(bool on) override;
  void setMultisamples(int samples) override;

 private:
  struct Gl;
  Gl& gl();
  void paint(const core::View& view, const core::DrawList& draw);

  std::shared_ptr<Gl> gl_;                     // shared across a hot reload (carryOver)
  int firstWidth_ = 1280, firstHeight_ = 720;  // the window's size when it opens
  std::optional<core::View> lastView_;
  uint64_t lastPresent_ = 0;  // SDL's performance counter at the last present
  double frameSeconds_ = 0;   // smoothed time between presents, for the frame-rate counter
  core::DrawList lastDraw_{true};
};

}  // namespace platon::render

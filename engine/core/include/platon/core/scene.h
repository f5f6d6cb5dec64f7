// One running level: its physics world, the stage its faces came from, and the systems it asked
// for. A frame is: systems read the input, physics solves, systems see the result.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "platon/core/system.h"
#include "platon/physics/world.h"
#include "platon/stage/solid_net.h"

namespace platon::core {

class Scene {
 public:
  physics::World& world() { return world_; }
  const physics::World& world() const { return world_; }

  // The solid the level is drawn on, once built into the world.
  void setStage(stage::SolidNet net) { stage_ = std::move(net); }
  const stage::SolidNet* stage() const { return stage_ ? &*stage_ : nullptr; }

  // Systems run in the order they were added.
  void addSystem(std::unique_ptr<System> system);
  size_t systemCount() const { return systems_.size(); }

  // One fixed frame.
  physics::SolveReport step(const InputFrame& input);
  uint64_t frame() const { return world_.frame(); }
  // Asks every system what to draw; does nothing when the list is disabled (no renderer).
  void draw(DrawList& out) const;

 private:
  physics::World world_;
  std::optional<stage::SolidNet> stage_;
  std::vector<std::unique_ptr<System>> systems_;
};

}  // namespace platon::core

#include "game_in_cpp.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace platon::bench {
namespace {

using physics::EntityId;
constexpr double kQ16 = 65536.0;
constexpr uint32_t kHazard = 1, kGoal = 2, kCheckpoint = 3, kDoor = 1000, kSwitch = 2000;

struct Place {
  physics::MapPartId face;
  int32_t x, y;
};

class Game final : public core::System, public physics::Rules {
 public:
  // scripts/progression.lua: start(); scripts/scene.lua: start() sets the rules.
  void start(core::Scene& scene) override {
    world_ = &scene.world();
    world_->setRules(this);
    const stage::LevelPoint& start = scene.level()->start;  // world.levelStart()
    start_ = Place{static_cast<physics::MapPartId>(start.face), start.position.x, start.position.y};
    message_ = "walk right: every edge turns the cube";  // levels/cube_intro/level.lua: build()
    spawn(spawnPoint());
  }

  void beforeStep(core::Scene&, const core::InputFrame& input) override {
    tick(input);
    pressedRestart_ = input.wasPressed(core::Button::Restart);
  }

  // scripts/progression.lua: afterStep()
  void afterStep(core::Scene&) override {
    ++time_;
    for (const uint32_t id : pendingToggles_) {
      switches_[id] = !switches_[id];
      world_->refreshPierce(kDoor + id);
    }
    pendingToggles_.clear();
    if (touchedCheckpoint_) {
      touchedCheckpoint_ = false;
      const physics::InstanceView anchor = world_->entity(player_).instance(0);
      checkpoint_ = Place{anchor.part, anchor.position.x, anchor.position.y};
    }
    if (reachedGoal_ && !won_) {
      won_ = true;
      message_ = "goal reached";
    }
    if (killed_ || (pressedRestart_ && !won_)) {
      killed_ = false;
      ++deaths_;
      world_->destroyEntity(player_);
      spawn(spawnPoint());
    }
  }

  // scripts/rules/game.lua
  bool pierce(EntityId, const physics::LineRef& line) override {
    if (line.kind == physics::LineKind::Warp) return true;
    if (line.tag == kGoal || line.tag == kCheckpoint) return true;
    if (line.tag >= kSwitch && line.tag < kSwitch + 1000) return true;
    if (line.tag >= kDoor && line.tag < kDoor + 1000) return switches_[line.tag - kDoor];
    return false;
  }
  void beginContact(const physics::Contact& c) override {
    if (c.entity != player_) return;
    if (c.line.tag == kGoal)
      reachedGoal_ = true;
    else if (c.line.tag == kCheckpoint)
      touchedCheckpoint_ = true;
    else if (c.line.tag >= kSwitch && c.line.tag < kSwitch + 1000)
      pendingToggles_.push_back(c.line.tag - kSwitch);
  }
  void contact(const physics::Contact& c, physics::ContactResponse&) override {
    if (c.line.tag == kHazard && c.entity == player_) killed_ = true;
  }
  void crushed(const physics::Contact& c) override {
    if (c.entity == player_) killed_ = true;
  }

 private:
  Place spawnPoint() const { return checkpoint_.value_or(start_); }

  void spawn(Place at) {
    player_ = world_->createEntity(physics::Convex::regular(16, 96));
    world_->insert(player_, at.face, {at.x, at.y}, 0);
    coyote_ = buffer_ = 0;
    grounded_ = false;
  }

  static double approach(double value, double target, double step) {
    if (value < target) return std::min(value + step, target);
    return std::max(value - step, target);
  }

  // scripts/player.lua: Player.tick, with the same arithmetic in the same order.
  void tick(const core::InputFrame& input) {
    constexpr double kWalk = 9, kGroundAccel = 0.6, kBrake = 0.9, kAirAccel = 0.35, kJump = 11, kCut = 4;
    constexpr int kCoyote = 6, kBuffer = 6;
    constexpr double kGroundCos = 0.64;
    const physics::EntityView e = world_->entity(player_);
    const physics::Vec2w gq = world_->mapPart(e.instance(0).part).gravity();
    const double gx = static_cast<double>(gq.x) / kQ16, gy = static_cast<double>(gq.y) / kQ16;
    const double g = std::sqrt(gx * gx + gy * gy);
    double dx = 0, dy = -1;
    if (g > 0) dx = gx / g, dy = gy / g;
    const double rx = -dy, ry = dx;

    grounded_ = false;
    for (const physics::Contact& c : e.contacts()) {
      const double cx = static_cast<double>(c.normal.x), cy = static_cast<double>(c.normal.y);
      const double length = std::sqrt(cx * cx + cy * cy);  // as lua::unitNormal
      const double nx = length > 0 ? cx / length : 0, ny = length > 0 ? cy / length : 0;
      if (-(nx * dx + ny * dy) > kGroundCos) grounded_ = true;
    }
    if (grounded_)
      coyote_ = kCoyote;
    else if (coyote_ > 0)
      --coyote_;
    if (input.wasPressed(core::Button::Jump))
      buffer_ = kBuffer;
    else if (buffer_ > 0)
      --buffer_;

    const double vx = static_cast<double>(e.velocity().x) / kQ16, vy = static_cast<double>(e.velocity().y) / kQ16;
    double along = vx * rx + vy * ry;
    double fall = vx * dx + vy * dy;
    const int dir = (input.isHeld(core::Button::Right) ? 1 : 0) - (input.isHeld(core::Button::Left) ? 1 : 0);
    const double accel = grounded_ ? kGroundAccel : kAirAccel;
    if (dir != 0)
      along = approach(along, dir * kWalk, accel);
    else if (grounded_)
      along = approach(along, 0, kBrake);
    if (buffer_ > 0 && coyote_ > 0) {
      fall = -kJump;
      buffer_ = coyote_ = 0;
    } else if (!input.isHeld(core::Button::Jump) && fall < -kCut) {
      fall = -kCut;
    }
    world_->setVelocity(player_,
                        {std::llround((rx * along + dx * fall) * kQ16), std::llround((ry * along + dy * fall) * kQ16)});
  }

  physics::World* world_ = nullptr;
  EntityId player_;
  int coyote_ = 0, buffer_ = 0;
  bool grounded_ = false;
  std::map<uint32_t, bool> switches_;
  std::vector<uint32_t> pendingToggles_;
  Place start_{};
  std::optional<Place> checkpoint_;
  bool reachedGoal_ = false, touchedCheckpoint_ = false, killed_ = false, won_ = false, pressedRestart_ = false;
  int deaths_ = 0;
  uint64_t time_ = 0;
  std::string message_;
};

}  // namespace

std::unique_ptr<core::Scene> cubeIntroInCpp() {
  // The scene as the engine loads it (the level file's stage, lines, gravity and goal), with this
  // game standing in for the scripts.
  core::SystemRegistry registry;
  registry.add("scripting", [](core::Scene&) { return std::make_unique<Game>(); });
  return core::loadScene(std::string(PLATON_SOURCE_ROOT) + "/levels/cube_intro/scene.lua", registry);
}

}  // namespace platon::bench

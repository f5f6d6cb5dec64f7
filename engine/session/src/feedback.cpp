#include "platon/session/feedback.h"

#include <algorithm>
#include <cmath>

namespace platon::session {

// Sparks start on a ring about the size of the game's player (96 units): any nearer is hidden in it.
constexpr float kRim = 100;

const std::vector<Cue>& cues() {
  // Colours read apart for the common colour blindnesses: they differ in lightness as well as hue.
  static const std::vector<Cue> kCues = {
      // sound, particles, speed, up, life, size, colour, flash frames, flash, shake, freeze, before, below
      {"jump", 10, 7, 0.3f, 18, 30, {170, 160, 140, 230}, 0, {}, 0, 0, false, 90},
      {"land", 14, 9, 0.35f, 20, 34, {150, 140, 120, 230}, 0, {}, 0.002f, 0, false, 90},
      {"cross", 16, 10, 0, 22, 26, {150, 210, 255, 230}, 0, {}, 0, 0, false, 0},
      {"death", 36, 26, 0, 44, 44, {255, 90, 40, 255}, 14, {200, 30, 20, 110}, 0.012f, 6, true, 0},
      {"respawn", 18, 12, 0, 24, 28, {255, 255, 255, 220}, 0, {}, 0, 0, false, 0},
      {"checkpoint", 26, 16, 0.8f, 38, 32, {90, 230, 120, 255}, 8, {60, 200, 90, 60}, 0, 0, false, 0},
      {"switch", 18, 14, 0.5f, 26, 28, {255, 220, 60, 255}, 6, {255, 220, 60, 50}, 0, 0, false, 0},
      {"door", 0, 0, 0, 0, 0, {}, 0, {}, 0.004f, 0, false, 0},
      {"goal", 60, 24, 0.7f, 72, 36, {255, 200, 60, 255}, 18, {255, 250, 220, 130}, 0.006f, 8, false, 0},
  };
  return kCues;
}

void Feedback::step(const core::Scene& scene, const script::GameStatus& status) {
  advance();
  // A death's sparks fly where the player died, before the respawn this same frame moved it.
  const Place now{status.face, static_cast<float>(status.x), static_cast<float>(status.y)};
  const Place before = last_.value_or(now);
  last_ = now;
  for (const core::SoundEvent& e : scene.sounds().thisFrame()) {
    const auto cue = std::find_if(cues().begin(), cues().end(), [&](const Cue& c) { return c.sound == e.name; });
    if (cue != cues().end()) start(*cue, scene, cue->whereBefore ? before : now);
  }
  // A burst never fills the picture: the oldest go first.
  if (particles_.size() > 400) particles_.erase(particles_.begin(), particles_.end() - 400);
}

void Feedback::advance() {
  // Every particle moves on, falls along its face's down, and fades at the end of its life.
  for (Particle& p : particles_) {
    p.vx += p.gx, p.vy += p.gy;
    p.x += p.vx, p.y += p.vy;
    p.vx *= 0.96f, p.vy *= 0.96f;
    ++p.age;
  }
  std::erase_if(particles_, [](const Particle& p) { return p.age >= p.life; });
  shake_ *= 0.85f;
  if (flashLeft_ > 0) --flashLeft_;
}

void Feedback::start(const Cue& cue, const core::Scene& scene, const Place& at) {
  shake_ = std::max(shake_, cue.shake);
  freeze_ = std::max(freeze_, cue.freezeFrames);
  if (cue.flashFrames > 0) flash_ = cue.flash, flashLeft_ = flashFrames_ = cue.flashFrames;
  const physics::MapPart* part = scene.world().findMapPart(at.face);
  if (!part) return;
  const auto gravity = part->gravity();
  const float gx = static_cast<float>(gravity.x) / 65536.0f, gy = static_cast<float>(gravity.y) / 65536.0f;
  const float g = std::hypot(gx, gy);
  const float dx = g > 0 ? gx / g : 0, dy = g > 0 ? gy / g : -1;  // down
  for (int i = 0; i < cue.particles; ++i) {
    // A fixed sequence (not the machine's randomness): a shot of frame N shows what the game did.
    random_ = random_ * 1664525u + 1013904223u;
    const float angle = static_cast<float>(random_ >> 8) / 16777216.0f * 6.2831853f;
    random_ = random_ * 1664525u + 1013904223u;
    const float speed = cue.speed * (0.35f + 0.65f * static_cast<float>(random_ >> 8) / 16777216.0f);
    const float cx = std::cos(angle), cy = std::sin(angle);
    float vx = cx * speed, vy = cy * speed;
    vx -= dx * cue.up * cue.speed, vy -= dy * cue.up * cue.speed;  // up is against down
    // From the player's rim (a spark inside the ball would not show), or below it (a jump's dust).
    const float rim = cue.below > 0 ? 0 : kRim;
    particles_.push_back({at.face, at.x + dx * cue.below + cx * rim, at.y + dy * cue.below + cy * rim, vx, vy,
                          dx * 0.6f, dy * 0.6f, 0, cue.life, cue.size, cue.color});
  }
}

void Feedback::draw(core::DrawList& out) const {
  for (const Particle& p : particles_) {
    const float left = 1 - static_cast<float>(p.age) / static_cast<float>(p.life);
    core::Color c = p.color;
    c.a = static_cast<uint8_t>(static_cast<float>(c.a) * std::min(1.0f, 2 * left));
    out.circle(core::Place::onFace(p.face), {p.x, p.y}, p.size * (0.5f + 0.5f * left), c);
  }
  if (flashLeft_ > 0) {
    core::Color c = flash_;
    c.a = static_cast<uint8_t>(static_cast<float>(c.a) * static_cast<float>(flashLeft_) /
                               static_cast<float>(flashFrames_));
    const core::Point2 screen[] = {{0, 0}, {0, 16384}, {16384, 16384}, {16384, 0}};
    out.polygon(core::Place::onScreen(), screen, c);
  }
}

}  // namespace platon::session

// PlatonWorld (platon_world.h).
#include "platon_world.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "platon/testing/si_units.h"

namespace platon::bench {

using namespace platon::physics;

PlatonWorld::PlatonWorld(int unitsPerMetre, double hz)
    : upm_(unitsPerMetre), hz_(hz), part_(&world_.createMapPart(1)) {}

PlatonWorld::~PlatonWorld() = default;

std::string PlatonWorld::name() const {
  return "Platon " + std::to_string(upm_) + "u/m " + std::to_string(std::lround(hz_)) + "Hz";
}

void PlatonWorld::setGravity(double gx, double gy) { part_->setGravity({q16(gx / hz_), q16(gy / hz_)}); }

void PlatonWorld::addSegment(double x0, double y0, double x1, double y1, bool sensor) {
  if (sensor) throw std::invalid_argument("PlatonWorld: no sensors");
  const Vec2 a = units(x0, y0), b = units(x1, y1);
  part_->line(a, b);
  segments_.push_back({metres(a.x), metres(a.y), metres(b.x), metres(b.y)});
}

int PlatonWorld::addBody(const Polygon& convexCCW, double x, double y, bool) {
  if (!part_->initialized()) part_->initialize();
  std::vector<Vec2> verts;
  for (const auto& [vx, vy] : convexCCW) verts.push_back(units(vx, vy));
  const EntityId id = world_.createEntity(Convex(verts));
  for (Vec2 at = units(x, y);; ++at.y) {
    try {
      world_.insert(id, part_->id(), at, 0);
      break;
    } catch (const Error&) {
      if (at.y > units(x, y).y + 4) throw;
    }
  }
  bodies_.push_back(id);
  return static_cast<int>(bodies_.size()) - 1;
}

void PlatonWorld::setVelocity(int body, double vx, double vy) {
  world_.setVelocity(bodies_.at(body), {q16(vx), q16(vy)});
}

void PlatonWorld::setAngularVelocity(int body, double w) {
  world_.setAngularVelocity(bodies_.at(body),
                            static_cast<int32_t>(std::lround(w / hz_ / (2 * std::numbers::pi) * 0x1p32)));
}

void PlatonWorld::setRestitution(double restitution) {
  if (restitution != 0 && restitution != 1) throw std::invalid_argument("PlatonWorld: restitution is 0 or 1");
  bounce_ = restitution == 1 ? std::make_unique<ElasticBounce>() : nullptr;
  world_.setRules(bounce_.get());
}

void PlatonWorld::step(double dt) {
  if (std::fabs(dt * hz_ - 1) > 1e-9) throw std::invalid_argument("PlatonWorld: the frame rate is fixed");
  world_.solve();
}

Pose PlatonWorld::pose(int body) const {
  const EntityView e = world_.entity(bodies_.at(body));
  const Vec2 p = e.instance(0).position;
  return {metres(p.x), metres(p.y), e.angle() * (2 * std::numbers::pi) * 0x1p-32};
}

Polygon PlatonWorld::shape(int body) const {
  Polygon out;
  for (const Vec2 v : world_.entity(bodies_.at(body)).shape().vertices()) out.push_back({metres(v.x), metres(v.y)});
  return out;
}

Vec2 PlatonWorld::units(double x, double y) const { return platon::testing::pointFromMetres(x, y, upm_); }

int64_t PlatonWorld::q16(double v) const { return platon::testing::q16FromSpeed(v, upm_, hz_); }

}  // namespace platon::bench

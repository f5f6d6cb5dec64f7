// Platon behind the PeerWorld interface (peer.h), so the numerics benchmarks run the same scenes in
// all three engines. Platon counts frames, not seconds: the frame rate is fixed at construction and
// SI values are converted once (lengths to whole units, velocities to 1/65536 units per frame,
// gravity to 1/65536 units per frame squared). One map part, no sensors.
#pragma once
#include <memory>
#include <vector>

#include "peer.h"
#include "platon/physics/world.h"

namespace platon::bench {

class PlatonWorld final : public PeerWorld {
 public:
  PlatonWorld(int unitsPerMetre, double hz);
  ~PlatonWorld() override;

  std::string name() const override;
  void setGravity(double gx, double gy) override;
  void addSegment(double x0, double y0, double x1, double y1, bool sensor = false) override;
  // The start is rounded to whole units; a start that then overlaps a line (a sloped line passes
  // between units) is raised one unit at a time, so it begins within a unit of the exact contact.
  int addBody(const Polygon& convexCCW, double x, double y, bool fixedRotation = true) override;
  void setVelocity(int body, double vx, double vy) override;
  void setAngularVelocity(int body, double w) override;
  // Platon has no restitution; 1 installs ElasticBounce (below), 0 the default contact response.
  void setRestitution(double restitution) override;
  void step(double dt) override;
  Pose pose(int body) const override;
  int sensorBeginEvents() const override { return 0; }

  size_t overlaps() const { return world_.countOverlaps(); }
  // The geometry as Platon holds it (rounded to units), for the measurements. The shape is the
  // unrotated one.
  const Segments& segments() const { return segments_; }
  Polygon shape(int body) const;

 private:
  physics::Vec2 units(double x, double y) const;
  double metres(int64_t u) const { return static_cast<double>(u) / upm_; }
  int64_t q16(double v) const;

  int upm_;
  double hz_;
  physics::World world_;
  physics::MapPart* part_;
  std::unique_ptr<physics::Rules> bounce_;
  Segments segments_;
  std::vector<physics::EntityId> bodies_;
};

// An elastic bounce as a Platon user writes one: a contact rule that asks for restitution 1
// (ContactResponse::restitution; the world then bounces exactly, see docs/physics.md).
class ElasticBounce final : public physics::Rules {
 public:
  void contact(const physics::Contact&, physics::ContactResponse& response) override { response.restitution = {1, 1}; }
};

}  // namespace platon::bench

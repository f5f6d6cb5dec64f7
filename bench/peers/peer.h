// Peer engines behind one small interface, so benchmarks can run the same scene in Box2D 2.4.1 and
// Chipmunk 7.0.3 and measure them the same way.
//
// Debian builds both libraries without NDEBUG: Box2D's b2Assert checks (assert) and Chipmunk's
// cpAssertSoft/cpAssertWarn run in every call. bench/assertion_cost measures what that costs
// against NDEBUG builds of the same Debian sources (tools/peers_ndebug.sh).
//
// Everything is SI: metres, seconds, radians. Static geometry is segments on one static body;
// bodies are dynamic convex polygons (counter-clockwise vertices relative to the body origin,
// at most 8 for Box2D). Unless a scene sets them otherwise, friction and restitution are zero,
// so a body slides like Platon's entities (which have no friction).
//
//   Box2D 2.4.1: two-sided b2EdgeShape fixtures on one static body (Platon's lines block from both
//     sides); each body a b2PolygonShape fixture of density 1 with the engine's skin
//     (b2_polygonRadius = 1 cm); sleeping allowed (the default).
//   Chipmunk 7.0.3: cpSegmentShape of radius 0 on the space's static body; cpPolyShape of radius 0,
//     mass from density 1, moment infinite for fixed rotation; cpSpaceSetIterations; collision slop
//     5 mm (Box2D's linear slop: Chipmunk's default of 0.1 is meant for pixel units and would be
//     10 cm here), the default bias; sleeping off (the default).
//
// The measurement helpers work in long double on a reported pose, so they judge every engine,
// Platon included, by the same yardstick.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace platon::bench {

using Polygon = std::vector<std::array<double, 2>>;   // convex, counter-clockwise, body frame
using Segments = std::vector<std::array<double, 4>>;  // x0, y0, x1, y1 in world metres

struct Pose {
  double x, y, angle;  // body origin (metres) and rotation (radians)
};

class PeerWorld {
 public:
  virtual ~PeerWorld() = default;
  // Engine, version and solver setting, plus the step rate once step() has been called,
  // e.g. "Box2D 2.4.1 v8p3 60Hz".
  virtual std::string name() const = 0;
  virtual void setGravity(double gx, double gy) = 0;  // m/s^2
  // A static segment (metres). A sensor reports overlaps and never collides.
  virtual void addSegment(double x0, double y0, double x1, double y1, bool sensor = false) = 0;
  // A dynamic body; returns its index for the calls below.
  virtual int addBody(const Polygon& convexCCW, double x, double y, bool fixedRotation = true) = 0;
  virtual void setVelocity(int body, double vx, double vy) = 0;  // m/s
  virtual void setAngularVelocity(int body, double w) = 0;       // rad/s
  // Restitution of every shape, present and future (0 by default; 1: perfectly elastic). Platon has
  // no restitution: its adapter answers with a contact rule (platon_world.h).
  virtual void setRestitution(double restitution) = 0;
  virtual void step(double dt) = 0;  // seconds
  virtual Pose pose(int body) const = 0;
  virtual int sensorBeginEvents() const = 0;  // sensor begin events so far, all bodies
};

// velocityIterations / positionIterations as b2World::Step takes them (Box2D's default is 8 / 3).
std::unique_ptr<PeerWorld> makeBox2D(int velocityIterations, int positionIterations);
// cpSpaceSetIterations (Chipmunk's default is 10) and cpSpaceSetCollisionSlop (metres).
std::unique_ptr<PeerWorld> makeChipmunk(int iterations, double collisionSlop = 0.005);

// How deep the polygon placed at `pose` overlaps the interior of any segment: the largest, over
// the segments, of the shortest push that separates the two (metres); 0 when none overlaps.
double penetrationDepth(const Polygon& convexCCW, Pose pose, const Segments& segments);
// Distance from the polygon at `pose` to the nearest segment (metres); 0 if one touches or
// overlaps it; infinity without segments.
double gapToNearest(const Polygon& convexCCW, Pose pose, const Segments& segments);

}  // namespace platon::bench

// The frame step of one entity: rotation, gravity, then the slide. Each sub-move of the slide
// sweeps every instance, moves all of them to the earliest contact, fires the events along the
// way, and projects the rest of the motion along the line it met.
#include <algorithm>
#include <array>

#include "bounce.h"
#include "bounds.h"
#include "contact_normal.h"
#include "fixed_point.h"
#include "projection.h"
#include "world_impl.h"

namespace platon::physics {
namespace {

enum class HitKind { None, Solid, Bound, Warp, Entity };

// The earliest event of a sub-move.
struct Hit {
  HitKind kind = HitKind::None;
  Fraction t = Fraction::one();
  size_t instance = 0;
  LineIndex line = 0;
  Sweep sweep;
  Constraint axis;
  uint32_t otherSlot = 0;  // HitKind::Entity: the entity met (its `line` is kEntityKey | slot)
  bool crease = false;     // no open direction makes progress: the body stops here (see slideAlong)

  // Earlier wins. At equal times: a solid contact before a warp (so walls at edges hold), then the
  // lower instance, then the lower line index. The order never depends on the grid or on the
  // order lines entered a region, so the same map gives the same motion however it is indexed.
  bool improvedBy(Fraction when, HitKind kind2, size_t instance2, LineIndex line2) const {
    if (kind == HitKind::None) return when < Fraction::one();
    if (when != t) return when < t;
    const bool warp = kind == HitKind::Warp, warp2 = kind2 == HitKind::Warp;
    if (warp != warp2) return warp;
    if (instance2 != instance) return instance2 < instance;
    return line2 < line;
  }
};

// Entities met in a sub-move are ordered after lines at equal times, by slot.
constexpr LineIndex kEntityKey = 0x80000000u;

// Whether t * m is whole: then the rounded step lies on the swept path itself.
bool exactMove(Vec2w m, Fraction t) {
  return t == Fraction::one() || ((i128{t.num} * m.x) % t.den == 0 && (i128{t.num} * m.y) % t.den == 0);
}

// A copy keeps a lift of up to this many units off its ideal position (see liftAtSeam); a larger
// gap is closed as soon as the way is free.
constexpr int64_t kCopyLift = 3;

// How far a copy stands off its ideal position, in whole units (the larger coordinate).
int64_t offIdeal(const Instance& copy) {
  const Vec2 ideal = pointFromQ30(copy.idealQ30), at = copy.position;
  return std::max(std::abs(int64_t{ideal.x} - at.x), std::abs(int64_t{ideal.y} - at.y));
}

// Whether every copy is where it may stay: within kCopyLift units of its ideal position. Otherwise
// it still owes a correction when the motion is spent.
bool copiesSettled(const Entity& e) {
  for (size_t i = 1; i < e.instances.size(); ++i)
    if (offIdeal(e.instances[i]) > kCopyLift) return false;
  return true;
}

// Whether an end of `seg` is within three units of a warp line near the instance: a line ending
// there is cut by a face edge and continues on the next face (a seam).
bool endNearWarpLine(WorldImpl& w, Instance& inst, const Segment& seg) {
  const MapPart& part = w.part(inst.part);
  const auto lines = inst.region.lines();
  for (size_t k = 0; k < lines.size(); ++k) {
    if (part.lines()[lines[k]].kind != LineKind::Warp) continue;
    const Segment s = part.segments()[lines[k]];
    const Vec2w d = s.b - s.a;
    for (const Vec2 point : {seg.a, seg.b}) {
      const Vec2w pa = point - s.a, pb = point - s.b;
      if (dot128(pa, pa) <= 9 || dot128(pb, pb) <= 9) return true;
      const i128 along = dot128(pa, d), across = cross128(d, pa);
      if (along >= 0 && along <= dot128(d, d) && across * across <= 9 * dot128(d, d)) return true;
    }
  }
  return false;
}

// One sub-move of the slide, in the order of its steps. The per-instance arrays are the world's
// scratch buffers.
class SubMove {
 public:
  SubMove(WorldImpl& world, Move& move)
      : w_(world),
        move_(move),
        e_(move.entity),
        n_(e_.instances.size()),
        verts_(world.scratch.verts),
        moves_(world.scratch.moves),
        steps_(world.scratch.steps),
        pierceNear_(world.scratch.pierceNear) {}

  // 1. Each instance's motion: the anchor's own; the others move as their ideal position does (the
  //    anchor's motion turned into their frame). Closing the gap to the ideal is a separate step
  //    after the move (commit), so a copy that rounding left a unit off never holds the entity back.
  void planMotions() {
    subMotion_ = move_.motion;
    verts_.resize(n_);
    moves_.resize(n_);
    pierceNear_.assign(n_, 0);
    for (size_t i = 0; i < n_; ++i) {
      Instance& inst = e_.instances[i];
      worldVertices(inst, verts_[i]);
      if (i == 0) {
        moves_[i] = move_.motion;
      } else {
        const Vec2w aim = inst.idealQ30 + rotateQ30(inst.rotation, move_.motion);
        moves_[i] = {unitsFromQ30(aim.x) - unitsFromQ30(inst.idealQ30.x),
                     unitsFromQ30(aim.y) - unitsFromQ30(inst.idealQ30.y)};
      }
      w_.coverMotion(inst, moves_[i]);
    }
  }

  // 2. The earliest event over all instances: a solid line, the world's edge, or a warp whose target
  //    has no instance yet (the move stops there so the new instance starts touching).
  void findFirstEvent() {
    uint32_t tested = 0;
    for (size_t i = 0; i < n_; ++i) {
      const Box box = sweptBox(e_.instances[i], moves_[i]);  // verts_[i] are where the instance is
      tested += firstLineHit(i, box);
      firstBoundHit(i, box);
      if (moves_[i] != Vec2w{}) tested += firstMovingHit(i, box);
    }
    e_.work += tested;
    w_.report.tested += tested;
  }

  // Instance i's first hit of its part's own lines (and which pierceable lines are near it): the
  // lines tested.
  uint32_t firstLineHit(size_t i, const Box& box) {
    Instance& inst = e_.instances[i];
    const MapPart& part = w_.part(inst.part);
    const auto lines = inst.region.lines();
    for (size_t k = 0; k < lines.size(); ++k) {
      const Segment& seg = part.segments()[lines[k]];
      if (outside(seg, box)) continue;
      const bool pierce = w_.isPierceable(e_, inst, k);
      pierceNear_[i] |= pierce;
      if (moves_[i] == Vec2w{}) continue;
      const Line& line = part.lines()[lines[k]];
      if (!pierce && !w_.blocks(e_, inst, k, verts_[i])) continue;  // a one-way line, from behind
      if (pierce && (line.kind != LineKind::Warp || e_.instanceIn(part.warps()[line.warp].target) != nullptr)) continue;
      const Sweep s = sweep(verts_[i], moves_[i], seg);
      if (line.kind == LineKind::Warp && !pierce && s.startsInside()) {
        // A warp that cannot be crossed this frame (no room on the far side) already overlapped:
        // it still holds, so the instance may not go any further across it. Its face lies to the
        // left of the warp line.
        const Vec2w into{-(seg.b.y - seg.a.y), seg.b.x - seg.a.x};
        if (dot(moves_[i], into) < 0 && hit_.improvedBy(Fraction::zero(), HitKind::Solid, i, lines[k]))
          hit_ = {HitKind::Solid, Fraction::zero(), i, lines[k], s, {0, -into}};
        continue;
      }
      if (!s.hitsWithinFrame()) continue;
      const HitKind kind = pierce ? HitKind::Warp : HitKind::Solid;
      if (hit_.improvedBy(s.enter, kind, i, lines[k])) hit_ = {kind, s.enter, i, lines[k], s, s.enterAxis};
    }
    return static_cast<uint32_t>(lines.size());
  }

  // Instance i reaching the world's edge.
  void firstBoundHit(size_t i, const Box& box) {
    Constraint bounds[4];
    for (const Constraint& c : boundConstraints(verts_[i], box, bounds)) {
      const int64_t rate = dot(c.c, moves_[i]);
      if (rate <= 0 || rate <= c.slack) continue;  // not reached within the frame (t = slack / rate >= 1)
      const Fraction when{c.slack, rate};
      if (hit_.improvedBy(when, HitKind::Bound, i, kWorldBoundLine))
        hit_ = {HitKind::Bound, when, i, kWorldBoundLine, {}, c};
    }
  }

  // Instance i's first hit of what moves: platforms' lines and solid bodies; the ones tested.
  uint32_t firstMovingHit(size_t i, const Box& box) {
    uint32_t tested = 0;
    const Instance& inst = e_.instances[i];
    w_.forEachPlatformLine(inst.part, box, [&](const PlatformLine& l, LineIndex key) {
      ++tested;
      if ((l.kind == LineKind::OneWay && !wholyInFront(verts_[i], l.segment)) || w_.inPocket(e_, key)) return;
      const Sweep s = sweep(verts_[i], moves_[i], l.segment);
      if (s.hitsWithinFrame() && hit_.improvedBy(s.enter, HitKind::Solid, i, key))
        hit_ = {HitKind::Solid, s.enter, i, key, s, s.enterAxis};
    });
    std::vector<Vec2>& other = w_.scratch.probe;
    w_.forEachSolidNear(e_, inst.part, box, [&](const Entity& o, const Instance& oi) {
      ++tested;
      worldVertices(oi, other);
      const Sweep s = sweep(verts_[i], moves_[i], other);
      if (!s.hitsWithinFrame()) return;
      if (!w_.steppedThisFrame(o)) unsteppedMet_ = std::min(unsteppedMet_, o.id.index);
      const LineIndex key = kEntityKey | o.id.index;
      if (hit_.improvedBy(s.enter, HitKind::Entity, i, key))
        hit_ = {HitKind::Entity, s.enter, i, key, s, s.enterAxis, o.id.index};
    });
    return tested;
  }

  // At the instant of a solid hit, the lines the polygon touches decide where it slides
  // (contact_normal.h): along the open direction that keeps the most of its motion, whichever line
  // or edge of its own that runs along. None: a crease, and it stops.
  void resolveContactNormal() {
    if (hit_.kind != HitKind::Solid && hit_.kind != HitKind::Entity) return;
    const size_t i = hit_.instance;
    const Box box = sweptBox(e_.instances[i], moves_[i]);  // where verts_[i] are: a lift that failed moved nothing
    OpenDirections& open = w_.scratch.open;
    open.clear();
    addTouchingLines(i, box, open);
    addTouchingBodies(i, box, open);
    chooseSlide(i, open);
  }

  // Each line instance i touches at the hit's instant, its normals found once, then added to `open`
  // in line index order, so the choice never depends on the region's order.
  void addTouchingLines(size_t i, const Box& box, OpenDirections& open) {
    Instance& inst = e_.instances[i];
    const MapPart& part = w_.part(inst.part);
    const auto lines = inst.region.lines();
    std::vector<WorldImpl::TouchingLine>& touchingLines = w_.scratch.touchingLines;
    std::vector<Vec2w>& normals = w_.scratch.lineNormals;
    touchingLines.clear();
    normals.clear();
    // Met where it stands, the rest test may have asked the same of the same vertices.
    const WorldImpl::Scratch::TouchMemo& memo = w_.scratch.touchMemo;
    const bool standing = hit_.t == Fraction::zero() && memo.holds(inst.part, verts_[i]);
    auto touches = [&](LineIndex line, const Segment& seg) {
      const uint32_t begin = static_cast<uint32_t>(normals.size());
      if (const WorldImpl::TouchingLine* known = standing ? memo.find(line) : nullptr) {
        normals.insert(normals.end(), memo.normals.begin() + known->begin, memo.normals.begin() + known->end);
        touchingLines.push_back({line, begin, static_cast<uint32_t>(normals.size())});
      } else if (touchingNormals(verts_[i], moves_[i], hit_.t, seg, normals)) {
        touchingLines.push_back({line, begin, static_cast<uint32_t>(normals.size())});
      }
    };
    for (size_t k = 0; k < lines.size(); ++k) {
      const Segment& seg = part.segments()[lines[k]];
      if (!outside(seg, box) && w_.blocks(e_, inst, k, verts_[i])) touches(lines[k], seg);
    }
    w_.forEachPlatformLine(inst.part, box, [&](const PlatformLine& l, LineIndex key) {
      if ((l.kind != LineKind::OneWay || wholyInFront(verts_[i], l.segment)) && !w_.inPocket(e_, key))
        touches(key, l.segment);
    });
    addInKeyOrder(touchingLines, normals, open);
  }

  // Bodies touched at that instant are obstacles too (in slot order: the index's order is not part
  // of the result). One that can be pushed closes nothing unless it is the one met: sliding into it
  // pushes it.
  void addTouchingBodies(size_t i, const Box& box, OpenDirections& open) {
    std::vector<WorldImpl::TouchingLine>& touching = w_.scratch.touchingLines;
    std::vector<Vec2w>& normals = w_.scratch.lineNormals;
    std::vector<Vec2>& other = w_.scratch.probe;
    touching.clear();  // now the entities' slots
    w_.forEachSolidNear(e_, e_.instances[i].part, box, [&](const Entity& o, const Instance& oi) {
      if (o.filter.pushable && !(hit_.kind == HitKind::Entity && hit_.otherSlot == o.id.index)) return;
      worldVertices(oi, other);
      const uint32_t begin = static_cast<uint32_t>(normals.size());
      if (touchingNormals(verts_[i], moves_[i], hit_.t, other, normals))
        touching.push_back({o.id.index, begin, static_cast<uint32_t>(normals.size())});
    });
    addInKeyOrder(touching, normals, open);
  }

  static void addInKeyOrder(std::vector<WorldImpl::TouchingLine>& touching, const std::vector<Vec2w>& normals,
                            OpenDirections& open) {
    std::sort(touching.begin(), touching.end(),
              [](const WorldImpl::TouchingLine& a, const WorldImpl::TouchingLine& b) { return a.key < b.key; });
    for (const WorldImpl::TouchingLine& t : touching) {
      open.beginLine();
      for (uint32_t k = t.begin; k < t.end; ++k) open.addNormal(normals[k]);
    }
  }

  // Where instance i slides, given the directions its contacts leave open: along the open
  // direction that keeps the most of its motion; none is a crease, and it stops.
  void chooseSlide(size_t i, OpenDirections& open) {
    // Which way it wants to go: its exact motion (a copy's integer step is the anchor's turned and
    // rounded, and may point straight into a floor the exact motion slides along).
    const Vec2w wanted = i == 0 ? moves_[0] : shortDirection(rotateQ30(e_.instances[i].rotation, move_.motion));
    if (open.empty() || open.open(wanted)) return;
    int best = open.slideNormal(wanted);
    // Rounded down to whole units, a slow slide along a line can point a unit straight into it (its
    // remainder carried along the line may be negative), and a frame's exact motion can be all but
    // nothing. That is no crease if the exact motion, or else the velocity, goes along: it slides on.
    for (const Vec2w intent : {move_.exactQ17, e_.velocityQ16}) {
      if (best >= 0 || i > 0 || intent == Vec2w{}) break;
      if (open.open(shortDirection(intent))) return;
      best = open.slideNormal(shortDirection(intent));
    }
    if (best < 0) {
      hit_.crease = true;
      return;
    }
    hit_.axis = {0, -open.normals()[static_cast<size_t>(best)]};
  }

  // A copy sits where rounding put it (its shape and position are rounded in its own turned
  // frame), up to about a unit and a half from where the original maps; its integer steps zigzag
  // about the exact direction. So it can meet a line the original glides along: the floor that
  // continues across the edge, met face-on by a zigzag step or edge-on at its first point. Such a
  // hit is known by the copy's exact motion (the anchor's, turned into its frame) not moving into
  // the line; or, as before, by the copy being stopped at once after the original's own contact in
  // this frame. The same rounding puts either side of an edge up to two units off the line it
  // continues: an instance that meets, edge-on, the end of a line that lies on a face edge (a
  // seam) without moving into the line is in that case too. The instance is lifted off the line by
  // one to three units, if that frees it (a copy alone; the anchor, with the whole entity), and the
  // sub-move is redone. A wall the body moves into still holds.
  bool liftAtSeam() {
    if (hit_.kind != HitKind::Solid || isPlatformLine(hit_.line)) return false;
    const size_t i = hit_.instance;
    // The last lift left this instance meeting this line no later: lifting again would only repeat
    // it (one unit a sub-move until the frame's sub-moves run out, the body stalled with no
    // contact), so the line is met as a line.
    if (move_.lastLift.instance == i) return false;
    Instance& inst = e_.instances[i];
    Vec2w liftAlong;  // the instance's frame
    if (i > 0 && hit_.t == Fraction::zero() && !move_.normals.empty()) {
      // Off the line along the frame's last contact normal, up to kCopyLift units off its exact
      // place: one already that far off meets the line as a line. (Lifted again frame after frame
      // off a wall it was pushed into, a copy slid along the wall while its exact place went into
      // it, tens of units off, and the body's pieces on the two faces no longer met.)
      if (offIdeal(inst) >= kCopyLift) return false;
      liftAlong = rotateWide(inst.rotation, move_.normals.back());
    } else {
      const Segment seg = w_.part(inst.part).segments()[hit_.line];
      const bool edgeOn = hit_.sweep.axis < static_cast<int>(verts_[i].size());  // a polygon edge met the end
      if (i == 0 && !(edgeOn && endNearWarpLine(w_, inst, seg))) return false;
      liftAlong = normalTowards(verts_[i], seg);  // off the line, on the instance's side
      // Not into the line by more than about a degree (the turn between two faces comes from their
      // rounded edges, so a floor continued across them is off by a fraction of one): -dot / |a||b|
      // <= 1/64, compared squared on directions shortened to 20 bits.
      const Vec2w a = shortTo20(i == 0 ? move_.motion : rotateQ30(inst.rotation, move_.motion)),
                  b = shortTo20(liftAlong);
      const i128 along = dot128(a, b);
      if (along < 0 && along * along * 4096 > dot128(a, a) * dot128(b, b)) return false;
    }
    const bool lifted = i > 0 ? w_.liftCopy(e_, inst, liftAlong, moves_[i]) : liftEntity(liftAlong);
    if (lifted) move_.lastLift = {i, hit_.line, hit_.t};
    if (lifted) ++w_.report.copiesReplaced;
    if (!lifted && i == 0) replan();
    return lifted;
  }

  // The lifts tried are sub-moves of their own in the same scratch buffers: when none was free,
  // this sub-move's motions, vertices and regions are planned again (its hit stays). Going on with
  // theirs, a copy took the last lift's motion as its own, unchecked, into a wall.
  void replan() {
    const Hit kept = hit_;
    hit_ = Hit{};
    planMotions();
    findFirstEvent();
    hit_ = kept;
  }

  // 3. Every instance's step to the event's time, rounded to the safe side. A step that is exactly on
  //    the swept path is free by the search above; a rounded one is proved free by an exact sweep of
  //    its own, and if rounding left the safe path, t is pulled back and retried. The last resort,
  //    t = 0, always succeeds.
  void roundSteps() {
    t_ = hit_.t;
    for (int attempt = 0;; ++attempt) {
      if (attempt == 3) t_ = Fraction::zero();
      if (tryStepsAt(attempt)) break;
    }
    // The anchor's step is the frame's progress (the motion left is the anchor's): a copy that
    // still moves a unit, closing on its ideal place, makes none, and going again from there
    // meets the same hit in the same place.
    const bool anchorStill = steps_[0] == Vec2w{};
    if (pulledBack() && anchorStill && (hit_.kind == HitKind::None || hit_.kind == HitKind::Warp)) {
      const Fraction pulled = t_;
      t_ = hit_.t;
      if (tryOtherRoundings()) return;
      t_ = pulled;
      steps_.assign(n_, Vec2w{});
      // A warp no whole-unit step can reach (a wall within a unit of where the path meets it): it
      // holds like a wall for the rest of the frame, so the next sub-move meets it as one (a
      // contact where the body stands, then the slide along it) instead of going again from the
      // same place with the same result until the frame's sub-moves run out, frame after frame.
      if (hit_.kind == HitKind::Warp) {
        e_.instances[hit_.instance].blockedWarps.push_back(hit_.line);
        ++w_.report.warpsHeld;
      }
    }
  }

  // The steps rounded toward zero kept meeting a line the exact path clears by less than a unit
  // (the end of a wall it passes, a wall just beside a warp edge), and were pulled back until
  // nothing moved. With no contact to answer, the same sub-move would come again, and the frame
  // would end with the body where it was and its velocity growing: frozen. So each instance takes,
  // nearest first, the other whole-unit steps around its exact one that are free.
  bool tryOtherRoundings() {
    bool moved = false;
    for (size_t i = 0; i < n_; ++i) {
      const Vec2w m = moves_[i];
      const i128 qx = i128{t_.num} * m.x, qy = i128{t_.num} * m.y;
      const int64_t x0 = static_cast<int64_t>(floorDiv(qx, t_.den)), y0 = static_cast<int64_t>(floorDiv(qy, t_.den));
      // Fractions of a unit past the floor, to order the four candidates by distance.
      const i128 fx = qx - i128{x0} * t_.den, fy = qy - i128{y0} * t_.den;
      std::array<Vec2w, 4> candidates{Vec2w{x0, y0}, Vec2w{x0 + 1, y0}, Vec2w{x0, y0 + 1}, Vec2w{x0 + 1, y0 + 1}};
      auto distance = [&](Vec2w c) {
        const i128 dx = (c.x - x0) * i128{t_.den} - fx, dy = (c.y - y0) * i128{t_.den} - fy;
        return dx * dx + dy * dy;
      };
      std::sort(candidates.begin(), candidates.end(), [&](Vec2w a, Vec2w b) {
        const i128 da = distance(a), db = distance(b);
        return da != db ? da < db : (a.x != b.x ? a.x < b.x : a.y < b.y);
      });
      // Standing still is the last resort, and only for a copy: the instance that met the hit
      // must move.
      steps_[i] = Vec2w{};
      for (const Vec2w c : candidates) {
        if (c == Vec2w{} || w_.firstBlock(e_, e_.instances[i], verts_[i], c) < Fraction::one()) continue;
        steps_[i] = c;
        break;
      }
      if (steps_[i] == Vec2w{} && i == hit_.instance) return false;
      moved = moved || steps_[i] != Vec2w{};
    }
    return moved;
  }

  // 4. Commit; then each copy closes its gap to its ideal position where that path is free.
  void commit() {
    for (size_t i = 0; i < n_; ++i) {
      Instance& inst = e_.instances[i];
      inst.position.x += static_cast<int32_t>(steps_[i].x);
      inst.position.y += static_cast<int32_t>(steps_[i].y);
      if (i > 0) closeGap(i);
    }
    move_.motion = move_.motion - steps_[0];
    if (t_.num == t_.den)  // the whole rest of the frame (as the division below, without it)
      move_.timeLeftQ30 = 0;
    else if (t_.num != 0)
      move_.timeLeftQ30 -= static_cast<int64_t>(floorDiv(i128{move_.timeLeftQ30} * t_.num, t_.den));
  }

  // 5. Pierce events along the way; a warp reached creates the instance on the other side; the warp
  //    links then erase instances the entity has left (which may change the anchor).
  void afterMove() {
    w_.updatePierceState(e_, {verts_, steps_, pierceNear_});
    hitPart_ = e_.instances[hit_.instance].part;
    hitRotation_ = e_.instances[hit_.instance].rotation;
    anchorPart_ = e_.instances.front().part;
    hitMove_ = moves_[hit_.instance];
    if (hit_.kind == HitKind::Warp && !pulledBack()) crossWarp();
    if (!e_.links.empty()) w_.updateLinks(move_);
  }

  // The lowest slot of the entities this sub-move meets within its motion that have not stepped
  // this frame (UINT32_MAX: none).
  uint32_t unsteppedMet() const { return unsteppedMet_; }

  // What the slide does next, once the instances have moved.
  enum class Next { Stop, Again, Respond };
  Next next() const {
    // Pulled back, the next sub-move goes on from where the steps got to. If no instance moved (a
    // crease whose sides are both within a unit: every rounded step toward the hit meets the other
    // side), going again would find the same hit forever and the frame would end with nothing
    // moved and no contact: the hit is met where the body stands, and the slide along it moves on.
    if (pulledBack() && std::any_of(steps_.begin(), steps_.end(), [](Vec2w s) { return s != Vec2w{}; }))
      return Next::Again;
    if (hit_.kind == HitKind::None) return Next::Stop;
    if (hit_.kind == HitKind::Warp) return Next::Again;
    return Next::Respond;
  }

  // 6. A solid contact: tell the rules, then slide along the line. Returns whether to go on.
  // What follows a solid contact.
  enum class After { Stop, Slide, Again };

  // 6. A solid contact: tell the rules; push the entity met if it can be pushed (then the sub-move
  //    goes again, into the room it made); else slide along the line or the entity.
  After respondToContact(int& pushes) {
    ++w_.report.hits;
    // The copy that met the line can be gone already: a copy that only touches its warp edge, while
    // the anchor only touches it too, is erased by the links. The line still holds the body (a
    // wall just over an edge): it is met all the same, through the copy's frame as it was. (Ending
    // the slide there left the velocity driving the body into that wall frame after frame, and
    // nothing moved: frozen.) Only an anchor changed meanwhile leaves no frame to answer in.
    const Instance* inst = e_.instanceIn(hitPart_);
    if (!inst && e_.instances.front().part != anchorPart_) return After::Stop;
    const Rotation rotation = inst ? inst->rotation : hitRotation_;
    const Vec2w partNormal = -hit_.axis.c;
    ContactPoints points;
    if (hit_.kind == HitKind::Solid)
      points = contactPoints(verts_[hit_.instance], hitMove_, w_.segmentOf(w_.part(hitPart_), hit_.line), hit_.sweep);
    const bool withEntity = hit_.kind == HitKind::Entity;
    Contact contact = w_.makeContact(e_, hitPart_, withEntity ? kNoLine : hit_.line, hit_.t, partNormal, points);
    if (withEntity) contact.other = w_.slots[hit_.otherSlot].entity->id;
    if (e_.contactsAreRest) e_.contacts = e_.restContacts, e_.contactsAreRest = false;  // kept, then pushed
    e_.contacts.push_back(contact);
    ContactResponse response;
    w_.callRules([&](Rules& r) { r.contact(contact, response); });
    const Vec2w normal = shortDirection(rotateWideInverse(rotation, shortDirection(partNormal)));
    // A push goes along the contact's own normal (the sweep's), not the slide's: that can be a line
    // the body touches too, the floor it jumps off (a crate on its head, the jump sideways). Pushed
    // along the floor's normal the crate was not pushed at all, and sliding along the floor, the
    // body went nowhere, frame after frame.
    const Vec2w pushNormal = shortDirection(rotateWideInverse(rotation, shortDirection(hit_.sweep.normal())));
    if (withEntity && inst && pushes < 4 && tryPush(*inst, pushNormal)) {
      ++pushes;
      return After::Again;
    }
    if (bounce(normal, w_.checkedRestitution(response.restitution))) return After::Slide;
    if (response.removeNormalVelocity) {
      // The velocity it meets the line with turns along it; the gravity of the rest of the frame
      // then acts as the line lets it (a body that slides off a floor onto a rise slows on the rise
      // for the part of the frame it spends there, not for the whole frame nor not at all).
      auto forTimeLeft = [&](Vec2w g) {
        return Vec2w{static_cast<int64_t>((i128{g.x} * move_.timeLeftQ30) >> kQ30Bits),  // floor division
                     static_cast<int64_t>((i128{g.y} * move_.timeLeftQ30) >> kQ30Bits)};
      };
      const Vec2w atContact = e_.velocityQ16 - forTimeLeft(move_.actingGravityQ16);
      move_.actingGravityQ16 = removeInto(move_.gravityQ16, normal);
      e_.velocityQ16 = clampVelocityQ16(removeInto(atContact, normal) + forTimeLeft(move_.actingGravityQ16));
      // In a crease, or turned against the frame's own velocity by its contacts (one after another:
      // one line alone turns it only along, or back by the gravity after the contact): it is held.
      if (hit_.crease || (!move_.normals.empty() && dot128(e_.velocityQ16, move_.primalVelocity) < 0))
        e_.velocityQ16 = {};
    }
    move_.exactQ17 = {};  // from here on, the remaining motion is the slide's
    if (!response.slide) return After::Stop;
    slideAlong(normal, response.removeNormalVelocity);
    return After::Slide;
  }

 private:
  bool pulledBack() const { return t_ < hit_.t; }

  // Pushes the entity met, if it can be pushed, by the part of the remaining motion that goes
  // into it (rounded away from zero, so it clears the way), as a slide of its own. Returns whether
  // it moved. `normal` is the contact's, in this entity's frame.
  bool tryPush(const Instance& inst, Vec2w normal) {
    Entity& other = *w_.slots[hit_.otherSlot].entity;
    if (!other.filter.pushable || other.instances.empty()) return false;
    const i128 into = dot128(move_.motion, normal);
    if (into >= 0) return false;
    const i128 nn = dot128(normal, normal);
    // -(m.n / n.n) n, each component rounded away from zero: at least as far as the motion goes in.
    auto away = [&](int64_t nk) {
      const i128 q = -into * nk;
      return static_cast<int64_t>(q >= 0 ? ceilDiv(q, nn) : floorDiv(q, nn));
    };
    const Vec2w pushHere{away(-normal.x), away(-normal.y)};  // this entity's frame
    // Into the other's frame: through the part both instances are in.
    const Instance* theirs = other.instanceIn(inst.part);
    if (!theirs) return false;
    const Vec2w inPart = rotateWide(inst.rotation, pushHere);
    const Vec2w inTheirs = theirs->frame == 0 ? inPart : rotateWideInverse(theirs->rotation, inPart);
    w_.reindex(e_);  // where this one is now, for the other's slide to see
    return w_.push(other, clampMove(inTheirs));
  }
  static Vec2w clampMove(Vec2w v) {
    return {std::clamp<int64_t>(v.x, -kMaxMove, kMaxMove), std::clamp<int64_t>(v.y, -kMaxMove, kMaxMove)};
  }

  // Bounces off the line (bounce.h): the velocity and the rest of the frame's motion (its whole
  // units and the remainder below one) turn as the exact motion would. Whatever of the bounced
  // motion still goes into the line (a bounce too slow to clear it this frame) slides. Not reached
  // yet (rounding left it touching): it slides and keeps its velocity, to bounce next frame.
  // False when it lands: the usual response follows.
  bool bounce(Vec2w normal, Fraction restitution) {
    if (restitution <= Fraction::zero()) return false;
    const Vec2w gravity = move_.actingGravityQ16;
    const Vec2w remainingQ17{move_.motion.x * kQ17 + e_.subunitQ17.x, move_.motion.y * kQ17 + e_.subunitQ17.y};
    const Bounce b = bounceOff(e_.velocityQ16, gravity, remainingQ17, normal, restitution);
    if (b.outcome == BounceOutcome::Lands) return false;
    if (b.outcome == BounceOutcome::Bounces) {
      e_.velocityQ16 = b.velocityQ16;
      move_.motion = {static_cast<int64_t>(floorDiv(b.remainingQ17.x, kQ17)),
                      static_cast<int64_t>(floorDiv(b.remainingQ17.y, kQ17))};
      e_.subunitQ17 = {b.remainingQ17.x - move_.motion.x * kQ17, b.remainingQ17.y - move_.motion.y * kQ17};
    }
    if (dot128(move_.motion, normal) < 0) {
      Vec2w carryQ17;
      move_.motion = removeIntoCarrying(move_.motion, normal, carryQ17);
      e_.subunitQ17 = withoutComponent(e_.subunitQ17 + carryQ17, normal);
    }
    return true;
  }

  // Moves the whole entity one to three units along `direction` (entity frame) where that move is
  // free of every line for every instance: a sub-move of its own, with its pierce events.
  bool liftEntity(Vec2w direction) {
    for (int64_t units = 1; units <= 3; ++units) {
      const Vec2w step = stepAlong(direction, units);
      if (step == Vec2w{}) continue;
      std::vector<Vec2w> none;
      Move lift{e_, step, none, step, e_.velocityQ16};
      SubMove sub(w_, lift);  // reuses the scratch buffers: this sub-move is abandoned afterwards
      sub.planMotions();
      sub.findFirstEvent();
      if (!sub.free()) continue;
      const Angle frameBefore = e_.angle;
      sub.roundSteps();
      sub.commit();
      sub.afterMove();
      // The lift can take the anchor off its part (the link to the copy ends it): the rest of the
      // frame's move turns into the new anchor's frame, as rebase turned the lift's.
      if (e_.angle != frameBefore) w_.turnMove(move_, static_cast<Angle>(e_.angle - frameBefore));
      return true;
    }
    return false;
  }
  bool free() const { return hit_.kind == HitKind::None; }

  static Vec2w shortTo20(Vec2w v) {
    while (std::max(std::abs(v.x), std::abs(v.y)) > (int64_t{1} << 20)) v = {v.x / 2, v.y / 2};
    return v;
  }

  bool tryStepsAt(int attempt) {
    steps_.assign(n_, Vec2w{});
    for (size_t i = 0; i < n_; ++i) {
      const bool keepAxis = attempt == 0 && hit_.kind != HitKind::None && i == hit_.instance;
      steps_[i] = roundedStep(moves_[i], t_, keepAxis ? &hit_.axis : nullptr);
      if (steps_[i] == Vec2w{} || (attempt == 0 && exactMove(moves_[i], t_))) continue;
      const Fraction first = w_.firstBlock(e_, e_.instances[i], verts_[i], steps_[i]);
      if (first < Fraction::one()) {
        ++w_.report.roundingRetries;
        // Scale t by the free fraction, kept in 24 fractional bits (rounded down).
        const i128 tq = floorDiv(i128{t_.num} << 24, t_.den);
        t_ = {static_cast<int64_t>(floorDiv(tq * first.num, first.den)), int64_t{1} << 24};
        return false;
      }
    }
    return true;
  }

  // A copy follows the anchor's step exactly in Q30; its whole-unit position may lag. It keeps a
  // lift of up to three units (see liftAtSeam); a larger gap, left by a blocked step, is closed
  // where the way is free.
  void closeGap(size_t i) {
    Instance& inst = e_.instances[i];
    inst.idealQ30 = inst.idealQ30 + rotateQ30(inst.rotation, steps_[0]);
    const Vec2 ideal = pointFromQ30(inst.idealQ30);
    const Vec2w gap{int64_t{ideal.x} - inst.position.x, int64_t{ideal.y} - inst.position.y};
    if (std::max(std::abs(gap.x), std::abs(gap.y)) <= kCopyLift) return;
    std::vector<Vec2>& at = w_.scratch.probe;
    worldVertices(inst, at);
    w_.coverMotion(inst, gap);
    Vec2w close = gap;
    if (const Fraction free = w_.firstBlock(e_, inst, at, gap); free < Fraction::one()) {
      // As far as the way is free, in whole units (rounded toward the copy): a copy that keeps
      // meeting a wall is rounded off it a unit a sub-move, and closing nothing unless the whole
      // gap was free, it drifted tens of units off its place while the body slid along.
      close = roundedStep(gap, free, nullptr);
      if (close == Vec2w{} || w_.firstBlock(e_, inst, at, close) < Fraction::one()) return;
    }
    inst.position.x += static_cast<int32_t>(close.x);
    inst.position.y += static_cast<int32_t>(close.y);
    steps_[i] = steps_[i] + close;  // pierce events see the whole way it went
  }

  // The warp the sub-move stopped at: the exact touching position, in Q30, maps to where the new
  // instance starts. If the far side has no room, the warp holds like a wall this frame.
  void crossWarp() {
    const Vec2 start = e_.instances[hit_.instance].position;
    const Vec2w before{start.x - steps_[hit_.instance].x, start.y - steps_[hit_.instance].y};
    const Vec2w exact{(before.x << kQ30Bits) +
                          static_cast<int64_t>(floorDiv((i128{hit_.t.num} * hitMove_.x) << kQ30Bits, hit_.t.den)),
                      (before.y << kQ30Bits) +
                          static_cast<int64_t>(floorDiv((i128{hit_.t.num} * hitMove_.y) << kQ30Bits, hit_.t.den))};
    if (!w_.createWarpInstance(e_, hit_.instance, hit_.line, exact, move_.motion))
      e_.instances[hit_.instance].blockedWarps.push_back(hit_.line);
  }

  // The rest of the motion goes along the line. The entity is in a crease (a wedge, a corner, a
  // valley), and stops for this frame, when the slide would run into a line met earlier in the
  // frame, or when the contacts have turned the motion against the frame's own: in exact terms its
  // projection along the line points back (dot < 0 with the frame's first motion). Sliding on,
  // it would only bounce between the lines by the rounding of a unit.
  void slideAlong(Vec2w normal, bool stopVelocityInCrease) {
    Vec2w carryQ17;
    move_.motion = removeIntoCarrying(move_.motion, normal, carryQ17);
    bool crease = hit_.crease || turnsBack(subMotion_, normal);
    for (const Vec2w& previous : move_.normals) crease = crease || dot128(move_.motion, previous) < 0;
    if (crease) {
      move_.motion = {};  // the lines hold it in place
      e_.subunitQ17 = {};
      if (stopVelocityInCrease) e_.velocityQ16 = {};
    } else {
      // Touching the line, the entity has no fraction of a unit left to move across it, nor away
      // from it; along it, it keeps what rounding left out.
      e_.subunitQ17 = withoutComponent(e_.subunitQ17 + carryQ17, normal);
    }
    move_.normals.push_back(normal);
  }

  // Whether m, this sub-move's motion, with its component into n removed (exactly: the rounding
  // of the step to the contact must not count) points against the frame's first motion: sign of
  // dot(m, p) |n|^2 - dot(m, n) dot(n, p), all terms below 2^125.
  bool turnsBack(Vec2w m, Vec2w n) const {
    const Vec2w p = move_.primalMotion;
    const i128 mn = dot128(m, n);
    if (mn >= 0) return false;  // not into the line: nothing is removed
    return dot128(m, p) * dot128(n, n) - mn * dot128(n, p) < 0;
  }

  WorldImpl& w_;
  Move& move_;
  Entity& e_;
  const size_t n_;
  std::vector<std::vector<Vec2>>& verts_;
  std::vector<Vec2w>& moves_;
  std::vector<Vec2w>& steps_;
  std::vector<uint8_t>& pierceNear_;
  Hit hit_;
  uint32_t unsteppedMet_ = UINT32_MAX;
  Vec2w subMotion_;  // the anchor's motion at the start of this sub-move, entity frame
  Fraction t_;
  MapPartId hitPart_ = 0;
  Rotation hitRotation_;      // the hit instance's frame, kept in case the links erase it
  MapPartId anchorPart_ = 0;  // the anchor's part when the hit was met
  Vec2w hitMove_;
};

}  // namespace

namespace {

// The directions a contact's normals close to the entity (in its own frame), as one line's.
// Whether one of them is against `w` (any, for no w): a line the body is pressed onto, not one it
// only touches (a crate on its head does not hold it up).
bool closeDirections(OpenDirections& open, const Instance& inst, const std::vector<Vec2w>& normals, Vec2w w) {
  open.beginLine();
  bool against = w == Vec2w{};
  for (const Vec2w n : normals) {
    const Vec2w inFrame = inst.frame == 0 ? n : shortDirection(rotateWideInverse(inst.rotation, shortDirection(n)));
    open.addNormal(inFrame);
    against = against || dot128(inFrame, w) < 0;
  }
  return against;
}

// The normal a contact with `seg` reports: the line's own when it is one of them (a body on a
// floor, not the edge of its own shape at the floor's end).
Vec2w reportedNormal(const std::vector<Vec2w>& normals, const Segment& seg) {
  Vec2w reported = normals[0];
  for (const Vec2w n : normals)
    if (dot128(n, seg.b - seg.a) == 0) reported = n;
  return reported;
}

}  // namespace

// The instance's part's own lines it rests against: their normals close directions in `open`,
// each is a contact. Whether one of them touches it.
bool WorldImpl::restOnPartLines(Entity& e, Instance& inst, const std::vector<Vec2>& verts, const Box& box, Vec2w w) {
  std::vector<Vec2w>& normals = scratch.lineNormals;
  const MapPart& p = part(inst.part);
  bool touching = false;
  const auto lines = inst.region.lines();
  for (size_t k = 0; k < lines.size(); ++k) {
    const Segment& seg = p.segments()[lines[k]];
    normals.clear();
    if (outside(seg, box) || !blocks(e, inst, k, verts)) continue;
    const Nearness nearness = nearNormals(verts, seg, normals);
    if (nearness == Nearness::Apart) continue;
    if (nearness == Nearness::Touching && &inst == &e.instances[0]) {  // for the slide (TouchMemo)
      Scratch::TouchMemo& memo = scratch.touchMemo;
      const uint32_t begin = static_cast<uint32_t>(memo.normals.size());
      memo.normals.insert(memo.normals.end(), normals.begin(), normals.end());
      memo.lines.push_back({lines[k], begin, static_cast<uint32_t>(memo.normals.size())});
    }
    // A copy sits where rounding put it, and may meet a line's end edge-on where the original
    // glides along it; so may any instance at a seam, the end of a line cut by a face edge. The
    // slide lifts them off (liftAtSeam); for rest, such a line counts by its own side only.
    const bool ownSide =
        std::any_of(normals.begin(), normals.end(), [&](Vec2w n) { return dot128(n, seg.b - seg.a) == 0; });
    if (&inst != &e.instances[0] || (!ownSide && endNearWarpLine(*this, inst, seg))) {
      normals.assign(1, normalTowards(verts, seg));
    }
    const bool against = closeDirections(scratch.open, inst, normals, w);
    touching = touching || (nearness == Nearness::Touching && against);
    scratch.restContacts.push_back({inst.part, lines[k], reportedNormal(normals, seg), {}});
  }
  return touching;
}

// The same for the moving platforms' lines near it: they count as the part's own do.
bool WorldImpl::restOnPlatformLines(Instance& inst, const std::vector<Vec2>& verts, const Box& box, Vec2w w) {
  std::vector<Vec2w>& normals = scratch.lineNormals;
  bool touching = false;
  forEachPlatformLine(inst.part, box, [&](const PlatformLine& l, LineIndex key) {
    if (l.kind == LineKind::OneWay && !wholyInFront(verts, l.segment)) return;
    normals.clear();
    const Nearness nearness = nearNormals(verts, l.segment, normals);
    if (nearness == Nearness::Apart) return;
    const bool against = closeDirections(scratch.open, inst, normals, w);
    touching = touching || (nearness == Nearness::Touching && against);
    scratch.restContacts.push_back({inst.part, key, reportedNormal(normals, l.segment), {}});
  });
  return touching;
}

// The same for the entities solid to it that it is against: the other polygon's sides count as
// lines do. One that can be pushed holds it only as a support (a contact against gravity, as in a
// stack): from the side, walking into it pushes it.
bool WorldImpl::restOnEntities(Entity& e, Instance& inst, const std::vector<Vec2>& verts, const Box& box, Vec2w w) {
  std::vector<Vec2w>& normals = scratch.lineNormals;
  std::vector<Vec2>& other = scratch.probe;
  const Vec2w down = part(inst.part).gravity();
  bool touching = false;
  forEachSolidNear(e, inst.part, box, [&](const Entity& o, const Instance& oi) {
    worldVertices(oi, other);
    normals.clear();
    const Nearness nearness = nearNormals(verts, other, normals);
    if (nearness == Nearness::Apart) return;
    if (o.filter.pushable) std::erase_if(normals, [&](Vec2w n) { return dot128(n, down) >= 0; });
    if (normals.empty()) return;
    const bool against = closeDirections(scratch.open, inst, normals, w);
    touching = touching || (nearness == Nearness::Touching && against);
    scratch.restContacts.push_back({inst.part, kNoLine, normals[0], o.id});
  });
  return touching;
}

// Whether `e` moving by `w` (its frame) is held where it is by what it is against: every instance's
// lines, platforms and solid entities. Leaves the contacts that hold it in e.contacts (none when it
// is not held).
bool WorldImpl::restsAgainstLines(Entity& e, Vec2w w) {
  OpenDirections& open = scratch.open;
  open.clear();
  e.contacts.clear();
  scratch.restContacts.clear();
  bool touching = false;
  for (Instance& inst : e.instances) {
    coverMotion(inst, {}, 2);
    std::vector<Vec2>& verts = scratch.now;
    worldVertices(inst, verts);
    if (&inst == &e.instances[0]) {  // restOnPartLines notes what touches these vertices
      scratch.touchMemo.part = inst.part;
      scratch.touchMemo.verts = verts;
      scratch.touchMemo.lines.clear();
      scratch.touchMemo.normals.clear();
    }
    Box box = sweptBox(inst, {});
    box.x0 -= 2, box.y0 -= 2, box.x1 += 2, box.y1 += 2;
    touching = restOnPartLines(e, inst, verts, box, w) || touching;
    touching = restOnPlatformLines(inst, verts, box, w) || touching;
    touching = restOnEntities(e, inst, verts, box, w) || touching;
  }
  // Resting on a line, it touches it; wedged into a corner, it may be kept up to 1.5 units from
  // the lines by the whole-unit grid, and lines near it count only if they form a corner.
  if (!open.empty() && open.cannotMove(w) && (touching || open.wedges(w))) {
    for (const auto& r : scratch.restContacts) {
      e.contacts.push_back(makeContact(e, r.part, r.line, Fraction::zero(), r.normal, {}));
      e.contacts.back().other = r.other;
    }
    // Contacts in line order, then entities by slot: neither the region's nor the index's order is
    // part of the result.
    std::sort(e.contacts.begin(), e.contacts.end(), [](const Contact& a, const Contact& b) {
      if (a.part != b.part) return a.part < b.part;
      if (a.line.index != b.line.index) return a.line.index < b.line.index;
      return a.other.index < b.other.index;
    });
    return true;
  }
  e.contacts.clear();
  return false;
}

namespace {

bool sameContacts(const std::vector<Contact>& a, const std::vector<Contact>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Contact& p, const Contact& q) {
    return p.entity == q.entity && p.part == q.part && p.line.part == q.line.part && p.line.index == q.line.index &&
           p.line.tag == q.line.tag && p.line.kind == q.line.kind && p.line.platform == q.line.platform &&
           p.other == q.other && p.normal == q.normal;
  });
}

}  // namespace

// Whether a resting entity's kept answer still stands: nothing that the calls and moves around it
// cannot report has changed (its part's gravity, its parts' platforms).
bool WorldImpl::keepsRest(const Entity& e) const {
  return e.resting && e.angularVelocity == 0 && e.velocityQ16 == Vec2w{} && e.subunitQ17 == Vec2w{} &&
         e.instances.size() == 1 && part(e.instances[0].part).gravity() == e.restGravityQ16 &&
         platformEpochOf(e) == e.restPlatformEpoch;
}

void WorldImpl::stepEntity(Entity& e) {
  for (Instance& inst : e.instances) inst.blockedWarps.clear();
  bool kept = keepsRest(e);
  // Held by an entity that has not stepped this frame: that one steps first, as it does for the
  // rest test below (moving, it wakes this one, which is then tested where it is now).
  auto holderWaits = [&] {
    return std::any_of(e.restHolders.begin(), e.restHolders.end(), [&](uint32_t s) {
      const Entity* o = slots[s].entity.get();
      return o && !steppedThisFrame(*o);
    });
  };
  if (kept && holderWaits() && stepHoldersFirst(e, e.restContacts, e.velocityQ16, true)) {
    if (e.awaiting.takenOver) return;
    kept = keepsRest(e);
  }
  if (e.resting && !kept) wake(e);
  if (kept && !restCheck) {  // the rest test's answer, as it would give it again
    e.velocityQ16 = {};
    e.contactsAreRest = true;  // read through contactsOf: a crowd at rest copies no contacts
    ++report.restsKept;
    return;
  }
  stepEntityTested(e);
  if (kept) {  // RestMode::Checked: the test's answer against the kept one
    ++report.restsKept;
    if (e.velocityQ16 != Vec2w{} || e.subunitQ17 != Vec2w{} || !sameContacts(e.contacts, e.restContacts))
      ++report.restMismatches;
  }
}

void WorldImpl::stepEntityTested(Entity& e) {
  std::vector<Vec2w> nestedNormals;  // a neighbour's step inside another's leaves the outer one's alone
  std::vector<Vec2w>& normals = neighbourDepth == 0 ? scratch.normals : nestedNormals;
  if (e.angularVelocity != 0) rotateBy(e, e.angularVelocity);
  if (e.instances.empty()) return;
  const Vec2w before = e.velocityQ16;
  if (e.gravity) e.velocityQ16 = clampVelocityQ16(e.velocityQ16 + part(e.instances[0].part).gravity());
  // The frame moves by the average of the velocities at its start and end: for constant gravity
  // that is the exact parabola at every frame, not the first-order step most engines take. The
  // sum of the two Q16 velocities is the average in Q17; whole units move now, the remainder
  // below one unit waits for the next frame.
  Vec2w frameQ17 = e.subunitQ17 + before + e.velocityQ16;
  // At rest: pressed into the lines it is against, it cannot move. It stays exactly where it is,
  // with no velocity and no fraction of a unit left over, so it stays at rest.
  bool rests = e.angularVelocity == 0 && restsAgainstLines(e, e.velocityQ16);
  // Held by an entity that has not stepped this frame (a guard it walks behind, a crate it stands
  // on that slides away): that one steps first, as a sweep meeting it would have it, and the test
  // is asked again. So whether it is still held never depends on the handles' order.
  if (rests && stepHoldersFirst(e, e.contacts, before, false)) {
    if (e.awaiting.takenOver) return;
    rests = restsAgainstLines(e, e.velocityQ16);
  }
  if (rests) {
    // It was moving and stops here: a landing (a rounded step can end touching a line that the
    // exact motion reaches just after the frame) is a contact, whichever path finds it.
    const Arrival arrival = before != Vec2w{} ? reportArrival(e, frameQ17) : Arrival::Rests;
    if (arrival == Arrival::Stays) e.subunitQ17 = {};
    if (arrival == Arrival::Rests) {
      e.velocityQ16 = {};
      e.subunitQ17 = {};
      if (!copiesSettled(e)) {  // a copy lagging more than a lift closes its gap where it is free
        normals.clear();
        Move still{e, {}, normals, {}, {}};
        slide(still);
        reindex(e);
      } else if (before == Vec2w{} && restCache && e.instances.size() == 1) {
        // At rest from the frame's start to its end, no callback asked: the answer holds until
        // something near it changes (keepsRest).
        if (!e.resting) ++restingCount;
        e.resting = true;
        e.restGravityQ16 = part(e.instances[0].part).gravity();
        e.restPlatformEpoch = platformEpochOf(e);
        e.restContacts = e.contacts;
        e.restHolders.clear();  // what it is pressed onto: gravity its only push
        for (const Contact& c : e.contacts)
          if (c.other.isSet() && dot128(c.normal, e.gravity ? e.restGravityQ16 : Vec2w{}) < 0)
            e.restHolders.push_back(c.other.index);
      }
    }
    if (arrival != Arrival::Bounces) return;
  }
  const Vec2w whole{frameQ17.x >> 17, frameQ17.y >> 17};
  e.subunitQ17 = {frameQ17.x - whole.x * kQ17, frameQ17.y - whole.y * kQ17};
  normals.clear();
  Move move{e, whole, normals, whole, e.velocityQ16};
  move.exactQ17 = frameQ17;
  if (e.gravity) move.gravityQ16 = move.actingGravityQ16 = part(e.instances[0].part).gravity();
  slide(move);
  reindex(e);
}

WorldImpl::Arrival WorldImpl::reportArrival(Entity& e, Vec2w& frameQ17) {
  bool keepVelocity = false, bounced = false, notYet = false;
  std::vector<Contact>& arrived = scratch.arrived;
  arrived = e.contacts;  // the callbacks may read the entity's contacts
  const Vec2w gravity = e.gravity ? part(e.instances[0].part).gravity() : Vec2w{};
  for (const Contact& c : arrived) {
    ContactResponse response;
    callRules([&](Rules& r) { r.contact(c, response); });
    keepVelocity = keepVelocity || !response.removeNormalVelocity;
    const Fraction restitution = checkedRestitution(response.restitution);
    const Instance* inst = e.instanceIn(c.part);
    if (!inst || restitution <= Fraction::zero()) continue;
    // Met at the frame's start: the whole frame's motion is what is left after the contact.
    const Vec2w normal = inst->frame == 0 ? c.normal : rotateWideInverse(inst->rotation, shortDirection(c.normal));
    const Bounce b = bounceOff(e.velocityQ16, gravity, frameQ17, normal, restitution);
    if (b.outcome == BounceOutcome::Bounces) {
      e.velocityQ16 = b.velocityQ16;
      frameQ17 = b.remainingQ17;
      bounced = true;
    }
    notYet = notYet || b.outcome == BounceOutcome::NotYet;
  }
  if (bounced) return Arrival::Bounces;
  if (notYet) return Arrival::Stays;
  return keepVelocity && !restsAgainstLines(e, e.velocityQ16) ? Arrival::Stays : Arrival::Rests;
}

// Handle order decides who steps first, but not where a move meets another entity: one it meets
// that has not stepped this frame steps first (seeing the mover where it is now: the index is told
// first), and the mover's sub-move is planned again. So a move, and a chain it pushes (each link a
// slide of its own), meets every entity where it is this frame. Nested steps are bounded; beyond
// that, an entity is met where it is.
bool WorldImpl::steppedThisFrame(const Entity& e) const { return e.steppedFrame == frame && !e.awaiting.now; }

bool WorldImpl::stepMetEntityFirst(Entity& mover, uint32_t slot, bool moverMoved) {
  Entity* o = slots[slot].entity.get();
  if (!steppingEntities || !o || steppedThisFrame(*o) || neighbourDepth >= kMaxNeighbourDepth) return false;
  if (moverMoved) reindex(mover);
  if (o->awaiting.now) {  // its step starts again here, from where it began, and is over when this returns
    o->awaiting.now = false;
    o->awaiting.takenOver = true;
    o->velocityQ16 = o->awaiting.velocityQ16;
    o->subunitQ17 = o->awaiting.subunitQ17;
  }
  const int pushesBefore = pushDepth;
  pushDepth = 0;  // its own step pushes as far as any step may
  ++neighbourDepth;
  stepInFrame(*o);
  --neighbourDepth;
  pushDepth = pushesBefore;
  return true;
}

// The holders step while this entity waits (once a frame: two bodies that hold each other do not
// take turns). `velocityBefore` is its velocity when its step began.
bool WorldImpl::stepHoldersFirst(Entity& e, const std::vector<Contact>& contacts, Vec2w velocityBefore, bool kept) {
  if (e.awaiting.frame == frame || !steppingEntities) return false;
  auto unstepped = [&](const Contact& c) {
    const Entity* o = c.other.isSet() ? slots[c.other.index].entity.get() : nullptr;
    return o && !steppedThisFrame(*o);
  };
  // The usual case (on lines, or on what has stepped already) costs a look at its contacts.
  if (std::none_of(contacts.begin(), contacts.end(), unstepped)) return false;
  // Kept at rest, its velocity is none and its rest test would ask with its gravity.
  const Vec2w pressed = !kept ? e.velocityQ16 : e.gravity ? part(e.instances[0].part).gravity() : Vec2w{};
  // A holder is what it is pressed into (by its velocity, gravity in it): a crate on its head holds
  // it from nothing, and waiting for it, each would wait for the other.
  auto waitsFor = [&](const Contact& c) {
    const Instance* inst = e.instanceIn(c.part);
    return unstepped(c) && inst &&
           dot128(c.normal, inst->frame == 0 ? pressed : rotateWide(inst->rotation, pressed)) < 0;
  };
  if (std::none_of(contacts.begin(), contacts.end(), waitsFor)) return false;  // no list made
  std::vector<uint32_t> holders;  // a step may change the contacts: the slots are read first
  for (const Contact& c : contacts)
    if (waitsFor(c)) holders.push_back(c.other.index);
  e.awaiting = {true, false, frame, velocityBefore, e.subunitQ17};
  bool stepped = false;
  // Before its own move the entity is where the index has it (reindexing would only wake it).
  for (size_t k = 0; k < holders.size() && !e.awaiting.takenOver; ++k)
    stepped = stepMetEntityFirst(e, holders[k], false) || stepped;
  e.awaiting.now = false;
  return stepped || e.awaiting.takenOver;
}

void WorldImpl::slide(Move& move) {
  Entity& e = move.entity;
  if (!e.instances.empty()) move.startFace = e.instances[startCopy(e, std::nullopt)].part;
  int pushes = 0;
  for (int iteration = 0; iteration < kMaxSubMoves && !e.instances.empty(); ++iteration) {
    createOverlappedWarps(e);
    if (move.motion == Vec2w{} && (copiesSettled(e) || iteration > 0)) break;  // gaps get one try a frame
    ++report.subMoves;
    SubMove sub(*this, move);
    sub.planMotions();
    sub.findFirstEvent();
    if (sub.unsteppedMet() != UINT32_MAX && stepMetEntityFirst(e, sub.unsteppedMet())) {
      --iteration;  // the same sub-move again: each time, one more entity has stepped (finite)
      continue;
    }
    if (sub.liftAtSeam()) continue;
    sub.resolveContactNormal();
    sub.roundSteps();
    sub.commit();
    sub.afterMove();
    const SubMove::Next next = sub.next();
    if (next == SubMove::Next::Stop) break;
    if (next == SubMove::Next::Again) continue;
    const SubMove::After after = sub.respondToContact(pushes);
    if (after == SubMove::After::Stop || (after == SubMove::After::Slide && move.straight)) break;
  }
  keepOnFace(move);
}

}  // namespace platon::physics

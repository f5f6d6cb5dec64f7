// The solver's state and its steps. World (platon/physics/world.h) is the checked public face;
// this is what it owns. Files: world.cpp (ownership, handles, the public API), placement.cpp
// (regions, free places, first blocking line), step.cpp (one entity's frame: the slide),
// rotation.cpp, warps.cpp (instances across warp edges), pierce_events.cpp, state_hash.cpp.
#pragma once
#include <algorithm>
#include <deque>
#include <exception>
#include <memory>
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "bounds.h"
#include "contact_normal.h"
#include "entity.h"
#include "entity_index.h"
#include "fixed_point.h"
#include "grid.h"
#include "line_boxes.h"
#include "platon/physics/world.h"

namespace platon::physics {

// One entity's motion through one frame: the motion still to go and the contacts met so far,
// shared by the sub-moves of the slide and by the warp bookkeeping that may turn the frame.
struct Move {
  Entity& entity;
  Vec2w motion;                 // whole units still to move, in the entity's frame
  std::vector<Vec2w>& normals;  // this frame's contact normals, in the entity's frame
  // The frame's motion and velocity before any contact: contacts that turn either against them
  // mean a crease (see SubMove::slideAlong).
  Vec2w primalMotion;
  Vec2w primalVelocity;
  // The part's gravity (per frame, Q16), the part of it the velocity still gains until the frame
  // ends (all of it in flight; along the line while sliding on one), and the part of the frame
  // still to go (Q30): at a contact the velocity at that moment turns along the line, and the
  // rest of the frame's gravity acts as that line lets it.
  Vec2w gravityQ16{};
  Vec2w actingGravityQ16{};
  // The frame's exact motion (Q17, the remainder included) until its first contact: which way the
  // body means to go, where its whole-unit motion (rounded down) points a unit off it.
  Vec2w exactQ17{};
  int64_t timeLeftQ30 = int64_t{1} << kQ30Bits;
  // The latest lift at a seam (SubMove::liftAtSeam): a lift that leaves the same instance meeting
  // the same line no later is no help, and the line is then met as a line.
  struct Lift {
    size_t instance = SIZE_MAX;
    LineIndex line = 0;
    Fraction t;
  } lastLift{};
  // The part of the copy whose centre stood least off its face when the slide began (where the
  // body was, on the solid): a path through a vertex goes on from that copy (keepOnFace).
  std::optional<MapPartId> startFace{};
  // Straight on: a contact ends the move instead of turning it along the line (a body carried in a
  // platform's pocket goes where the platform goes, or stops).
  bool straight = false;
};

// Where each instance went during one sub-move, for the pierce events along the way. Empty: the
// instances did not move (an insert, a rotation), and only their present overlap counts.
struct Path {
  std::span<const std::vector<Vec2>> start;  // world vertices before the sub-move
  std::span<const Vec2w> steps;              // the whole-unit step each took
  std::span<const uint8_t> pierceNear;       // whether any pierceable line was near its path
};

// A platform's lines on a face beside its own (World::createPlatform): placed once through the
// warp, rounded, then moved rigidly, each frame by the whole-unit step that follows `originQ30`,
// the exact image of the platform's moves, as an entity's copy follows its anchor.
struct PlatformCopy {
  MapPartId part = 0;
  std::vector<PlatformLine> lines;
  Box box{0, 0, -1, -1};
  Rotation rotation;   // the platform's frame into this part's
  Vec2w originQ30;     // where the platform's moves so far take a point that started at 0
  LineIndex edge = 0;  // the platform's part's warp line it is placed through (a turn maps its lines again)
  // The step of the copy's lines when the platform steps by `step`.
  Vec2w stepFor(Vec2w step) const {
    return pointFromQ30(originQ30 + rotateQ30(rotation, step)) - pointFromQ30(originQ30);
  }
};

// A moving platform (see World::createPlatform). Its lines are kept where they are now.
struct Platform {
  MapPartId part = 0;
  // Its lines as created; where they are now is those turned by `angle` about `pivot` (both in the
  // created lines' coordinates), each end rounded to the nearest unit, then moved by `offset`. Every
  // frame recomputes them from these, so turns and moves never drift.
  std::vector<PlatformLine> base;
  std::vector<PlatformLine> lines;
  Vec2 offset, motion;
  // Its motion exactly, in Q30, and what whole-unit frames have left of it: as set, `motion`
  // itself and nothing; turned into another part's frame when it crosses a warp edge, whole units a
  // frame that add up to it exactly (`motion` is then its nearest whole units).
  Vec2w motionQ30, motionLeftQ30;
  Vec2 pivot;
  Angle angle = 0;
  int32_t spin = 0;                  // binary-angle units a frame
  uint64_t work = 0;                 // the latest frame's (PlatformView::work)
  Box box{0, 0, -1, -1};             // around its lines, where they are now
  std::vector<PlatformCopy> copies;  // one a part at most
  uint32_t generation = 0;
  bool alive = false;
};

// The box around a platform's lines.
Box boxOfLines(const std::vector<PlatformLine>& lines);

// Sub-steps that turn a shape of squared radius `radius2` (about the turning point) by `delta`
// binary-angle units with every point's arc within half a unit of its chord (rotation.cpp).
int64_t rotationSubSteps(int64_t radius2, int64_t delta);
// The squared distance of a platform's farthest line end from `pivot` (capped at INT64_MAX).
int64_t turnRadius2(const std::vector<PlatformLine>& lines, Vec2 pivot);

// A platform's line as the solver names it: this bit, the platform's slot << 16, the line.
inline constexpr LineIndex kPlatformLineBit = 0x40000000u;
constexpr bool isPlatformLine(LineIndex key) { return (key & kPlatformLineBit) != 0 && key < 0x80000000u; }

struct WorldImpl {
  struct Slot {
    std::unique_ptr<Entity> entity;
    uint32_t generation = 0;
  };

  std::deque<MapPart> parts;        // stable addresses
  std::vector<MapPart*> partIndex;  // sorted by id
  // Parts by id for ids below kPartsById (levels number their faces from 0): a read, not a search.
  static constexpr MapPartId kPartsById = 4096;
  std::vector<MapPart*> partById;        // null where no part has that id
  std::vector<MapPart*> uncheckedWarps;  // parts whose warp targets have not been checked yet
  std::vector<Slot> slots;
  std::vector<uint32_t> freeSlots;
  size_t liveEntities = 0;
  Rules defaultRules;
  Rules* rules = &defaultRules;
  uint64_t frame = 0;
  bool locked = false;  // inside solve() or another call that runs rules callbacks
  std::exception_ptr pendingError;
  SolveReport report;
  EntityIndex entityIndex;  // entities that meet other entities, by place
  // Pairs of entities that report overlaps and overlap now: (lower slot, higher slot, part).
  struct OverlapPair {
    uint32_t a, b;
    MapPartId part;
    friend auto operator<=>(const OverlapPair&, const OverlapPair&) = default;
  };
  std::vector<OverlapPair> entityOverlaps;
  // The slots whose instances may overlap pierceable lines (listed when an instance's `overlapping`
  // is set; fireOverContacts keeps those that still do): its over events walk these, not every body
  // (a crowd of 10,000 resting bodies paid a second walk over all of them every frame).
  std::vector<uint32_t> overlappingSlots;
  int pushDepth = 0;  // entities pushing entities pushing entities: bounded
  // Entities step in handle order, but one that another's move meets steps first, so that a move
  // (a push chain too) meets it where it is this frame (stepMetEntityFirst).
  bool steppingEntities = false;  // solve() is stepping the entities (not moving platforms)
  int neighbourDepth = 0;         // steps begun for a neighbour inside another's step: bounded
  static constexpr int kMaxNeighbourDepth = 32;
  std::vector<Platform> platforms;
  std::vector<uint32_t> freePlatforms;
  // countOverlaps' index of each part's fixed lines, made the first time it is asked.
  mutable std::unordered_map<MapPartId, std::unique_ptr<LineBoxes>> overlapLineIndex;
  const LineBoxes& overlapLines(const MapPart& part) const;
  // Rest that costs nothing (entity.h's `resting`): how many entities keep their rest answer, how
  // often each part's platforms moved, and the mode that asks anyway and compares (World::checkRest).
  size_t restingCount = 0;
  std::unordered_map<MapPartId, uint64_t> platformEpochs;
  bool restCache = true, restCheck = false;
  void wake(Entity& e) {
    if (e.resting) e.resting = false, --restingCount;
  }
  void wakeAll() {
    for (Slot& s : slots)
      if (s.entity) wake(*s.entity);
  }
  // Wakes every entity filed near `e` (within a cell of where the index has it), `e` too.
  void wakeAround(const Entity& e);
  bool keepsRest(const Entity& e) const;
  uint64_t platformEpochOf(const Entity& e) const;
  // A line (or an entity, by its slot) that a sub-move's hit touches, and its normals' range in
  // Scratch::lineNormals.
  struct TouchingLine {
    uint32_t key;
    uint32_t begin, end;
  };
  // Per-frame buffers, kept to avoid allocating on every step (solve is not reentrant).
  struct Scratch {
    std::vector<std::vector<Vec2>> verts;
    std::vector<Vec2w> moves, steps, normals;
    std::vector<uint8_t> pierceNear;
    std::vector<Vec2> now, probe;
    std::vector<Vec2> other;  // another entity's vertices, in the innermost loops (never held across calls)
    std::vector<TouchingLine> touchingLines;
    std::vector<Vec2w> lineNormals;
    std::vector<Contact> arrived;
    // The rest test's contacts, made into Contacts only if it holds (most moving bodies are not).
    struct RestContact {
      MapPartId part;
      LineIndex line;
      Vec2w normal;
      EntityId other;
    };
    std::vector<RestContact> restContacts;
    // The part lines the rest test found touching a body's vertices (restOnPartLines) and the
    // normals nearNormals gave them: touchingNormals at t = 0 gives the same for the same vertices
    // and segment (a pure function of the two: see contact_normal.h), so the slide's contact where
    // the body stands (resolveContactNormal) reads them here. Kept for the last vertices tested.
    struct TouchMemo {
      MapPartId part = 0;
      std::vector<Vec2> verts;
      std::vector<TouchingLine> lines;  // key: the line; [begin, end) in normals
      std::vector<Vec2w> normals;
      bool holds(MapPartId p, std::span<const Vec2> v) const {
        return p == part && std::equal(v.begin(), v.end(), verts.begin(), verts.end());
      }
      const TouchingLine* find(LineIndex line) const {
        for (const TouchingLine& t : lines)
          if (t.key == line) return &t;
        return nullptr;
      }
    } touchMemo;
    OpenDirections open;
  } scratch;

  // world.cpp
  // Inline: the slide asks for an instance's part many times a sub-move.
  const MapPart* findPart(MapPartId id) const {
    if (id < partById.size()) return partById[id];
    auto it = std::lower_bound(partIndex.begin(), partIndex.end(), id,
                               [](const MapPart* p, MapPartId v) { return p->id() < v; });
    return it != partIndex.end() && (*it)->id() == id ? *it : nullptr;
  }
  const MapPart& part(MapPartId id) const {
    const MapPart* p = findPart(id);
    if (!p) [[unlikely]]
      throwNoPart(id);
    return *p;
  }
  [[noreturn]] static void throwNoPart(MapPartId id);
  Entity& entity(EntityId id);
  const Entity& entity(EntityId id) const;
  void checkUnlocked(const char* what) const;
  void checkWarpTargets();

  // entities meeting entities (entity_contacts.cpp)
  // Files or unfiles the entity in the index after it moved, changed shape or filter.
  void reindex(const Entity& e);
  // Calls visit(other, otherInstance) for each entity solid to `e` (or reporting overlaps with it)
  // with an instance in `part` whose box may meet `box`.
  template <class Visit>
  void forEachSolidNear(const Entity& e, MapPartId part, const Box& box, Visit&& visit);
  template <class Visit>
  void forEachOverlappingNear(const Entity& e, MapPartId part, const Box& box, Visit&& visit);
  // The first entity solid to `e` whose instance in inst's part the vertices overlap.
  std::optional<EntityId> entityOverlap(const Entity& e, const Instance& inst, std::span<const Vec2> verts);
  // Moves entity `b` by `push` (its own frame) as a slide of its own; returns whether it moved.
  bool push(Entity& b, Vec2w push, bool straight = false);
  // A body carried in a pocket of one platform's lines (carryInPocket): that platform's lines are
  // not in the body's way, nor the body in theirs.
  struct Pocket {
    uint32_t platform = UINT32_MAX, entity = UINT32_MAX;
  } pocket;
  bool inPocket(const Entity& e, LineIndex platformLine) const {
    return e.id.index == pocket.entity && ((platformLine & ~kPlatformLineBit) >> 16) == pocket.platform;
  }
  bool heldByOwnLines(uint32_t slot, const Entity& e, Vec2w motion);
  bool nearAWarp(Instance& inst, Vec2w step);
  Vec2w carryInPocket(uint32_t slot, uint32_t entity, Vec2w remaining);
  // Begin and end events of entities that report overlaps, along a sub-move's path (or at rest),
  // added to `events` for updatePierceState to order.
  struct PathEvent {
    Fraction t;
    size_t instance;
    uint64_t key;  // lines: the line index; entities: (1 << 32) | slot, so lines come first
    bool begin;
    Vec2w normal;
    ContactPoints points;
    EntityId other;
  };
  void entityOverlapEvents(Entity& e, const Path& path, std::vector<PathEvent>& events);
  // When along its path an instance entered and left what it met: the sweep's times within the
  // frame; the frame's start and end when it did not move or the sweep says no more.
  static Fraction enterTime(bool moved, const Sweep& s) {
    return moved && s.hasEnter && s.enter > Fraction::zero() ? s.enter : Fraction::zero();
  }
  static Fraction exitTime(bool moved, const Sweep& s) {
    return moved && s.hasExit && s.exit < Fraction::one() ? s.exit : Fraction::one();
  }
  void endEntityOverlaps(Entity& e, MapPartId part);

  // platforms.cpp
  void movePlatforms();
  // movePlatforms' steps, for one platform (its slot).
  struct Rider {
    uint32_t entity;  // its slot
    MapPartId part;   // where it stands on the platform: its part, or a copy's
    Vec2 start;       // where it stood there before the platform moved
    Vec2 origin;      // where the lines it stands on were (the platform's offset, a copy's origin)
  };
  struct PlatformHit {
    Fraction at = Fraction::one();  // of the motion; one: nothing met
    uint32_t entity = 0, line = 0;
    MapPartId part = 0;  // where: the platform's part or a copy's
  };
  std::vector<Rider> ridersOf(uint32_t slot);
  PlatformHit firstPlatformHit(uint32_t slot, Vec2w motion);
  Vec2w clearPlatformStep(uint32_t slot, Vec2w step, std::optional<PlatformHit>& blocker);
  // Rules::crushed for the entity (its slot) that platform `slot`'s line `line` stopped in `part`.
  void crushed(uint32_t slot, uint32_t entity, uint32_t line, MapPartId part);
  // platform_copies.cpp: the copies platform `slot` needs moving by `motion` (made where its lines
  // come within reach of a warp edge, dropped where they no longer do). A new copy over a body: at a
  // frame's start made (the body is one left in a copy's line: cleared off it, or passed through);
  // on creation not made, and the body is returned (World::createPlatform refuses the platform);
  // just after crossing not made over any body at all, nor is any copy dropped (the next frame's
  // start decides, where the body may have gone).
  enum class CopyPlacing { Frame, Create, Crossed };
  std::optional<PlatformHit> updatePlatformCopies(uint32_t slot, Vec2w motion, CopyPlacing placing);
  std::optional<LineIndex> copyEdgeOf(const Platform& pl, Vec2w motion);
  template <class Meets>
  std::optional<PlatformHit> firstBodyIn(const PlatformCopy& c, Meets&& meets);
  bool anyBodyIn(const PlatformCopy& c);
  // Once every line of platform `slot` is beyond one warp edge, it belongs to the face beyond
  // (true: it crossed).
  bool crossPlatform(uint32_t slot);
  // Lifts the copies of bodies met elsewhere (platformMeets) off the platform's copy lines they
  // overlap by rounding.
  void clearPlatformCopies(uint32_t slot);
  // Where a platform meets an entity: the first of its parts (its own, then its copies') the entity
  // has an instance in. The entity's instances and the platform's lines in other parts are the same
  // things again, each rounded in its own frame: met there as well, a unit's disagreement between
  // the two roundings would be a collision of its own.
  static std::optional<MapPartId> platformMeets(const Platform& pl, const Entity& e) {
    if (e.instanceIn(pl.part)) return pl.part;
    for (const PlatformCopy& c : pl.copies)
      if (e.instanceIn(c.part)) return c.part;
    return std::nullopt;
  }
  // The first of the lines the polygon is in (its interior across a solid line; a one-way line
  // lets through what crosses it, and a polygon wholly in front of one is not across it).
  static std::optional<uint32_t> lineItIsIn(std::span<const PlatformLine> lines, std::span<const Vec2> verts) {
    for (uint32_t k = 0; k < lines.size(); ++k)
      if (lines[k].kind != LineKind::OneWay && overlapsInterior(verts, lines[k].segment)) return k;
    return std::nullopt;
  }
  // Whether a body the platform meets in a copy's part is in one of the copy's lines there (its own
  // copy was there, rounded in its frame, when the platform came to meet it there; or the copy was
  // made where it already was): the platform passes through it, as a one-way line passes what is
  // behind it: its lines neither push, carry nor stop at it until it is out of them.
  static bool passesThrough(std::span<const PlatformLine> lines, std::span<const Vec2> verts) {
    return lineItIsIn(lines, verts).has_value();
  }
  // Where the lines of a platform are in one of its parts (its own, or its copy's), with the step
  // they take there when the platform steps by some step.
  struct PlatformPlace {
    MapPartId part;
    const std::vector<PlatformLine>& lines;
    const Box& box;
    Vec2w step;
  };
  template <class Visit>
  void forEachPlatformPlace(const Platform& pl, Vec2w step, Visit&& visit) const {
    visit(PlatformPlace{pl.part, pl.lines, pl.box, step});
    for (const PlatformCopy& c : pl.copies) visit(PlatformPlace{c.part, c.lines, c.box, c.stepFor(step)});
  }
  void shiftPlatform(uint32_t slot, Vec2w step);
  // This frame's whole-unit motion (Platform::motionQ30 and what earlier frames left of it).
  static Vec2w frameMotion(Platform& pl);
  Vec2w advancePlatform(uint32_t slot, Vec2w motion);
  void carryRiders(uint32_t slot, const std::vector<Rider>& riders, Vec2w moved, Angle turned);
  void settleOn(MapPartId part, const std::vector<PlatformLine>& lines, Entity& e);
  // Where platform `slot`'s lines are at `angle` (its offset as it is).
  void placePlatformLines(const Platform& pl, Angle angle, std::vector<PlatformLine>& out) const;
  // Turns platform `slot` by its spin in sub-steps, pushing what each sub-step's lines sweep over;
  // stops (Rules::crushed) at the first sub-step whose room cannot be made. Returns the angle turned.
  Angle turnPlatform(uint32_t slot);
  // Pushes every entity that turning platform `slot` from its lines to `next` sweeps over; false
  // (and `blocker`, its slot) when one cannot be cleared of the lines' new place.
  // One place of a turning platform's sub-step: its part or a copy's, its lines from and to, the
  // pivot there.
  struct TurnPlace {
    MapPartId part;
    const std::vector<PlatformLine>* from;
    std::vector<PlatformLine> to;
    Vec2w pivot;
  };
  bool clearTurn(uint32_t slot, const TurnPlace& at, uint32_t& blocker, bool& pushedAny, bool pushing);
  // A platform's lines (or a point) in its part, placed through the warp of its part's warp line
  // `edge`: false (nothing) where an end falls beyond the coordinate range there.
  bool linesThrough(const Platform& pl, LineIndex edge, std::vector<PlatformLine>& lines) const;
  Vec2w pointThrough(const Platform& pl, LineIndex edge, Vec2w point) const;
  // Calls visit(line, key) for each line of a live platform in `part` whose platform box meets
  // `box` (the caller tests the line itself).
  template <class Visit>
  void forEachPlatformLine(MapPartId part, const Box& box, Visit&& visit) const;
  // A platform line by its key: as created (its tag and kind), or where it is in a part.
  const PlatformLine& platformLine(LineIndex key) const {
    return platforms[(key & ~kPlatformLineBit) >> 16].lines[key & 0xffff];
  }
  const PlatformLine& platformLine(MapPartId part, LineIndex key) const {
    return (*platformLinesIn(platforms[(key & ~kPlatformLineBit) >> 16], part))[key & 0xffff];
  }
  // A platform's lines in `part`: its own, or its copy's there; nullptr: none there.
  static const std::vector<PlatformLine>* platformLinesIn(const Platform& pl, MapPartId part) {
    if (pl.part == part) return &pl.lines;
    const PlatformCopy* c = platformCopyIn(pl, part);
    return c ? &c->lines : nullptr;
  }
  static const PlatformCopy* platformCopyIn(const Platform& pl, MapPartId part) {
    for (const PlatformCopy& c : pl.copies)
      if (c.part == part) return &c;
    return nullptr;
  }
  // A line's segment where it is now: the part's own, or a platform's there.
  const Segment& segmentOf(const MapPart& p, LineIndex line) const {
    return isPlatformLine(line) ? platformLine(p.id(), line).segment : p.segments()[line];
  }

  // placement.cpp
  Instance makeInstance(const Entity& e, MapPartId part, Vec2 position, Angle turn) const;
  // Whether region line k lets the instance through. Inline: every sweep asks it of every line
  // near, and the answer is almost always the one the region keeps.
  bool isPierceable(const Entity& e, Instance& inst, size_t regionIndex) {
    const uint8_t kept = inst.region.flags()[regionIndex];
    if (kept == 1) return false;
    if (kept == 2 && inst.blockedWarps.empty()) return true;
    return askPierceable(e, inst, regionIndex);
  }
  bool askPierceable(const Entity& e, Instance& inst, size_t regionIndex);  // not kept, or a warp held
  // Whether region line k stops the instance whose vertices are `verts`: it is not pierceable, and
  // if it is one-way, the instance is wholly on its front.
  bool blocks(const Entity& e, Instance& inst, size_t regionIndex, std::span<const Vec2> verts) {
    if (isPierceable(e, inst, regionIndex)) return false;
    const MapPart& p = part(inst.part);
    const LineIndex index = inst.region.lines()[regionIndex];
    return p.lines()[index].kind != LineKind::OneWay || wholyInFront(verts, p.segments()[index]);
  }
  // Makes the instance's region hold every line near its shape moved by anything from 0 to
  // `motion`, and within `slack` more units around that.
  // (Inline, as coverBox: every sub-move asks, and the region almost always has those cells.)
  void coverMotion(Instance& inst, Vec2w motion, int64_t slack = 0) {
    Box b = sweptBox(inst, motion);
    coverBox(inst, {b.x0 - slack, b.y0 - slack, b.x1 + slack, b.y1 + slack});
  }
  // The same for any box of the part's coordinates (a rotation covers the hull it sweeps).
  void coverBox(Instance& inst, Box b) {
    // One unit of margin: points on the box edge round into the next cell's range.
    b.x0 -= 1, b.y0 -= 1, b.x1 += 1, b.y1 += 1;
    const Grid& grid = part(inst.part).grid();
    if (!inst.region.keeps(grid, b)) inst.region.update(grid, grid.cellsCovering(b, inst.region.rect()));
  }
  // The first solid line (in region order) whose interior the vertices overlap, if any. The
  // region must already cover them.
  std::optional<LineIndex> solidOverlap(const Entity& e, Instance& inst, std::span<const Vec2> verts);
  // Whether the vertices are inside the coordinate range and overlap no solid line.
  bool isFree(const Entity& e, Instance& inst, std::span<const Vec2> verts);
  // The earliest time in [0, 1) at which `verts` moved by `step` meets a solid line or the range's
  // edge; 1 when none.
  Fraction firstBlock(const Entity& e, Instance& inst, std::span<const Vec2> verts, Vec2w step);

  // step.cpp
  // The entity's frame, once per solve(): its contacts and work start afresh.
  void stepInFrame(Entity& e);
  // A sub-move of `mover` met the entity in `slot`: if that one has not stepped this frame, it steps
  // now (returns true, and the sub-move is planned again). The mover is reindexed first if it may
  // have moved since it was last.
  bool stepMetEntityFirst(Entity& mover, uint32_t slot, bool moverMoved = true);
  // The same for the entities among `contacts` (e's rest test's, or its kept rest's: `kept`) that
  // e is pressed into (by the velocity its rest test asks with), before e moves: whether any
  // stepped. Meanwhile e counts as not stepped (Entity::awaiting); `velocityBefore` is its velocity
  // when its step began.
  bool stepHoldersFirst(Entity& e, const std::vector<Contact>& contacts, Vec2w velocityBefore, bool kept);
  // Whether e has taken its step this frame (one waiting for its holders has not).
  bool steppedThisFrame(const Entity& e) const;
  void stepEntity(Entity& e);
  void stepEntityTested(Entity& e);  // the step as it is without a kept rest answer
  void slide(Move& move);
  // Whether the entity, wanting to move along w (its velocity after gravity), presses into the
  // solid lines it is against (touching or within one unit) so that it cannot move at all. If so,
  // they become its contacts for this frame.
  bool restsAgainstLines(Entity& e, Vec2w w);
  // Its steps, for one instance (its vertices and their box grown by 2): whether one touches it.
  bool restOnPartLines(Entity& e, Instance& inst, const std::vector<Vec2>& verts, const Box& box, Vec2w w);
  bool restOnPlatformLines(Instance& inst, const std::vector<Vec2>& verts, const Box& box, Vec2w w);
  bool restOnEntities(Entity& e, Instance& inst, const std::vector<Vec2>& verts, const Box& box, Vec2w w);
  // The entity was moving and has just come to rest against its contacts (restsAgainstLines): the
  // rules hear of each. They may let it rest; send it off with a velocity that no longer presses
  // into them (it Stays where it is for the rest of this frame, as a slide along its contacts
  // would); or bounce it, which turns its velocity and this frame's motion (`frameQ17`).
  enum class Arrival { Rests, Stays, Bounces };
  Arrival reportArrival(Entity& e, Vec2w& frameQ17);

  // rotation.cpp
  bool rotateBy(Entity& e, int64_t delta);
  bool rotationStepFits(Entity& e, Instance& inst, Angle angle, std::vector<Vec2>& next);
  std::optional<Contact> rotationLineHit(Entity& e, Instance& inst, const std::vector<Vec2>& hull,
                                         const std::vector<Vec2>& before);
  std::optional<Contact> rotationBodyHit(Entity& e, const Instance& inst, const std::vector<Vec2>& hull);

  // warps.cpp
  // A new instance across the warp `warpLine` of instance `from`, where the point `fromQ30` maps;
  // placed so it can travel furthest along `probe`. False when the far side has no room.
  bool createWarpInstance(Entity& e, size_t from, LineIndex warpLine, Vec2w fromQ30, Vec2w probe);
  // Instances overlapping a warp whose far side has no instance get one (most have no overlap:
  // inline, that costs a look at each instance).
  void createOverlappedWarps(Entity& e) {
    for (const Instance& inst : e.instances)
      if (!inst.overlapping.empty()) return makeOverlappedWarpInstances(e);
  }
  void makeOverlappedWarpInstances(Entity& e);
  // Moves `inst` to the free whole-unit position within two units of `targetQ30` (touching
  // `mustTouch` if given) that lets it travel furthest along `probe`, nearest first among equals.
  bool placeNear(const Entity& e, Instance& inst, Vec2w targetQ30, const Segment* mustTouch, Vec2w probe);
  // Moves the copy one to three units along `direction` (its own frame) to the first place that is
  // free and lets it start along `move`; false (and unmoved) if there is none.
  bool liftCopy(const Entity& e, Instance& copy, Vec2w direction, Vec2w move);
  // Makes instance k the anchor: the frame, velocity, remainder and motion turn with it.
  void rebase(Move& move, size_t k);
  bool snapKeepsTouches(const Entity& e, Instance& inst, Vec2w gap);
  // Turns what is left of a frame's move into a frame turned by theta (the anchor changed).
  void turnMove(Move& move, Angle theta);
  void updateLinks(Move& move);
  void eraseUnlinkedCopies(Move& move);
  void eraseInstance(Move& move, size_t index);

  // vertices.cpp. After a slide: an entity whose every copy is beyond its face's corners (it went
  // through a vertex) goes on over the faces round the vertex (faces: MapPart::faceLoop).
  void keepOnFace(Move& move);
  size_t startCopy(const Entity& e, std::optional<MapPartId> inPart) const;
  // Its steps: places on a face for the body, and the body put at one.
  struct FacePlace;
  FacePlace continuePastVertex(const Entity& e, size_t from, bool otherSide) const;
  FacePlace inwardOnFace(const Entity& e, size_t from, int64_t inset) const;
  FacePlace backOnFace(const Entity& e, size_t from, int64_t inset) const;
  bool placeOnFace(Move& move, const FacePlace& c);
  void stopAtFaceEdges(Entity& e);
  struct CornerReturn;
  CornerReturn cornerReturn(const Entity& e) const;
  int64_t placeByCorner(Entity& e, const CornerReturn& r);

  // pierce_events.cpp
  // The begin and end events of the pierceable lines and overlapping entities along the path. Most
  // moves have nothing pierceable near, nothing overlapped and no overlaps reported (inline, that
  // is a look at each instance).
  void updatePierceState(Entity& e, const Path& path) {
    if (e.filter.overlapWith == 0 && e.filter.category == 0) {
      size_t i = 0;
      while (i < e.instances.size() && pierceQuiet(e, path, i)) ++i;
      if (i == e.instances.size()) return;
    }
    firePierceEvents(e, path);
  }
  // Whether instance i has nothing pierceable near the path and overlaps nothing.
  static bool pierceQuiet(const Entity& e, const Path& path, size_t i) {
    return i < path.pierceNear.size() && !path.pierceNear[i] && e.instances[i].overlapping.empty();
  }
  void firePierceEvents(Entity& e, const Path& path);
  void instancePierceEvents(Entity& e, const Path& path, size_t i, std::vector<PathEvent>& events);
  void firePathEvents(Entity& e, std::vector<PathEvent>& events);
  void fireOverContacts();
  Contact makeContact(const Entity& e, MapPartId part, LineIndex line, Fraction t, Vec2w normal,
                      ContactPoints points) const;
  Contact makeContact(const Entity& e, const Instance& inst, LineIndex line, Fraction t, Vec2w normal,
                      ContactPoints points) const {
    return makeContact(e, inst.part, line, t, normal, points);
  }
  // A restitution a callback left in its ContactResponse, or zero (and an Error for solve() to
  // throw at the end of the frame) when it is not a fraction num/den with num >= 0 and den > 0.
  Fraction checkedRestitution(Fraction r) {
    if (r.den > 0 && r.num >= 0) return r;
    if (!pendingError)
      pendingError = std::make_exception_ptr(Error("ContactResponse::restitution " + std::to_string(r.num) + "/" +
                                                   std::to_string(r.den) + ": needs num >= 0 and den > 0"));
    return Fraction::zero();
  }
  // Runs a rules callback; an exception is kept for the CallbackScope to rethrow once the world
  // is whole again.
  template <class F>
  void callRules(F&& f) {
    try {
      f(*rules);
    } catch (...) {
      if (!pendingError) pendingError = std::current_exception();
    }
  }
};

template <class Visit>
void WorldImpl::forEachPlatformLine(MapPartId part, const Box& box, Visit&& visit) const {
  for (uint32_t slot = 0; slot < platforms.size(); ++slot) {
    const Platform& pl = platforms[slot];
    if (!pl.alive) continue;
    const std::vector<PlatformLine>* lines = platformLinesIn(pl, part);
    if (!lines) continue;
    const Box& b = lines == &pl.lines ? pl.box : platformCopyIn(pl, part)->box;
    if (b.x0 > box.x1 || b.x1 < box.x0 || b.y0 > box.y1 || b.y1 < box.y0) continue;
    for (uint32_t k = 0; k < lines->size(); ++k) visit((*lines)[k], kPlatformLineBit | (slot << 16) | k);
  }
}

template <class Visit>
void WorldImpl::forEachSolidNear(const Entity& e, MapPartId part, const Box& box, Visit&& visit) {
  if (e.filter.solidWith == 0) return;
  entityIndex.forEachNear(part, box, [&](uint32_t slot) {
    const Entity* other = slots[slot].entity.get();
    if (!other || other == &e || !solidPair(e.filter, other->filter)) return;
    const Instance* inst = other->instanceIn(part);
    if (inst && boxMeets(*inst, box)) visit(*other, *inst);
  });
}

template <class Visit>
void WorldImpl::forEachOverlappingNear(const Entity& e, MapPartId part, const Box& box, Visit&& visit) {
  entityIndex.forEachNear(part, box, [&](uint32_t slot) {
    const Entity* other = slots[slot].entity.get();
    if (!other || other == &e || !overlapPair(e.filter, other->filter)) return;
    const Instance* inst = other->instanceIn(part);
    if (inst && boxMeets(*inst, box)) visit(*other, *inst);
  });
}

// Rules callbacks may run while a scope lives: structural changes are refused (checkUnlocked), and
// the first error a callback throws waits in pendingError. finish() rethrows it once the caller's
// work is whole. Leaving without finish() (the solver itself threw) drops it: that error wins.
class CallbackScope {
 public:
  explicit CallbackScope(WorldImpl& world) : world_(world) { world_.locked = true; }
  ~CallbackScope() {
    world_.locked = false;
    world_.pendingError = nullptr;
  }
  CallbackScope(const CallbackScope&) = delete;
  CallbackScope& operator=(const CallbackScope&) = delete;
  void finish() {
    world_.locked = false;
    if (world_.pendingError) std::rethrow_exception(std::exchange(world_.pendingError, nullptr));
  }

 private:
  WorldImpl& world_;
};

}  // namespace platon::physics

// A body that goes through a vertex of a solid. The faces meeting at a vertex leave less than a
// full turn around it, so a path through the vertex (or near enough that every copy's centre
// comes out beyond its face's corner) crosses no warp edge: nothing would ever bring the body back
// onto a face. Its path goes on over the faces around the vertex instead, as if they were laid
// flat beside the face it left (a geodesic), from where it is, as far as it went: no jump.
#include <algorithm>
#include <array>

#include "faces.h"
#include "world_impl.h"

namespace platon::physics {
namespace {

// Whether velocity `v` leaves the face at corner k across the edge that starts there (`out`) by
// more than across the edge that ends there (`in`): the larger outward speed, ties to `out`.
bool leavesByOut(const MapPart& face, size_t k, Vec2w v) {
  const auto loop = face.faceLoop();
  const Segment out = face.segments()[loop[k]];
  const Segment in = face.segments()[loop[(k + loop.size() - 1) % loop.size()]];
  const Vec2w outDir = out.b - out.a, inDir = in.b - in.a;
  // Outward normals: right of each counter-clockwise edge.
  const i128 leaveOut = (i128{v.x} * outDir.y - i128{v.y} * outDir.x) * lengthOf(inDir);
  const i128 leaveIn = (i128{v.x} * inDir.y - i128{v.y} * inDir.x) * lengthOf(outDir);
  return leaveOut >= leaveIn;
}

// How far from corner k along either of its edges a point must lie to be `clearance` units from
// the other edge's line: clearance / sin(angle), or just clearance where the corner is obtuse
// (the vertex itself is then the nearest point of the other edge).
int64_t alongForClearance(const MapPart& face, size_t k, int64_t clearance) {
  const auto loop = face.faceLoop();
  const Segment out = face.segments()[loop[k]];
  const Segment in = face.segments()[loop[(k + loop.size() - 1) % loop.size()]];
  const Vec2w a = in.b - in.a, b = out.b - out.a;
  const i128 dot = i128{a.x} * b.x + i128{a.y} * b.y;
  const i128 cross = i128{a.x} * b.y - i128{a.y} * b.x;
  if (dot >= 0 || cross <= 0) return clearance;
  const i128 lengths = i128{lengthOf(a)} * lengthOf(b);
  return static_cast<int64_t>(std::min<i128>((i128{clearance} * lengths + cross - 1) / cross, INT64_MAX));
}

bool sameEdge(Segment a, Segment b) { return (a.a == b.a && a.b == b.b) || (a.a == b.b && a.b == b.a); }

}  // namespace

// A place on a face for the body: its centre there, and the turn from the anchor's frame into
// that face's.
struct WorldImpl::FacePlace {
  bool found = false;
  MapPartId part = 0;
  Vec2w centreQ30;
  Angle turn = 0;
};

// The path past the vertex, from copy `from`: the same distance from the vertex, the same heading,
// only turned by the warps crossed, face after face round the vertex until one holds the point.
// It goes round on the side of the vertex the path passed: across the one edge it is past, or,
// past both edges at the corner, the one its heading passes the vertex beside (through the vertex
// itself, the one it leaves by most). `otherSide`: round the other way (past both edges only).
WorldImpl::FacePlace WorldImpl::continuePastVertex(const Entity& e, size_t from, bool otherSide) const {
  const Instance& start = e.instances[from];
  const MapPart* face = &part(start.part);
  const Vec2 centre = centreOf(start);
  auto loop = face->faceLoop();
  size_t k = nearestCorner(*face, centre);
  const Segment out = face->segments()[loop[k]];
  const Segment in = face->segments()[loop[(k + loop.size() - 1) % loop.size()]];
  FacePlace c;
  c.turn = start.frame;
  c.centreQ30 = q30FromPoint(centre);
  Vec2 vertex = out.a;
  const bool pastOut = insideEdge(out, centre) < 0, pastIn = insideEdge(in, centre) < 0;
  if (!pastOut && !pastIn) return c;  // beyond an edge of another corner: not this vertex
  if (otherSide && !(pastOut && pastIn)) return c;
  bool byOut = pastOut;
  if (pastOut && pastIn) {
    const Vec2w v = rotateWide(start.rotation, e.velocityQ16), rel = c.centreQ30 - q30FromPoint(vertex);
    const i128 side = i128{v.x} * rel.y - i128{v.y} * rel.x;  // > 0: it passed the vertex on `out`'s side
    byOut = (side != 0 ? side > 0 : leavesByOut(*face, k, v)) != otherSide;
  }
  LineIndex edge = loop[byOut ? k : (k + loop.size() - 1) % loop.size()];
  // Each face turns the point by its corner's angle; the faces leave less than a full turn, so
  // within a round one holds it (64: a bound, not a count; faces of a mesh at a vertex may be many).
  for (int step = 0; step < 64; ++step) {
    const Line& line = face->lines()[edge];
    if (line.kind != LineKind::Warp) return c;
    const Warp& w = face->warps()[line.warp];
    const Segment seg = face->segments()[edge];
    c.centreQ30 = mapThroughWarp(w, seg, c.centreQ30);
    c.turn = static_cast<Angle>(c.turn + w.turn);
    vertex = vertex == seg.a ? w.targetSegment.a : w.targetSegment.b;
    face = &part(w.target);
    loop = face->faceLoop();
    if (loop.empty()) return c;
    if (insideFace(*face, pointFromQ30(c.centreQ30))) {
      c.found = true;
      c.part = w.target;
      return c;
    }
    // On over this face's other edge at the vertex.
    k = nearestCorner(*face, vertex);
    const LineIndex outEdge = loop[k], inEdge = loop[(k + loop.size() - 1) % loop.size()];
    if (face->segments()[outEdge].a != vertex) return c;
    edge = sameEdge(face->segments()[outEdge], w.targetSegment) ? inEdge : outEdge;
  }
  return c;
}

// Where the way on is walled (a wall on the face beyond stands where the path goes on), the
// vertex holds like a wall: copy `from` goes back onto its own face, `inset` units inside every
// edge it is past (alternate projections onto those edges, which meet in the face's corner).
WorldImpl::FacePlace WorldImpl::inwardOnFace(const Entity& e, size_t from, int64_t inset) const {
  const Instance& inst = e.instances[from];
  const MapPart& face = part(inst.part);
  Vec2 p = centreOf(inst);
  for (int round = 0; round < 8; ++round) {
    bool moved = false;
    for (const LineIndex line : face.faceLoop()) {
      const Segment s = face.segments()[line];
      const Vec2w d = s.b - s.a;
      const i128 by = inset * i128{lengthOf(d)} - insideEdge(s, p);  // times the length
      if (by <= 0) continue;
      const i128 len2 = i128{d.x} * d.x + i128{d.y} * d.y;
      p = {static_cast<int32_t>(p.x + roundDiv(-i128{d.y} * by, len2)),
           static_cast<int32_t>(p.y + roundDiv(i128{d.x} * by, len2))};
      moved = true;
    }
    if (!moved) break;
  }
  return {insideFace(face, p), inst.part, q30FromPoint(p), inst.frame};
}

// The same back along the way it came (against its velocity): where a pocket's walls at the
// vertex leave no room straight in, the way it came is free.
WorldImpl::FacePlace WorldImpl::backOnFace(const Entity& e, size_t from, int64_t inset) const {
  const Instance& inst = e.instances[from];
  const MapPart& face = part(inst.part);
  const Vec2 p = centreOf(inst);
  const Vec2w u = rotateWide(inst.rotation, e.velocityQ16);  // its way, Q16 a frame
  if (u == Vec2w{}) return {};
  i128 back = 0;  // how far back, in frames, Q48: enough for every edge it is past
  for (const LineIndex line : face.faceLoop()) {
    const Segment s = face.segments()[line];
    const Vec2w d = s.b - s.a;
    const i128 short_ = inset * i128{lengthOf(d)} - insideEdge(s, p);
    if (short_ <= 0) continue;
    const i128 rate = i128{d.y} * u.x - i128{d.x} * u.y;  // gained inside a frame back, Q16
    if (rate <= 0) return {};                             // going back does not bring it in
    back = std::max(back, (short_ << 48) / rate + 1);
  }
  const Vec2 q{static_cast<int32_t>(p.x - roundDiv(u.x * back, i128{1} << 48)),
               static_cast<int32_t>(p.y - roundDiv(u.y * back, i128{1} << 48))};
  return {insideFace(face, q), inst.part, q30FromPoint(q), inst.frame};
}

// Puts the entity at `c` as its one instance (turned with the new anchor's frame, velocity
// included, so it keeps its heading over the faces) if that place, or one within two units, is
// free and on the face; false, and nothing changed, if not. What it overlaps there
// is found as at insert: the lines it left end, the lines it overlaps begin, and the warp edges
// it straddles get their copies at once (without them it went over the next edge with none).
bool WorldImpl::placeOnFace(Move& move, const FacePlace& c) {
  Entity& e = move.entity;
  Instance inst;
  Vec2w originQ30;
  try {
    inst = makeInstance(e, c.part, {}, c.turn);  // its centre, turned as it will be there
    originQ30 = c.centreQ30 - q30FromPoint(inst.centre);
    inst = makeInstance(e, c.part, pointFromQ30(originQ30), c.turn);
  } catch (const Error&) {
    return false;  // out of range, or the shape cannot take that rotation
  }
  const Vec2w perFrame = rotateWide(rotationOf(c.turn), Vec2w{e.velocityQ16.x >> 16, e.velocityQ16.y >> 16});
  if (!placeNear(e, inst, originQ30, nullptr, perFrame) || !insideFace(part(c.part), centreOf(inst))) return false;
  inst.idealQ30 = originQ30;
  // The copy already on that face (one a part) goes there: the lines it overlaps and still
  // overlaps stay overlapped, with no end and begin again. It becomes the anchor (turned with it),
  // and the others go.
  size_t k = 0;
  while (k < e.instances.size() && e.instances[k].part != c.part) ++k;
  if (k == e.instances.size()) {
    e.instances.push_back(std::move(inst));
  } else {
    inst.overlapping = std::move(e.instances[k].overlapping);
    if (!inst.overlapping.empty()) overlappingSlots.push_back(e.id.index);
    e.instances[k] = std::move(inst);
  }
  rebase(move, k);
  while (e.instances.size() > 1) eraseInstance(move, e.instances.size() - 1);
  updatePierceState(e, {});
  createOverlappedWarps(e);
  return true;
}

// The anchor's velocity without what takes it out across the face's edges its centre is within
// 4 units of, or beyond (it was just held there, as by a wall).
void WorldImpl::stopAtFaceEdges(Entity& e) {
  const Instance& anchor = e.instances[0];
  const MapPart& face = part(anchor.part);
  for (const LineIndex line : face.faceLoop()) {
    const Segment s = face.segments()[line];
    const Vec2w d = s.b - s.a, v = e.velocityQ16;
    if (insideEdge(s, centreOf(anchor)) > 4 * i128{lengthOf(d)}) continue;
    const i128 out = i128{v.x} * d.y - i128{v.y} * d.x;  // along the outward normal, times the length
    if (out <= 0) continue;
    const i128 len2 = i128{d.x} * d.x + i128{d.y} * d.y;
    e.velocityQ16 = {v.x - static_cast<int64_t>(roundDiv(out * d.y, len2)),
                     v.y + static_cast<int64_t>(roundDiv(out * d.x, len2))};
  }
}

// The way back onto a face from past one of its corners: beside the edge the velocity crosses
// most (`byOut`: the edge that starts at the corner), `away` along that edge from the vertex,
// `inward` into the face; `meet`, how far along the velocity meets the edge before it passes the
// vertex; `clear`, how far the next frame's motion stays clear of the other edges at the vertex.
struct WorldImpl::CornerReturn {
  size_t corner = 0;
  Vec2 vertex;
  bool byOut = false;
  Vec2w away, inward;
  int64_t length = 0;  // of the chosen edge
  int64_t meet = 0, clear = 0;
};

WorldImpl::CornerReturn WorldImpl::cornerReturn(const Entity& e) const {
  const MapPart& face = part(e.instances[0].part);
  const Vec2 at = centreOf(e.instances[0]);
  const auto loop = face.faceLoop();
  CornerReturn r;
  // The corner nearest the centre, and its two edges: `in` ends there, `out` starts there.
  r.corner = nearestCorner(face, at);
  const Segment out = face.segments()[loop[r.corner]];
  const Segment in = face.segments()[loop[(r.corner + loop.size() - 1) % loop.size()]];
  r.vertex = out.a;
  // The edge the velocity leaves by most.
  const Vec2w outDir = out.b - out.a, inDir = in.b - in.a;
  const Vec2w v = e.velocityQ16;
  const int64_t outLength = lengthOf(outDir), inLength = lengthOf(inDir);
  r.byOut = leavesByOut(face, r.corner, v);
  // Along the chosen edge away from the vertex, and inward (left of the edge).
  r.away = r.byOut ? outDir : Vec2w{-inDir.x, -inDir.y};
  r.inward = r.byOut ? Vec2w{-outDir.y, outDir.x} : Vec2w{-inDir.y, inDir.x};
  r.length = r.byOut ? outLength : inLength;
  if (r.length == 0) return r;
  // Two units in; far enough along that the velocity meets the edge before passing the vertex:
  // along >= 4 + 2 * (velocity toward the vertex) / (velocity out across the edge).
  const i128 towardVertex = -(i128{v.x} * r.away.x + i128{v.y} * r.away.y);
  const i128 across = -(i128{v.x} * r.inward.x + i128{v.y} * r.inward.y);
  r.meet = 4;
  if (towardVertex > 0 && across > 0)
    r.meet += static_cast<int64_t>(std::min<i128>(towardVertex * 2 / across + 1, r.length / 4));
  // And far enough that the next frame's motion (at most this speed and its gravity) ends within
  // this face or the neighbour across the edge, clear of their other edges at the vertex: a body
  // put back closer goes through the same vertex again and is put back at the same place every
  // frame, frozen while its velocity grows.
  const Vec2w g = face.gravity();
  const int64_t reach = static_cast<int64_t>((isqrt(static_cast<u128>(i128{v.x} * v.x + i128{v.y} * v.y)) +
                                              isqrt(static_cast<u128>(i128{g.x} * g.x + i128{g.y} * g.y))) /
                                             kQ16) +
                        8;
  r.clear = alongForClearance(face, r.corner, reach);
  const Line& crossed = face.lines()[loop[r.byOut ? r.corner : (r.corner + loop.size() - 1) % loop.size()]];
  if (crossed.kind == LineKind::Warp) {
    const Warp& w = face.warps()[crossed.warp];
    const MapPart& neighbour = part(w.target);
    if (!neighbour.faceLoop().empty()) {
      const Vec2 image = r.byOut ? w.targetSegment.a : w.targetSegment.b;
      r.clear = std::max(r.clear, alongForClearance(neighbour, nearestCorner(neighbour, image), reach));
    }
  }
  return r;
}

// Puts the anchor by the corner as `r` says: as far along as `clear`, or where a wall stands
// there nearer (half, a quarter of the way, then as near as the edge is met), on the face and free.
// Returns how far along it went, or -1 (left where it was) when no place is free.
int64_t WorldImpl::placeByCorner(Entity& e, const CornerReturn& r) {
  const MapPart& face = part(e.instances[0].part);
  Instance& anchor = e.instances[0];
  const Vec2 was = anchor.position;
  std::vector<Vec2>& verts = scratch.probe;
  const int64_t far = std::max(r.meet, r.clear);
  const std::array<int64_t, 4> candidates{far, std::max(r.meet, far / 2), std::max(r.meet, far / 4), r.meet};
  for (size_t k = 0; k < candidates.size(); ++k) {
    if (k > 0 && candidates[k] == candidates[k - 1]) continue;
    const int64_t along = std::min<int64_t>(candidates[k], r.length / 2);
    // The centre goes there (the origin may lie outside the shape).
    anchor.position = {r.vertex.x - anchor.centre.x +
                           static_cast<int32_t>(roundDiv(i128{r.away.x} * along + i128{r.inward.x} * 2, r.length)),
                       r.vertex.y - anchor.centre.y +
                           static_cast<int32_t>(roundDiv(i128{r.away.y} * along + i128{r.inward.y} * 2, r.length))};
    worldVertices(anchor, verts);
    coverMotion(anchor, {});  // the lines around the new place, for the walls there and the warps to cross
    if (insideFace(face, centreOf(anchor)) && isFree(e, anchor, verts)) return along;
  }
  anchor.position = was;  // a wall right at the corner: leave it (it cannot go far that way)
  coverMotion(anchor, {});
  return -1;
}

// The anchor if its centre is on its face (or not on a face at all), else the copy whose centre
// is least off its face (the first such); with `inPart`, the copy in that part if there is one.
size_t WorldImpl::startCopy(const Entity& e, std::optional<MapPartId> inPart) const {
  if (e.instances.size() == 1) return 0;  // the anchor, whichever way it is asked (most bodies)
  if (!inPart) {  // the common case first: the anchor's centre on its face (0 off: none is less)
    const MapPart& face = part(e.instances[0].part);
    const Vec2 c = centreOf(e.instances[0]);
    const auto loop = face.faceLoop();
    if (std::all_of(loop.begin(), loop.end(), [&](LineIndex l) { return insideEdge(face.segments()[l], c) >= 0; }))
      return 0;
  }
  size_t best = 0;
  int64_t leastOff = INT64_MAX;
  for (size_t i = 0; i < e.instances.size(); ++i) {
    if (inPart && e.instances[i].part == *inPart) return i;
    const MapPart& p = part(e.instances[i].part);
    const int64_t off = p.faceLoop().empty() ? INT64_MAX : unitsOutside(p, centreOf(e.instances[i]));
    if (off < leastOff) leastOff = off, best = i;
  }
  return best;
}

void WorldImpl::keepOnFace(Move& move) {
  Entity& e = move.entity;
  if (e.instances.empty()) return;
  const bool onAFace = std::any_of(e.instances.begin(), e.instances.end(), [&](const Instance& inst) {
    const MapPart& p = part(inst.part);
    return p.faceLoop().empty() || insideFace(p, centreOf(inst));
  });
  if (onAFace) {  // the warp links decide
    if (e.instances.size() > 1) eraseUnlinkedCopies(move);
    return;
  }
  // Every copy is past its face's corner. The path goes on from the copy that was on its face (or
  // least off it) when the frame's slide began, where the body was: the others are where it would
  // be had it gone round the vertex another way (near a vertex, copies linked round either way
  // disagree by the angle the faces leave). If that copy is gone, from the one least off now.
  const size_t from = startCopy(e, move.startFace);
  for (const bool otherSide : {false, true})
    if (const FacePlace c = continuePastVertex(e, from, otherSide); c.found && placeOnFace(move, c)) {
      ++report.cornerReturns;
      return;
    }
  // Walled: held as by a wall, straight in or back the way it came, 2 units in, on the edge, or
  // within the rounding allowed beyond it, whichever is free first.
  for (int k = 0; k < 6; ++k) {
    const int64_t inset = std::array<int64_t, 3>{2, 0, -3}[k % 3];
    const FacePlace c = k < 3 ? inwardOnFace(e, from, inset) : backOnFace(e, from, inset);
    if (c.found && placeOnFace(move, c)) {
      stopAtFaceEdges(e);
      ++report.vertexHolds;
      return;
    }
  }
  // No room near where it went out: the last resort (the rule before paths went on) puts it back on
  // the anchor's face beside the corner, as far along the edge its velocity leaves by as the walls
  // allow, a jump, but on the faces: left where it was, off them, a body with a pocket's walls on
  // every side drifted on, thousands of units off the solid.
  if (e.instances.size() > 1) eraseUnlinkedCopies(move);
  const CornerReturn r = cornerReturn(e);
  if (r.length == 0 || placeByCorner(e, r) < 0) {
    stopAtFaceEdges(e);  // no room at all: it stays, held as by a wall
    return;
  }
  while (e.instances.size() > 1) eraseInstance(move, e.instances.size() - 1);
  e.instances[0].idealQ30 = q30FromPoint(e.instances[0].position);
  stopAtFaceEdges(e);
  updatePierceState(e, {});
  createOverlappedWarps(e);
  ++report.vertexHolds;
}

}  // namespace platon::physics

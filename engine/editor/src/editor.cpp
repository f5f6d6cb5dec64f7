#include "platon/editor/editor.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "platon/core/display.h"

namespace platon::editor {
namespace {

constexpr double kPickPixels = 10;  // a segment or an end this near the pointer is under it
constexpr double kMarkPixels = 24;  // the start's or the goal's marker
constexpr float kClickPixels = 4;   // a press and release nearer than this is a click
constexpr int kMinGrid = 8, kMaxGrid = 1024;
constexpr float kPaletteTop = 150;  // below the heads-up lines

const core::Color kCursor{90, 220, 255, 255}, kSelected{255, 214, 60, 255}, kError{255, 60, 60, 255},
    kWarning{255, 160, 40, 255}, kStart{80, 230, 120, 255}, kGoal{255, 235, 120, 255}, kPanel{20, 24, 32, 245},
    kText{235, 235, 235, 255}, kDim{150, 155, 165, 255};

physics::Vec2 whole(const FacePoint& p) {
  return {static_cast<int32_t>(std::llround(p.x)), static_cast<int32_t>(std::llround(p.y))};
}

double pointSegmentPixels(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

core::Color colorOf(stage::TagStyle style) { return {style.r, style.g, style.b, 255}; }

// The level as the game would build it: the segments inside their faces (one that is not is an
// error the check draws), the goal's square moved onto its face if it hangs over an edge.
stage::Level editorBuiltLevel(const stage::Level& level, const stage::Stage& solid) {
  stage::Level built = level;
  for (size_t f = 0; f < built.faces.size(); ++f)
    std::erase_if(built.faces[f].lines, [&](const stage::LevelLine& l) {
      return !editor::insideExactly(solid.faces[f].corners, l.a) || !editor::insideExactly(solid.faces[f].corners, l.b);
    });
  const auto& goalCorners = solid.faces[static_cast<size_t>(built.goal.face)].corners;
  const int32_t h = stage::goalHalfSide(built);
  for (int step = 0; step < 20; ++step) {
    const physics::Vec2 g = built.goal.position;
    if (editor::insideExactly(goalCorners, {g.x - h, g.y - h}) &&
        editor::insideExactly(goalCorners, {g.x + h, g.y - h}) &&
        editor::insideExactly(goalCorners, {g.x + h, g.y + h}) &&
        editor::insideExactly(goalCorners, {g.x - h, g.y + h}))
      break;
    int64_t cx = 0, cy = 0;
    for (const physics::Vec2 c : goalCorners) cx += c.x, cy += c.y;
    const auto n = static_cast<int64_t>(goalCorners.size());
    built.goal.position = {static_cast<int32_t>((g.x + cx / n) / 2), static_cast<int32_t>((g.y + cy / n) / 2)};
  }
  return built;
}

// A finding where its line is: the start's, the goal's, a face's or a segment's (the last of them
// that has the line wins); on the level as a whole otherwise.
Marker findingMarker(const stage::Finding& finding, bool error, const stage::Level& level) {
  Marker m{Marker::On::Level, {}, -1, error, finding.message};
  const int line = finding.where.line;
  if (line == level.start.sourceLine)
    m.on = Marker::On::Start, m.face = level.start.face;
  else if (line == level.goal.sourceLine)
    m.on = Marker::On::Goal, m.face = level.goal.face;
  for (size_t f = 0; f < level.faces.size() && line > 0; ++f) {
    if (level.faces[f].sourceLine == line) m.on = Marker::On::Face, m.face = static_cast<int>(f);
    for (size_t i = 0; i < level.faces[f].lines.size(); ++i)
      if (level.faces[f].lines[i].sourceLine == line)
        m.on = Marker::On::Segment, m.face = static_cast<int>(f),
        m.segment = {static_cast<int>(f), static_cast<int>(i)};
  }
  return m;
}

// "faces 2, 3, 4 have no lines" is one finding at the first of them: each is outlined.
void markFacesWithoutLines(const stage::Level& level, const stage::CheckReport& report, std::vector<Marker>& markers) {
  for (const stage::Finding& w : report.warnings) {
    if (w.message.find("no lines") == std::string::npos) continue;
    for (size_t f = 0; f < level.faces.size(); ++f) {
      const int face = static_cast<int>(f);
      if (!level.faces[f].lines.empty() || face == level.start.face || face == level.goal.face) continue;
      if (std::none_of(markers.begin(), markers.end(),
                       [&](const Marker& m) { return m.on == Marker::On::Face && m.face == face; }))
        markers.push_back({Marker::On::Face, {}, face, false, w.message});
    }
  }
}

// The check stops at the first segment off its face (the level would not load); every such
// segment (a file edited by hand) is marked, so all of them show at once.
void markSegmentsOffFaces(const stage::Level& level, const stage::Stage& solid, std::vector<Marker>& markers) {
  for (size_t f = 0; f < level.faces.size(); ++f)
    for (size_t i = 0; i < level.faces[f].lines.size(); ++i) {
      const stage::LevelLine& l = level.faces[f].lines[i];
      if (editor::insideExactly(solid.faces[f].corners, l.a) && editor::insideExactly(solid.faces[f].corners, l.b))
        continue;
      const SegmentRef ref{static_cast<int>(f), static_cast<int>(i)};
      if (std::none_of(markers.begin(), markers.end(), [&](const Marker& m) { return m.segment == ref; }))
        markers.push_back(
            {Marker::On::Segment, ref, static_cast<int>(f), true, "the segment leaves face " + std::to_string(f)});
    }
}

}  // namespace

Editor::Editor(LevelDocument document, stage::Stage solid, int64_t defaultGravityQ16)
    : document_(std::move(document)), solid_(std::move(solid)), gravity_(defaultGravityQ16) {
  const stage::Level& level = document_.level();
  if (level.faces.size() != solid_.faceCount())
    throw stage::StageError({level.file, level.endLine, 1},
                            "the file describes " + std::to_string(level.faces.size()) + " faces; its solid has " +
                                std::to_string(solid_.faceCount()) + ": fix that in the text first");
  for (const stage::LevelPoint* p : {&level.start, &level.goal})
    if (p->face < 0 || p->face >= static_cast<int>(solid_.faceCount()))
      throw stage::StageError({level.file, p->sourceLine, p->sourceColumn},
                              "face " + std::to_string(p->face) + " does not exist: fix that in the text first");
  for (const stage::TagKind& kind : document_.tags()->kinds())
    palette_.push_back({kind.word, kind.number, kind.count > 0});
  rebuild();
  faceHeadOn(level.start.face);
}

std::optional<FacePoint> Editor::pointAt(float x, float y) const { return pickFace(*view_, rayThrough(lens_, x, y)); }

void Editor::faceHeadOn(int face) {
  const stage::StageFace& f = solid_.faces[static_cast<size_t>(face)];
  const FacePoint centre = faceCentre(solid_, face);
  const double cx = centre.x, cy = centre.y;
  double reach = 0;
  for (const physics::Vec2 c : f.corners) reach = std::max(reach, std::hypot(c.x - cx, c.y - cy));
  lookAt(face, cx, cy);
  // Far enough that the whole face shows, its farthest corner inside the window's height (the
  // narrower way) with a margin for the heads-up lines.
  const double plane = (f.toWorld(cx, cy) - solid_.centre).dot(f.normal);
  const double fit = plane + 1.25 * reach / std::tan(lens_.verticalFov / 2);
  lens_.pose.distance = wantedPose_.distance = std::max(lens_.pose.distance, fit);
}

uint32_t Editor::currentTag() const {
  const PaletteEntry& e = palette_.at(paletteIndex_);
  return e.numbered ? e.number + number_ : e.number;
}

stage::LevelPoint Editor::playStart() const {
  if (cursor_) return {cursor_->point.face, whole(cursor_->point)};
  return document_.level().start;
}

void Editor::lookAt(int face, double x, double y) {
  const physics::Vec2w gravity = world_->mapPart(solid_.part(static_cast<size_t>(face))).gravity();
  const camera::CameraTarget target = core::cameraTarget(*view_, solid_.part(static_cast<size_t>(face)),
                                                         static_cast<float>(x), static_cast<float>(y), gravity);
  lens_.pose = wantedPose_ = camera::Camera::wanted(target);
}

void Editor::rebuild() {
  const auto began = std::chrono::steady_clock::now();
  const stage::Level& level = document_.level();
  stage::Level built = editorBuiltLevel(level, solid_);
  auto world = std::make_unique<physics::World>();
  stage::Stage solid = solid_;
  stage::buildLevel(built, solid, *world, 0, gravity_);
  for (size_t f = 0; f < solid.faceCount(); ++f) world->mapPart(solid.part(f)).initialize();
  view_ = core::stageView(solid, *world, *document_.tags());
  world_ = std::move(world);
  buildMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count();

  try {
    stage::checkLevelOnStage(level, solid_);
    loads_ = true;
  } catch (const stage::StageError&) {
    loads_ = false;
  }
  report_ = stage::checkLevel(level, solid_);
  markers_.clear();
  for (const stage::Finding& f : report_.errors) markers_.push_back(findingMarker(f, true, level));
  for (const stage::Finding& f : report_.warnings) markers_.push_back(findingMarker(f, false, level));
  markFacesWithoutLines(level, report_, markers_);
  markSegmentsOffFaces(level, solid_, markers_);
  std::erase_if(selection_, [&](SegmentRef s) {
    return s.face < 0 || s.face >= static_cast<int>(level.faces.size()) || s.index < 0 ||
           s.index >= static_cast<int>(level.faces[static_cast<size_t>(s.face)].lines.size());
  });
}

bool Editor::apply(const std::string& name, const std::function<void(stage::Level&)>& change) {
  try {
    if (!document_.edit(name, change)) return false;
  } catch (const stage::StageError& e) {
    say(std::string("not done: ") + e.what());
    return false;
  }
  rebuild();
  say(name);
  return true;
}

Editor::Request Editor::handle(const core::WindowInput& input) {
  if (input.width > 0 && input.height > 0) lens_.width = input.width, lens_.height = input.height;
  Request request = Request::None;
  for (const core::MouseEvent& event : input.mouse) {
    if (event.kind != core::MouseEvent::Kind::Wheel) onMove(event.x, event.y, input.shift, input.alt);
    onMouse(event, input.shift, input.alt);
  }
  onMove(input.mouseX, input.mouseY, input.shift, input.alt);
  std::vector<core::KeyPress> keys = input.keys;
  if (input.closed) keys.push_back({"Escape"});  // the window's close button: as Esc, asking first
  for (const core::KeyPress& key : keys) {
    if (key.name == "Escape") {
      if (drag_.what == Drag::What::Draw) {
        drag_ = {};
        say("drawing cancelled");
      } else if (document_.modified() && !quitAsked_) {
        quitAsked_ = true;
        say("unsaved edits: Esc (or closing the window) again quits without saving them, Ctrl+S saves");
      } else {
        request = Request::Quit;
      }
      continue;
    }
    quitAsked_ = false;
    if ((key.name == "Return" || key.name == "Keypad Enter") && !key.ctrl) {
      if (loads_)
        request = Request::Play;
      else
        say("the level does not load yet: " + (report_.errors.empty() ? "" : report_.errors[0].message));
      continue;
    }
    onKey(key);
  }
  return request;
}

void Editor::undoOrRedo(bool redo) {
  if (!(redo ? document_.redo() : document_.undo())) return say(redo ? "nothing to redo" : "nothing to undo");
  selection_.clear();  // the indices it held may name other segments now
  rebuild();
  say(redo ? "redone: " + document_.undoName() : "undone: " + document_.redoName());
}

void Editor::saveDocument(bool anyway) {
  if (!loads_ && !anyway) {
    say("not saved: the level would not load (Ctrl+Shift+S saves it anyway): " +
        (report_.errors.empty() ? std::string("see the check") : report_.errors[0].message));
    return;
  }
  try {
    document_.save();
    say("saved " + document_.path() + (report_.errors.empty() ? "" : " (with errors: see the check)"));
  } catch (const std::exception& e) {
    say(std::string("not saved: ") + e.what());
  }
}

void Editor::selectFace() {
  selection_.clear();
  const int f = cursor_->point.face;
  for (size_t i = 0; i < document_.level().faces[static_cast<size_t>(f)].lines.size(); ++i)
    selection_.push_back({f, static_cast<int>(i)});
  tool_ = Tool::Select;
  say("selected the " + std::to_string(selection_.size()) + " segments of face " + std::to_string(f));
}

void Editor::onCtrlKey(const core::KeyPress& key) {
  const std::string& k = key.name;
  if (k == "Z" || k == "Y") undoOrRedo(k == "Y" || key.shift);
  if (k == "S") saveDocument(key.shift);
  if (k == "C") copySelection();
  if (k == "V") paste();
  if (k == "A" && cursor_) selectFace();
}

void Editor::moveMarkToCursor(bool start) {
  const stage::LevelPoint at{cursor_->point.face, whole(cursor_->point)};
  apply(start ? "move the start" : "move the goal", [&](stage::Level& l) {
    stage::LevelPoint& p = start ? l.start : l.goal;
    p.face = at.face, p.position = at.position;
  });
}

void Editor::onKey(const core::KeyPress& key) {
  const std::string& k = key.name;
  if (key.ctrl) return onCtrlKey(key);
  if (k == "D") tool_ = Tool::Draw, drag_ = {};
  if (k == "S") tool_ = Tool::Select, drag_ = {};
  if (k == "T" || k == "Tab") {
    const size_t n = palette_.size();
    paletteIndex_ = key.shift ? (paletteIndex_ + n - 1) % n : (paletteIndex_ + 1) % n;
    applyTag();
  }
  if (k == "[" || k == "]") {
    const stage::TagKind* kind = document_.tags()->find(palette_[paletteIndex_].word);
    const uint32_t most = kind && kind->count ? kind->count : 1;
    number_ = k == "]" ? std::min(most, number_ + 1) : std::max(1u, number_ - 1);
    applyTag();
  }
  if (k == "O") toggleOneWay();
  if ((k == "P" || k == "G") && cursor_) moveMarkToCursor(k == "P");
  if (k == "V") cycleGravity();
  if (k == "F" && cursor_) faceHeadOn(cursor_->point.face);
  if (k == "Home") {
    const stage::LevelPoint& s = document_.level().start;
    lookAt(s.face, s.position.x, s.position.y);
  }
  if (k == "," || k == ".") {
    snap_.grid = k == "." ? std::min(kMaxGrid, std::max(kMinGrid, snap_.grid * 2)) : std::max(kMinGrid, snap_.grid / 2);
    say("grid " + std::to_string(snap_.grid) + " units");
  }
  if (k == "Delete" || k == "Backspace") deleteSelection();
}

void Editor::onMouse(const core::MouseEvent& event, bool shift, bool alt) {
  const float x = event.x, y = event.y;
  if (event.kind == core::MouseEvent::Kind::Wheel) return zoom(event.wheel);
  if (event.button == 2 || event.button == 3) {
    if (event.kind == core::MouseEvent::Kind::Down && drag_.what == Drag::What::None)
      drag_ = {Drag::What::Orbit, {}, {}, false, x, y};
    else if (event.kind == core::MouseEvent::Kind::Up && drag_.what == Drag::What::Orbit)
      drag_ = {};
    return;
  }
  if (event.button != 1) return;
  if (event.kind == core::MouseEvent::Kind::Up) return endDrag(x, y);
  if (clickPalette(x, y)) return;
  if (tool_ == Tool::Draw) {
    if (drag_.what == Drag::What::Draw && drag_.chain) return;                 // the release ends the segment
    if (cursor_) drag_ = {Drag::What::Draw, cursor_->point, {}, false, x, y};  // onMove placed it
    return;
  }
  pressToSelect(x, y, shift, alt);
}

// A press of the select tool: on the start or the goal it takes that mark; on a segment it selects
// it (Shift adds or takes away) and takes it, or its end; elsewhere it clears the selection.
void Editor::pressToSelect(float x, float y, bool shift, bool alt) {
  const stage::Level& level = document_.level();
  const std::optional<Snapped> at = cursor_;
  if (nearPoint(x, y, level.start, kMarkPixels)) {
    drag_ = {
        Drag::What::MoveStart, {level.start.face, double(level.start.position.x), double(level.start.position.y)}, {}};
  } else if (nearPoint(x, y, level.goal, kMarkPixels)) {
    drag_ = {Drag::What::MoveGoal, {level.goal.face, double(level.goal.position.x), double(level.goal.position.y)}, {}};
  } else {
    bool nearEnd = false, endB = false;
    const auto hit = segmentNear(x, y, nearEnd, endB);
    if (!hit) {
      if (!shift) selection_.clear();
      return;
    }
    const auto found = std::find(selection_.begin(), selection_.end(), *hit);
    if (shift && found != selection_.end()) {
      selection_.erase(found);
      return;
    }
    if (found == selection_.end()) {
      if (!shift) selection_.clear();
      selection_.push_back(*hit);
    }
    const stage::LevelLine& l = level.faces[static_cast<size_t>(hit->face)].lines[static_cast<size_t>(hit->index)];
    if (nearEnd) {
      const physics::Vec2 end = endB ? l.b : l.a;
      drag_ = {Drag::What::MoveEnd, {hit->face, double(end.x), double(end.y)}, *hit, endB};
      drag_.alone = alt;
    } else {
      const FacePoint from =
          at && at->point.face == hit->face ? at->point : FacePoint{hit->face, double(l.a.x), double(l.a.y)};
      drag_ = {Drag::What::MoveSegments, from, *hit};
    }
  }
  drag_.mouseX = x, drag_.mouseY = y;
}

void Editor::onMove(float x, float y, bool shift, bool alt) {
  if (drag_.what == Drag::What::Orbit) {
    orbit(x - mouseX_, y - mouseY_);
  }
  mouseX_ = x, mouseY_ = y;
  const bool onDragFace = drag_.what != Drag::What::None && drag_.what != Drag::What::Orbit;
  // Moving the start or the goal may take it to another face; anything else stays on its face.
  const bool anyFace = drag_.what == Drag::What::MoveStart || drag_.what == Drag::What::MoveGoal;
  cursor_ = snapAt(x, y, onDragFace && !anyFace ? drag_.from.face : -1, shift, alt);
  dragTo_ = onDragFace && cursor_ ? std::optional(cursor_->point) : std::nullopt;
}

void Editor::endDraw(const Drag& drag, physics::Vec2 a, physics::Vec2 b, FacePoint to, float x, float y) {
  if (a == b) return;
  const stage::LevelLine line{a, b, oneWay_, currentTag()};
  const int face = drag.from.face;
  if (apply("draw a segment", [&](stage::Level& l) { l.faces[static_cast<size_t>(face)].lines.push_back(line); })) {
    selection_ = {{face, static_cast<int>(document_.level().faces[static_cast<size_t>(face)].lines.size()) - 1}};
    if (drag.chain) drag_ = {Drag::What::Draw, to, {}, false, x, y, true};  // go on from its end
  }
}

// Every end at that point on the face moves with it (a joint stays a joint); Alt moves the dragged
// end alone. An end that would meet its segment's other end stays.
void Editor::endMoveEnd(const Drag& drag, physics::Vec2 a, physics::Vec2 b) {
  apply("move an end point", [&](stage::Level& l) {
    auto& lines = l.faces[static_cast<size_t>(drag.segment.face)].lines;
    for (size_t i = 0; i < lines.size(); ++i) {
      stage::LevelLine& line = lines[i];
      const bool dragged = static_cast<int>(i) == drag.segment.index;
      if (!dragged && drag.alone) continue;
      const bool moveA = dragged ? !drag.endB : line.a == a, moveB = dragged ? drag.endB : line.b == a;
      if (moveA && line.b != b) line.a = b;
      if (moveB && line.a != b) line.b = b;
    }
  });
}

void Editor::endMoveSegments(const Drag& drag, physics::Vec2 a, physics::Vec2 b) {
  const stage::Level& level = document_.level();
  const physics::Vec2 d{b.x - a.x, b.y - a.y};
  const auto& corners = solid_.faces[static_cast<size_t>(drag.from.face)].corners;
  for (const SegmentRef s : selection_) {
    if (s.face != drag.from.face) continue;
    const stage::LevelLine& l = level.faces[static_cast<size_t>(s.face)].lines[static_cast<size_t>(s.index)];
    if (!insideExactly(corners, {l.a.x + d.x, l.a.y + d.y}) || !insideExactly(corners, {l.b.x + d.x, l.b.y + d.y}))
      return say("not moved: it would take a segment off its face");
  }
  apply(selection_.size() == 1 ? "move a segment" : "move " + std::to_string(selection_.size()) + " segments",
        [&](stage::Level& l) {
          for (const SegmentRef s : selection_) {
            if (s.face != drag.from.face) continue;
            stage::LevelLine& line = l.faces[static_cast<size_t>(s.face)].lines[static_cast<size_t>(s.index)];
            line.a = {line.a.x + d.x, line.a.y + d.y}, line.b = {line.b.x + d.x, line.b.y + d.y};
          }
        });
}

void Editor::endDrag(float x, float y) {
  const Drag drag = drag_;
  const bool moved = std::hypot(x - drag.mouseX, y - drag.mouseY) >= kClickPixels;
  if (drag.what == Drag::What::Draw && !moved && !drag.chain) {
    drag_.chain = true;  // a click: the next click ends the segment
    return;
  }
  drag_ = {};
  if (drag.what == Drag::What::None || drag.what == Drag::What::Orbit || !dragTo_) return;
  const FacePoint to = *dragTo_;
  const physics::Vec2 a = whole(drag.from), b = whole(to);
  if (drag.what == Drag::What::Draw) return endDraw(drag, a, b, to, x, y);
  if (!moved) return;  // a click on a segment or a mark selects it and moves nothing
  if (drag.what == Drag::What::MoveEnd) return endMoveEnd(drag, a, b);
  if (drag.what == Drag::What::MoveSegments) return endMoveSegments(drag, a, b);
  const bool start = drag.what == Drag::What::MoveStart;
  apply(start ? "move the start" : "move the goal", [&](stage::Level& l) {
    stage::LevelPoint& p = start ? l.start : l.goal;
    p.face = to.face, p.position = b;
  });
}

std::optional<Snapped> Editor::snapAt(float x, float y, int onFace, bool shift, bool alt) const {
  const Ray ray = rayThrough(lens_, x, y);
  const auto raw = onFace < 0 ? pickFace(*view_, ray) : onFacePlane(*view_, onFace, ray);
  if (!raw) return std::nullopt;
  SnapSettings settings = snap_;
  settings.enabled = !alt;
  settings.angles = shift;
  std::optional<FacePoint> from;
  if (drag_.what == Drag::What::Draw) from = drag_.from;
  return snap(*raw, document_.level(), solid_, *view_, lens_, settings, from);
}

bool Editor::nearPoint(float x, float y, const stage::LevelPoint& p, double pixels) const {
  const auto at = toScreen(lens_, *view_, {p.face, double(p.position.x), double(p.position.y)});
  const Eigen::Vector3d n(view_->faces[static_cast<size_t>(p.face)].normal.x,
                          view_->faces[static_cast<size_t>(p.face)].normal.y,
                          view_->faces[static_cast<size_t>(p.face)].normal.z);
  const bool front =
      n.dot(toSpace(*view_, {p.face, double(p.position.x), double(p.position.y)}) - lens_.pose.eye()) < 0;
  return at && front && (*at - Eigen::Vector2d(x, y)).norm() <= pixels;
}

std::optional<SegmentRef> Editor::segmentNear(float x, float y, bool& nearEnd, bool& endB) const {
  const Eigen::Vector2d mouse(x, y);
  std::optional<SegmentRef> best;
  double bestEnd = kPickPixels, bestLine = kPickPixels;
  const stage::Level& level = document_.level();
  for (size_t f = 0; f < level.faces.size(); ++f) {
    const core::ViewFace& vf = view_->faces[f];
    const Eigen::Vector3d n(vf.normal.x, vf.normal.y, vf.normal.z), o(vf.origin.x, vf.origin.y, vf.origin.z);
    if (n.dot(o - lens_.pose.eye()) >= 0) continue;  // the face turns away
    const int face = static_cast<int>(f);
    for (size_t i = 0; i < level.faces[f].lines.size(); ++i) {
      const stage::LevelLine& l = level.faces[f].lines[i];
      const auto a = toScreen(lens_, *view_, {face, double(l.a.x), double(l.a.y)});
      const auto b = toScreen(lens_, *view_, {face, double(l.b.x), double(l.b.y)});
      if (!a || !b) continue;
      const SegmentRef ref{face, static_cast<int>(i)};
      for (const auto& [end, isB] : {std::pair{*a, false}, std::pair{*b, true}})
        if (const double d = (end - mouse).norm(); d <= bestEnd) bestEnd = d, best = ref, nearEnd = true, endB = isB;
      if (bestEnd < kPickPixels) continue;
      if (const double d = pointSegmentPixels(mouse, *a, *b); d <= bestLine && !nearEnd) bestLine = d, best = ref;
    }
  }
  return best;
}

void Editor::deleteSelection() {
  if (selection_.empty()) return say("nothing selected (S, then click a segment)");
  std::vector<SegmentRef> gone = selection_;
  apply(gone.size() == 1 ? "delete a segment" : "delete " + std::to_string(gone.size()) + " segments",
        [&](stage::Level& l) {
          std::sort(gone.begin(), gone.end(),
                    [](SegmentRef p, SegmentRef q) { return p.face != q.face ? p.face < q.face : p.index > q.index; });
          for (const SegmentRef s : gone) {
            auto& lines = l.faces[static_cast<size_t>(s.face)].lines;
            lines.erase(lines.begin() + s.index);
          }
        });
  selection_.clear();
}

void Editor::copySelection() {
  if (selection_.empty()) return say("nothing selected to copy");
  clipboard_.clear();
  const stage::Level& level = document_.level();
  physics::Vec2 origin{};
  for (const SegmentRef s : selection_) {
    stage::LevelLine l = level.faces[static_cast<size_t>(s.face)].lines[static_cast<size_t>(s.index)];
    if (clipboard_.empty()) origin = l.a;
    l.a = {l.a.x - origin.x, l.a.y - origin.y}, l.b = {l.b.x - origin.x, l.b.y - origin.y};
    l.sourceLine = 0;
    clipboard_.push_back(l);
  }
  say("copied " + std::to_string(clipboard_.size()) + " segment" + (clipboard_.size() == 1 ? "" : "s") +
      " (Ctrl+V pastes them at the cursor, on any face)");
}

void Editor::paste() {
  if (clipboard_.empty()) return say("nothing copied yet (Ctrl+C copies the selection)");
  if (!cursor_) return say("point at a face to paste there");
  const int face = cursor_->point.face;
  const physics::Vec2 at = whole(cursor_->point);
  const auto& corners = solid_.faces[static_cast<size_t>(face)].corners;
  std::vector<stage::LevelLine> lines;
  for (stage::LevelLine l : clipboard_) {
    l.a = {l.a.x + at.x, l.a.y + at.y}, l.b = {l.b.x + at.x, l.b.y + at.y};
    if (!insideExactly(corners, l.a) || !insideExactly(corners, l.b))
      return say("not pasted: the copy would reach off face " + std::to_string(face) + " here");
    lines.push_back(l);
  }
  const size_t first = document_.level().faces[static_cast<size_t>(face)].lines.size();
  if (apply("paste " + std::to_string(lines.size()) + " segment" + (lines.size() == 1 ? "" : "s"),
            [&](stage::Level& l) {
              auto& to = l.faces[static_cast<size_t>(face)].lines;
              to.insert(to.end(), lines.begin(), lines.end());
            })) {
    selection_.clear();
    for (size_t i = 0; i < lines.size(); ++i) selection_.push_back({face, static_cast<int>(first + i)});
    tool_ = Tool::Select;
  }
}

void Editor::applyTag() {
  if (tool_ != Tool::Select || selection_.empty()) return;
  const uint32_t tag = currentTag();
  apply("tag " + std::to_string(selection_.size()) + " segment" + (selection_.size() == 1 ? "" : "s") +
            document_.tags()->written(tag),
        [&](stage::Level& l) {
          for (const SegmentRef s : selection_)
            l.faces[static_cast<size_t>(s.face)].lines[static_cast<size_t>(s.index)].tag = tag;
        });
}

void Editor::toggleOneWay() {
  if (tool_ != Tool::Select || selection_.empty()) {
    oneWay_ = !oneWay_;
    return say(oneWay_ ? "new segments are one-way (solid from their left, seen from where you start them)"
                       : "new segments are solid from both sides");
  }
  apply("one-way on or off", [&](stage::Level& l) {
    for (const SegmentRef s : selection_) {
      stage::LevelLine& line = l.faces[static_cast<size_t>(s.face)].lines[static_cast<size_t>(s.index)];
      line.oneWay = !line.oneWay;
    }
  });
}

void Editor::cycleGravity() {
  if (!cursor_) return say("point at a face to turn its gravity");
  const int face = cursor_->point.face;
  // The scene's strength, turned a quarter at each press: down (the default), right, up, left.
  const auto g = static_cast<int32_t>(gravity_);
  const std::optional<physics::Vec2w> turns[] = {std::nullopt, physics::Vec2w{g, 0}, physics::Vec2w{0, g},
                                                 physics::Vec2w{-g, 0}};
  const auto& now = document_.level().faces[static_cast<size_t>(face)].gravityQ16;
  size_t next = 1;
  for (size_t i = 0; i < 4; ++i)
    if (turns[i] == now) next = (i + 1) % 4;
  if (now && std::find(std::begin(turns), std::end(turns), now) == std::end(turns)) next = 0;
  const char* names[] = {"down", "right", "up", "left"};
  apply(std::string("face ") + std::to_string(face) + "'s gravity " + names[next],
        [&](stage::Level& l) { l.faces[static_cast<size_t>(face)].gravityQ16 = turns[next]; });
}

void Editor::orbit(float dx, float dy) {
  // Turn the eye round the solid's centre: left and right about the view's up, up and down about
  // its right (the solid seems to follow the pointer).
  const Eigen::Vector3d up = lens_.pose.up(), right = lens_.pose.orientation * Eigen::Vector3d::UnitX();
  const Eigen::Quaterniond turn = Eigen::Quaterniond(Eigen::AngleAxisd(-0.006 * dx, up)) *
                                  Eigen::Quaterniond(Eigen::AngleAxisd(-0.006 * dy, right));
  lens_.pose.orientation = (turn * lens_.pose.orientation).normalized();
  wantedPose_ = lens_.pose;
}

void Editor::zoom(float notches) {
  const double nearest = view_->radius * 1.15, farthest = view_->radius * 12;
  lens_.pose.distance = std::clamp(lens_.pose.distance * std::pow(0.87, notches), nearest, farthest);
  wantedPose_ = lens_.pose;
}

// The palette is a column of words at the screen's right: a click on one takes it.
bool Editor::clickPalette(float x, float y) {
  const float right = static_cast<float>(lens_.width) - 12, left = right - 190, top = kPaletteTop, row = 26;
  if (x < left || x > right || y < top || y > top + row * static_cast<float>(palette_.size())) return false;
  paletteIndex_ = std::min(palette_.size() - 1, static_cast<size_t>((y - top) / row));
  applyTag();
  return true;
}

void Editor::drawSegment(core::DrawList& out, int face, physics::Vec2 a, physics::Vec2 b, float width,
                         core::Color color) const {
  out.line(core::Place::overlayOnFace(solid_.part(static_cast<size_t>(face))), {float(a.x), float(a.y)},
           {float(b.x), float(b.y)}, width, color);
}

core::View Editor::view() const {
  core::View v;
  v.title = "Platon editor: " + document_.path() + (document_.modified() ? " *" : "");
  v.stage = view_;
  v.face = cursor_ ? solid_.part(static_cast<size_t>(cursor_->point.face)) : 0;
  v.camera = lens_.pose;
  v.verticalFov = lens_.verticalFov;
  v.hud = hud();
  return v;
}

std::vector<std::string> Editor::hud() const {
  std::vector<std::string> lines;
  const PaletteEntry& e = palette_[paletteIndex_];
  std::string tag = e.numbered ? e.word + " " + std::to_string(number_) : e.word;
  if (oneWay_) tag += ", one-way";
  std::string where = "off the solid";
  if (cursor_)
    where = "face " + std::to_string(cursor_->point.face) + " (" + std::to_string(std::llround(cursor_->point.x)) +
            ", " + std::to_string(std::llround(cursor_->point.y)) + ")" +
            (cursor_->kind == Snapped::Kind::End     ? " end point"
             : cursor_->kind == Snapped::Kind::Grid  ? " grid"
             : cursor_->kind == Snapped::Kind::Angle ? " angle"
                                                     : "");
  lines.push_back(document_.path() + (document_.modified() ? " (unsaved)" : "") + "   " +
                  (tool_ == Tool::Draw ? "draw" : "select") + ": " + tag + "   grid " + std::to_string(snap_.grid) +
                  "   " + where);
  lines.push_back(std::to_string(report_.errors.size()) + " error" + (report_.errors.size() == 1 ? "" : "s") + ", " +
                  std::to_string(report_.warnings.size()) + " warning" + (report_.warnings.size() == 1 ? "" : "s") +
                  (report_.errors.empty() ? "" : ": " + report_.errors[0].message));
  if (!message_.empty()) lines.push_back(message_);
  lines.push_back(
      "D draw  S select  T tag  [ ] number  O one-way  P start  G goal  V gravity  F face  Del  Ctrl+Z/Y  Ctrl+C/V  "
      "Ctrl+S save  Enter play  Esc quit");
  return lines;
}

void Editor::draw(core::DrawList& out) const {
  const stage::Level& level = document_.level();
  const float unit = static_cast<float>(level.size) / 4096.0f;  // overlay widths scale with the solid
  drawMarkers(out, unit);
  // The start (the player's disk) and the goal's square.
  out.circle(core::Place::overlayOnFace(solid_.part(static_cast<size_t>(level.start.face))),
             {float(level.start.position.x), float(level.start.position.y)}, 96, {kStart.r, kStart.g, kStart.b, 150});
  {
    const float h = static_cast<float>(stage::goalHalfSide(level));
    const float gx = float(level.goal.position.x), gy = float(level.goal.position.y);
    const core::Point2 square[] = {{gx - h, gy - h}, {gx + h, gy - h}, {gx + h, gy + h}, {gx - h, gy + h}};
    out.polygon(core::Place::overlayOnFace(solid_.part(static_cast<size_t>(level.goal.face))), square,
                {kGoal.r, kGoal.g, kGoal.b, 110});
  }
  // The selection, the drag's preview, the cursor.
  for (const SegmentRef s : selection_) {
    const stage::LevelLine& l = level.faces[static_cast<size_t>(s.face)].lines[static_cast<size_t>(s.index)];
    drawSegment(out, s.face, l.a, l.b, 40 * unit, kSelected);
    for (const physics::Vec2 p : {l.a, l.b})
      out.circle(core::Place::overlayOnFace(solid_.part(static_cast<size_t>(s.face))), {float(p.x), float(p.y)},
                 36 * unit, kSelected);
  }
  if (dragTo_ && drag_.what != Drag::What::None) drawDragPreview(out, unit);
  if (cursor_) {
    const core::Place place = core::Place::overlayOnFace(solid_.part(static_cast<size_t>(cursor_->point.face)));
    const float r = cursor_->kind == Snapped::Kind::End ? 60 * unit : 32 * unit;
    out.circle(place, {float(cursor_->point.x), float(cursor_->point.y)}, r, kCursor);
  }
  drawPalette(out);
}

// The findings where they are: a segment's drawn over, a face's outlined, the start's or the
// goal's circled.
void Editor::drawMarkers(core::DrawList& out, float unit) const {
  const stage::Level& level = document_.level();
  for (const Marker& m : markers_) {
    const core::Color c = m.error ? kError : kWarning;
    if (m.on == Marker::On::Segment) {
      const stage::LevelLine& l = level.faces[static_cast<size_t>(m.face)].lines[static_cast<size_t>(m.segment.index)];
      drawSegment(out, m.face, l.a, l.b, 70 * unit, c);
    } else if (m.on == Marker::On::Face) {
      const auto& corners = solid_.faces[static_cast<size_t>(m.face)].corners;
      for (size_t i = 0; i < corners.size(); ++i)
        drawSegment(out, m.face, corners[i], corners[(i + 1) % corners.size()], 60 * unit, c);
    } else if (m.on == Marker::On::Start || m.on == Marker::On::Goal) {
      const physics::Vec2 p = m.on == Marker::On::Start ? level.start.position : level.goal.position;
      out.circle(core::Place::overlayOnFace(solid_.part(static_cast<size_t>(m.face))), {float(p.x), float(p.y)},
                 180 * unit, {c.r, c.g, c.b, 110});
    }
  }
}

// What the drag under way would make: the segment being drawn, the end, the start, the goal or
// the selected segments where they would go.
void Editor::drawDragPreview(core::DrawList& out, float unit) const {
  const stage::Level& level = document_.level();
  const physics::Vec2 a = whole(drag_.from), b = whole(*dragTo_);
  if (drag_.what == Drag::What::Draw) {
    drawSegment(out, drag_.from.face, a, b, 30 * unit, colorOf(document_.tags()->style(currentTag())));
  } else if (drag_.what == Drag::What::MoveEnd) {
    const stage::LevelLine& l =
        level.faces[static_cast<size_t>(drag_.segment.face)].lines[static_cast<size_t>(drag_.segment.index)];
    drawSegment(out, drag_.segment.face, drag_.endB ? l.a : b, drag_.endB ? b : l.b, 30 * unit, kSelected);
  } else if (drag_.what == Drag::What::MoveStart || drag_.what == Drag::What::MoveGoal) {
    const core::Place at = core::Place::overlayOnFace(solid_.part(static_cast<size_t>(dragTo_->face)));
    const float r = drag_.what == Drag::What::MoveStart ? 96 : static_cast<float>(stage::goalHalfSide(level));
    out.circle(at, {float(b.x), float(b.y)}, r, drag_.what == Drag::What::MoveStart ? kStart : kGoal);
  } else if (drag_.what == Drag::What::MoveSegments) {
    for (const SegmentRef s : selection_) {
      if (s.face != drag_.from.face) continue;
      const stage::LevelLine& l = level.faces[static_cast<size_t>(s.face)].lines[static_cast<size_t>(s.index)];
      drawSegment(out, s.face, {l.a.x + b.x - a.x, l.a.y + b.y - a.y}, {l.b.x + b.x - a.x, l.b.y + b.y - a.y},
                  30 * unit, kSelected);
    }
  }
}

// The palette: a panel at the top right, a swatch and a word for each tag, the current one marked.
void Editor::drawPalette(core::DrawList& out) const {
  const float right = static_cast<float>(lens_.width) - 12, left = right - 190, top = kPaletteTop, row = 26;
  const core::Point2 panel[] = {{left - 6, top - 30},
                                {right + 6, top - 30},
                                {right + 6, top + row * static_cast<float>(palette_.size()) + 6},
                                {left - 6, top + row * static_cast<float>(palette_.size()) + 6}};
  out.polygon(core::Place::onScreen(), panel, kPanel);
  out.text(core::Place::onScreen(), {left, top - 26}, oneWay_ ? "tags (O: one-way)" : "tags (O: solid)", 18, kDim);
  for (size_t i = 0; i < palette_.size(); ++i) {
    const PaletteEntry& e = palette_[i];
    const float y = top + row * static_cast<float>(i);
    const stage::TagStyle style = document_.tags()->style(e.numbered ? e.number + number_ : e.number);
    const core::Point2 swatch[] = {{left, y + 4}, {left + 18, y + 4}, {left + 18, y + 22}, {left, y + 22}};
    out.polygon(core::Place::onScreen(), swatch, colorOf(style));
    const std::string label = e.numbered ? e.word + " " + std::to_string(number_) : e.word;
    out.text(core::Place::onScreen(), {left + 28, y + 2}, (i == paletteIndex_ ? "> " : "  ") + label, 20,
             i == paletteIndex_ ? kSelected : kText);
  }
}

}  // namespace platon::editor

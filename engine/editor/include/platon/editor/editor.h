// The level editor's state: the document, the camera round the solid, the tool, the selection,
// the palette of tag words, the check's findings; what the window's input does to them, and the
// picture. The program around it (`platon edit`) owns the window and plays the level; the editor
// asks for that with handle()'s answer. Headless tests drive it with the events a window gives.
//
// Controls (docs/editing.md): the left button draws (drag, or click and click for a chain) or, in
// the select tool, picks and drags segments, their ends, the start and the goal; the right button
// (or the middle) turns the solid, the wheel zooms; keys: D draw, S select, T / Shift+T the
// palette, [ ] a door's or switch's number, O one-way, P start here, G goal here, V the face's
// gravity, F the face head-on, Home the game's view at the start, , and . the grid, Delete, Ctrl+Z
// and Ctrl+Y (Ctrl+Shift+Z), Ctrl+C and Ctrl+V, Ctrl+S save (refused while the level would not
// load; Ctrl+Shift+S saves anyway), Enter plays from the cursor, Esc quits (twice with unsaved
// edits).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "platon/core/display.h"
#include "platon/core/draw_list.h"
#include "platon/editor/level_document.h"
#include "platon/editor/pick.h"
#include "platon/editor/snap.h"
#include "platon/physics/world.h"
#include "platon/stage/level_check.h"

namespace platon::editor {

enum class Tool : uint8_t { Draw, Select };

// A segment of the level: its face and its index among the face's lines.
struct SegmentRef {
  int face = -1, index = -1;
  friend bool operator==(SegmentRef, SegmentRef) = default;
};

// One word of the palette: a tag kind of the scene's table ("door" with its number).
struct PaletteEntry {
  std::string word;
  uint32_t number = 0;  // the kind's tag (a numbered kind's base)
  bool numbered = false;
};

// A finding of the check drawn where it is: on a segment, the start, the goal or a whole face.
struct Marker {
  enum class On : uint8_t { Segment, Start, Goal, Face, Level };
  On on = On::Level;
  SegmentRef segment;
  int face = -1;
  bool error = false;
  std::string message;
};

class Editor {
 public:
  enum class Request : uint8_t { None, Quit, Play };

  // `solid`: the level's stage; `defaultGravityQ16`: the scene's gravity (a face without its own).
  Editor(LevelDocument document, stage::Stage solid, int64_t defaultGravityQ16);

  // The window's input since the last poll, in order; what the program should do next.
  Request handle(const core::WindowInput& input);
  // The picture: the solid from the editor's camera, the heads-up lines; and the overlays (the
  // cursor, the selection, the segment being drawn, the findings) and the palette.
  core::View view() const;
  void draw(core::DrawList& out) const;

  LevelDocument& document() { return document_; }
  const LevelDocument& document() const { return document_; }
  const stage::Stage& solid() const { return solid_; }
  // The level as the game builds it, made again after every edit (the segments inside their faces).
  const physics::World& world() const { return *world_; }
  const std::shared_ptr<const core::StageView>& stageView() const { return view_; }
  const stage::CheckReport& report() const { return report_; }
  const std::vector<Marker>& markers() const { return markers_; }
  // Whether the level loads in the game as it is (no finding of checkLevelOnStage).
  bool loads() const { return loads_; }

  Tool tool() const { return tool_; }
  const std::vector<SegmentRef>& selection() const { return selection_; }
  const std::vector<PaletteEntry>& palette() const { return palette_; }
  size_t paletteIndex() const { return paletteIndex_; }
  uint32_t currentTag() const;
  // The snapped point under the mouse, when it is on the solid.
  std::optional<FacePoint> cursor() const { return cursor_ ? std::optional(cursor_->point) : std::nullopt; }
  // Where a play from here starts: the cursor's point, else the level's start.
  stage::LevelPoint playStart() const;
  Lens lens() const { return lens_; }
  // The camera at once where the game's would be for a player at (face, x, y).
  void lookAt(int face, double x, double y);
  // The heads-up message line (the last one said).
  void say(std::string message) {
    said_.push_back(message);
    message_ = std::move(message);
  }
  const std::string& message() const { return message_; }
  // Every message said since the last call, in order (several edits may come in one poll).
  std::vector<std::string> takeMessages() { return std::exchange(said_, {}); }
  // The face point under pixel (x, y), not snapped; none off the solid.
  std::optional<FacePoint> pointAt(float x, float y) const;
  // The camera head-on to face `face` (its centre in the middle, its down down the screen).
  void faceHeadOn(int face);

  // Builds the world, the picture and the check from the document (after each edit, undo, redo).
  void rebuild();
  // How long the last rebuild took to make the level playable (the world and the picture's stage,
  // not the check), in milliseconds: bench/stage/edit_latency.cpp.
  double lastBuildMilliseconds() const { return buildMs_; }

 private:
  struct Drag {
    enum class What : uint8_t { None, Draw, Orbit, MoveEnd, MoveSegments, MoveStart, MoveGoal };
    What what = What::None;
    FacePoint from;      // where it began (snapped), on face from.face
    SegmentRef segment;  // MoveEnd: the segment, and which end
    bool endB = false;
    float mouseX = 0, mouseY = 0;  // the pointer when it began (a click is a drag that did not move)
    bool chain = false;            // Draw: a click began it; the next click ends the segment
    bool alone = false;            // MoveEnd: Alt held: the dragged end only, not the ends joined to it
  };

  void onKey(const core::KeyPress& key);
  void onCtrlKey(const core::KeyPress& key);
  void undoOrRedo(bool redo);
  void saveDocument(bool anyway);
  void selectFace();
  void moveMarkToCursor(bool start);
  void onMouse(const core::MouseEvent& event, bool shift, bool alt);
  void pressToSelect(float x, float y, bool shift, bool alt);
  void onMove(float x, float y, bool shift, bool alt);
  void endDrag(float x, float y);
  void endDraw(const Drag& drag, physics::Vec2 a, physics::Vec2 b, FacePoint to, float x, float y);
  void endMoveEnd(const Drag& drag, physics::Vec2 a, physics::Vec2 b);
  void endMoveSegments(const Drag& drag, physics::Vec2 a, physics::Vec2 b);
  bool apply(const std::string& name, const std::function<void(stage::Level&)>& change);
  std::optional<Snapped> snapAt(float x, float y, int onFace, bool shift, bool alt) const;
  std::optional<SegmentRef> segmentNear(float x, float y, bool& nearEnd, bool& endB) const;
  bool nearPoint(float x, float y, const stage::LevelPoint& p, double pixels) const;
  void deleteSelection();
  void copySelection();
  void paste();
  void applyTag();
  void toggleOneWay();
  void cycleGravity();
  void orbit(float dx, float dy);
  void zoom(float notches);
  bool clickPalette(float x, float y);
  void drawSegment(core::DrawList& out, int face, physics::Vec2 a, physics::Vec2 b, float width,
                   core::Color color) const;
  void drawMarkers(core::DrawList& out, float unit) const;
  void drawDragPreview(core::DrawList& out, float unit) const;
  void drawPalette(core::DrawList& out) const;
  std::vector<std::string> hud() const;

  LevelDocument document_;
  stage::Stage solid_;
  int64_t gravity_;
  std::unique_ptr<physics::World> world_;
  std::shared_ptr<const core::StageView> view_;
  stage::CheckReport report_;
  std::vector<Marker> markers_;
  bool loads_ = true;
  double buildMs_ = 0;

  Tool tool_ = Tool::Draw;
  bool oneWay_ = false;
  std::vector<PaletteEntry> palette_;
  size_t paletteIndex_ = 0;
  uint32_t number_ = 1;  // a numbered kind's n
  SnapSettings snap_;
  Lens lens_;
  camera::CameraPose wantedPose_;
  std::optional<Snapped> cursor_;
  float mouseX_ = 0, mouseY_ = 0;
  Drag drag_;
  std::optional<FacePoint> dragTo_;  // where the drag is now (snapped)
  std::vector<SegmentRef> selection_;
  std::vector<stage::LevelLine> clipboard_;  // relative to the first one's a
  std::string message_;
  std::vector<std::string> said_;
  bool quitAsked_ = false;
};

}  // namespace platon::editor

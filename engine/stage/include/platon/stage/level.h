// The level format (docs/level-format.md): the seed's text format, with comments, line tags,
// per-face gravity and mesh stages. Reading is two steps so that no half-built level ever reaches
// a world: parseLevel() checks the text; checkLevelOnStage() checks it against the solid's faces
// (face count, every segment inside its face, start and goal clear of walls). buildLevel() then
// creates the faces and lines in a world.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "platon/physics/world.h"
#include "platon/stage/polyhedron.h"
#include "platon/stage/stage.h"
#include "platon/stage/stage_error.h"
#include "platon/stage/tags.h"

namespace platon::stage {

struct LevelLine {
  physics::Vec2 a, b;
  bool oneWay = false;  // solid from its left side only (seen from a to b)
  uint32_t tag = 0;
  int sourceLine = 0, sourceColumn = 0;  // where a is written
  int endColumn = 0;                     // where b is written (its x)

  friend bool operator==(const LevelLine&, const LevelLine&);  // the data, not where it was read
};

struct LevelFace {
  std::vector<LevelLine> lines;
  std::optional<physics::Vec2w> gravityQ16;  // per frame per frame, in the face's frame; none: the scene's, down
  int sourceLine = 0;                        // the '%' line

  friend bool operator==(const LevelFace&, const LevelFace&);
};

struct LevelPoint {
  int face = 0;
  physics::Vec2 position;
  int sourceLine = 0, sourceColumn = 0;

  friend bool operator==(const LevelPoint&, const LevelPoint&);
};

struct Level {
  std::string file;                  // as given to parseLevel, for messages
  std::optional<Solid> solid;        // a Platonic solid, or
  std::string mesh;                  // a mesh file, relative to the level file's folder
  int meshLine = 0, meshColumn = 0;  // where the level names it: the mesh's errors point there
  LevelPoint start;
  int64_t startMillidegrees = 0;  // the player's rotation
  LevelPoint goal;
  int32_t size = 0;  // face edge (Platonic) or longest edge (mesh), in units
  std::vector<LevelFace> faces;
  int endLine = 0;  // the line after the last, for "missing" messages
  // The tag table the level was read with: its words are the segments' tags (tags.h).
  std::shared_ptr<const TagTable> tags = gameTags();

  friend bool operator==(const Level&, const Level&);
};

// The level's text, syntax and ranges only, its segments' tag words from `tags` (the game's, and
// a scene's mods' own). Throws StageError with file:line:column.
Level parseLevel(std::string_view text, const std::string& file, std::shared_ptr<const TagTable> tags = gameTags());

// The text of `level` as parseLevel reads it: parseLevel(writeLevel(l, ...)) == l for every level
// parseLevel accepts. With `original` (the text `level` was edited from, whose segments and points
// still carry their sourceLine), that text is kept wherever it still says the same: comments,
// blank lines and the order of lines stay; a line whose values changed is written again with its
// comment after it; a deleted segment's line goes; a new segment (sourceLine 0) follows the last
// segment of its face. Unchanged, the original comes back byte for byte. Without it (or when it
// does not read as a level of the same faces), the level is written afresh, without comments.
std::string writeLevel(const Level& level, std::string_view original = {});

// The room the player needs around its start, and the goal around its point: no solid line may
// come nearer (the default player is a circle of 96 units).
inline constexpr int32_t kStartClearance = 100;
// The goal is a square trigger (tag goal) of this half side, or size / 16 if that is smaller.
inline constexpr int32_t kGoalHalfSide = 150;
int32_t goalHalfSide(const Level& level);

// Checks the level against its stage's faces: as many faces as the solid has, every segment
// inside its face, start and goal on a face and clear of solid lines. Throws StageError.
void checkLevelOnStage(const Level& level, const Stage& stage);

// For a Platonic level: its stage (size from the level). Throws StageError for a mesh level.
Stage platonicStageOf(const Level& level);

// Puts the checked level into `world`: the stage's parts from firstPart on, the level's lines,
// each face's gravity (the level's, or `defaultGravityQ16` down its face), the goal's trigger.
// The parts are not initialized (the caller's systems may add lines first).
void buildLevel(const Level& level, Stage& stage, physics::World& world, physics::MapPartId firstPart,
                int64_t defaultGravityQ16);

// What a level may hold, checked as it is read (before memory grows): segments on one face and in
// all. 10^6 on a face is the largest map the benches measure (bench/map_scaling); a level of more
// would cost its players gigabytes (256 MB of text holds 12 million short segments).
inline constexpr size_t kMaxFaceSegments = size_t{1} << 20;
inline constexpr size_t kMaxLevelSegments = size_t{1} << 21;
// Faces ('%' lines): a mesh stage's most (its triangles, stage::kMaxMeshTriangles).
inline constexpr size_t kMaxLevelFaces = 100000;

// Reads a level file: a regular file of at most kMaxLevelFileBytes (throws StageError naming the
// file for one that cannot be read: missing, a FIFO or a device, too large).
inline constexpr size_t kMaxLevelFileBytes = size_t{256} << 20;
std::string readLevelFile(const std::string& path);

}  // namespace platon::stage

---@meta
-- The Lua language server's definitions of Platon's scripting API for level scripts, mods and a level's own rules and player (sandboxed).
-- Written by `platon defs` from the engine's binding tables: do not edit (docs/scripting.md, "Editors").

---@class platon
platon = {}

---@class platon.draw
platon.draw = {}

--- A disc; false when the frame's picture is full.
---@param place integer|"screen"
---@param x number
---@param y number
---@param r number
---@param colour integer
---@param alpha? integer
---@return boolean
function platon.draw.circle(place, x, y, r, colour, alpha) end

--- Whether anything is drawn (false headless).
---@return boolean
function platon.draw.enabled() end

--- A line.
---@param place integer|"screen"
---@param x0 number
---@param y0 number
---@param x1 number
---@param y1 number
---@param width number
---@param colour integer
---@return boolean
function platon.draw.line(place, x0, y0, x1, y1, width, colour) end

--- How the engine draws a body.
---@param entity integer
---@param colour integer
---@param form? "shape"|"ball"|"none"
---@param squash? number
function platon.draw.look(entity, colour, form, squash) end

--- A convex polygon, counter-clockwise.
---@param place integer|"screen"
---@param points number[]
---@param colour integer
---@return boolean
function platon.draw.polygon(place, points, colour) end

--- Text.
---@param place integer|"screen"
---@param x number
---@param y number
---@param text string
---@param height number
---@param colour integer
---@return boolean
function platon.draw.text(place, x, y, text, height, colour) end

---@class platon.sound
platon.sound = {}

--- Whether the bank has it.
---@param name string
---@param kind? "music"
---@return boolean
function platon.sound.has(name, kind) end

--- Plays a tune from now on (nil: none).
---@param name string?
function platon.sound.music(name) end

--- Plays an effect of the scene's bank this frame.
---@param name string
---@param volume? number
---@param pan? number
---@return boolean
function platon.sound.play(name, volume, pan) end

--- The tune playing.
---@return string?
function platon.sound.playing() end

---@class platon.TagKind
---@field word string
---@field number integer the tag, or a numbered kind's base
---@field count integer 0, or 999 for a word that takes a number
---@field passable "wall"|"through"|"door"
---@field color string "#rrggbb"
---@field glow boolean
---@field spikes boolean
---@field owner string "the game", or a mod's file

--- The line tags' kinds, in the table's order.
---@type platon.TagKind[]
platon.tagKinds = {}

--- Each line tag's number by its word (the game's and the mods'): platon.tags.hazard.
---@type table<string, integer>
platon.tags = {}

---@class platon.world
platon.world = {}

--- The body's turn.
---@param entity integer
---@return number degrees
function platon.world.angle(entity) end

--- The i-th contact: its unit normal away from the line, and what.
---@param entity integer
---@param i integer
---@return number nx
---@return number ny
---@return integer tag
---@return string kind
---@return integer part
---@return integer? line
---@return integer? other
function platon.world.contact(entity, i) end

--- Its solid contacts of the latest frame.
---@param entity integer
---@return integer
function platon.world.contactCount(entity) end

--- Bodies overlapping walls or each other (0 in a sound world).
---@return integer
function platon.world.countOverlaps() end

--- Makes a body; insert it to put it in the world.
---@param shape {circle?: number, sides?: integer, box?: number[], polygon?: number[]}
---@return integer entity
function platon.world.createEntity(shape) end

--- A moving platform of the lines (x0, y0, x1, y1, ...).
---@param part integer
---@param points integer[]
---@param tag? integer
---@param kind? "solid"|"oneway"
---@return integer platform
function platon.world.createPlatform(part, points, tag, kind) end

--- Destroys a body (not the player's, from a sandbox).
---@param entity integer
function platon.world.destroyEntity(entity) end

--- Removes it.
---@param platform integer
function platon.world.destroyPlatform(platform) end

--- Takes a body off a face.
---@param entity integer
---@param part integer
function platon.world.erase(entity, part) end

--- The i-th face's id (1-based).
---@param i integer
---@return integer part
function platon.world.face(i) end

--- The stage's faces.
---@return integer
function platon.world.faceCount() end

--- The world's frames since the scene was loaded.
---@return integer
function platon.world.frame() end

--- A face's gravity, per frame per frame.
---@param part integer
---@return number gx
---@return number gy
function platon.world.gravity(part) end

--- Puts a body on a face; an error where a wall is.
---@param entity integer
---@param part integer
---@param x integer
---@param y integer
---@param degrees? number
function platon.world.insert(entity, part, x, y, degrees) end

--- The i-th copy.
---@param entity integer
---@param i integer
---@return integer part
---@return integer x
---@return integer y
---@return number degrees
function platon.world.instance(entity, i) end

--- Its copies: one on a face, more across edges.
---@param entity integer
---@return integer
function platon.world.instanceCount(entity) end

--- The level file's start, or nothing.
---@return integer? part
---@return integer? x
---@return integer? y
---@return number? degrees
function platon.world.levelStart() end

--- Adds a solid line (build time only); tag from platon.tags.
---@param part integer
---@param x0 integer
---@param y0 integer
---@param x1 integer
---@param y1 integer
---@param tag? integer
function platon.world.line(part, x0, y0, x1, y1, tag) end

--- The i-th line, i from 1 to lineCount(part).
---@param part integer
---@param i integer
---@return integer x0
---@return integer y0
---@return integer x1
---@return integer y1
---@return integer tag
---@return string kind
function platon.world.lineAt(part, i) end

--- A face's lines.
---@param part integer
---@return integer
function platon.world.lineCount(part) end

--- Adds a one-way line, solid from its left (build time only).
---@param part integer
---@param x0 integer
---@param y0 integer
---@param x1 integer
---@param y1 integer
---@param tag? integer
function platon.world.oneWay(part, x0, y0, x1, y1, tag) end

--- How far it has turned about its pivot.
---@param platform integer
---@return number degrees
function platon.world.platformAngle(platform) end

--- How far it has moved since it was made, or last crossed a face's edge.
---@param platform integer
---@return integer dx
---@return integer dy
function platon.world.platformOffset(platform) end

--- The face it is on: it changes when it crosses a face's edge.
---@param platform integer
---@return integer part
function platon.world.platformPart(platform) end

--- The body's anchor: its face and place, in units.
---@param entity integer
---@return integer part
---@return integer x
---@return integer y
function platon.world.position(entity) end

--- Asks the rules again whether lines of this tag pierce.
---@param tag integer
function platon.world.refreshPierce(tag) end

--- Turns it each frame.
---@param entity integer
---@param degreesPerFrame number
function platon.world.setAngularVelocity(entity, degreesPerFrame) end

--- Which bodies it collides with, overlaps, and whether it can be pushed.
---@param entity integer
---@param filter {category?: integer, solidWith?: integer, overlapWith?: integer, pushable?: boolean}
function platon.world.setFilter(entity, filter) end

--- Sets a face's gravity.
---@param part integer
---@param gx number
---@param gy number
function platon.world.setGravity(part, gx, gy) end

--- Whether its face's gravity pulls it.
---@param entity integer
---@param on boolean
function platon.world.setGravityEnabled(entity, on) end

--- Moves it by (dx, dy) units every frame from the next on.
---@param platform integer
---@param dx integer
---@param dy integer
function platon.world.setPlatformMotion(platform, dx, dy) end

--- Turns it about (px, py) by that much every frame from the next on.
---@param platform integer
---@param px integer
---@param py integer
---@param degreesPerFrame number
function platon.world.setPlatformSpin(platform, px, py, degreesPerFrame) end

--- Sets it (each within +-131071): to copy a body exactly.
---@param entity integer
---@param sx integer
---@param sy integer
function platon.world.setSubunit(entity, sx, sy) end

--- Units per frame.
---@param entity integer
---@param vx number
---@param vy number
function platon.world.setVelocity(entity, vx, vy) end

--- The world's state hash, 16 hex digits.
---@return string
function platon.world.stateHash() end

--- The motion below one unit it carries to its next frame (1/131072 units).
---@param entity integer
---@return integer sx
---@return integer sy
function platon.world.subunit(entity) end

--- Whether the handle names a live body.
---@param entity integer
---@return boolean
function platon.world.valid(entity) end

--- Units per frame, in its face's frame.
---@param entity integer
---@return number vx
---@return number vy
function platon.world.velocity(entity) end

--- What level scripts, mods and a level's own rules are handed as `game` (their hooks' first
--- argument): annotate it with ---@param game platon.Game.
---@class platon.Game
---@field world platon.world the world, read-only as a table
local Game = {}

--- Moves the restart point.
---@param part integer
---@param x integer
---@param y integer
function Game.checkpoint(part, x, y) end

--- Frames played on the level (kept across hot reloads).
---@return integer
function Game.frame() end

--- Kills the player.
function Game.kill() end

--- The message shown to the player (200 bytes at most).
---@param text any
function Game.message(text) end

--- The player's entity.
---@return integer?
function Game.player() end

--- Whether switch id (1..999) is on.
---@param id integer
---@return boolean
function Game.switchOn(id) end

--- Toggles switch id after this frame.
---@param id integer
function Game.toggle(id) end

--- Whether the goal was reached.
---@return boolean
function Game.won() end

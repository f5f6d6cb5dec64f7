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

--- The actions held this frame (a player's tick's `input`), the engine's and the scene's mods':
--- `input.jump`; `input.pressed.jump` went down on this frame.
---@class platon.Input
---@field left boolean walks left along the face (its own left, as gravity turns)
---@field right boolean walks right along the face
---@field up boolean up, for scripts that use it (the game's player does not)
---@field down boolean down, for scripts that use it (the game's player does not)
---@field jump boolean jumps; held longer, higher (the jump is cut when it is let go)
---@field restart boolean back to the level's start (a death)
---@field pause boolean held by scripts and scenarios only: the game's Esc pauses the window
---@field reload boolean F5: the level's files read again (the tool's key, not bindable)
---@field pressed platon.Input the actions that went down on this frame

--- A mod's action (its table's `actions`): keys and pad buttons by SDL's names.
---@class platon.ActionDeclaration
---@field keys? string[] default keys ("Left Shift", "X"), at most 8
---@field pad? string[] default pad buttons ("x", "rightshoulder"), at most 8
---@field label? string the settings screen's name for it (default: its name)
---@field does? string one line: what it does

--- A tag a mod declares (its table's `tags`): its look, its passage and its handlers.
---@class platon.TagDeclaration
---@field color? string "#rrggbb"
---@field glow? boolean drawn unlit and bright
---@field spikes? boolean a row of spikes along its top
---@field numbered? boolean the word takes a number 1..999
---@field passable? boolean|fun(game: platon.Game, entity: integer, tag: integer, kind: integer): boolean
---@field contact? fun(game: platon.Game, entity: integer, tag: integer, kind: integer, ...): table?
---@field beginContact? fun(game: platon.Game, entity: integer, tag: integer, kind: integer, ...): table?
---@field overContact? fun(game: platon.Game, entity: integer, tag: integer, kind: integer, ...): table?
---@field endContact? fun(game: platon.Game, entity: integer, tag: integer, kind: integer, ...): table?
---@field touchContact? fun(game: platon.Game, entity: integer, tag: integer, kind: integer, ...): table?

--- What a level script or a mod returns.
---@class platon.Module
---@field build? fun(game: platon.Game, ...): any the build hook
---@field tick? fun(game: platon.Game, ...): any the tick hook
---@field draw? fun(game: platon.Game, ...): any the draw hook
---@field save? fun(game: platon.Game, ...): any the save hook
---@field onReload? fun(game: platon.Game, ...): any the onReload hook
---@field start? {face: integer, x: number, y: number} where the player starts
---@field tags? table<string, platon.TagDeclaration> a mod's line tags
---@field actions? table<string, platon.ActionDeclaration> a mod's actions

--- The game's player (scripts/player.lua): a level's own player is handed a copy to extend.
---@class platon.Player
---@field entity integer its body
---@field grounded boolean it stands on something
---@field wall integer the way off a wall it touches: 1 right, -1 left, 0 none
---@field facing integer the way it last walked: 1 right, -1 left
---@field downX number the face's down this frame (a unit vector)
---@field downY number
---@field rightX number the face's right this frame (down turned a quarter)
---@field rightY number
---@field jumping boolean rising from its own jump (the jump cut applies)
---@field coyote integer frames a jump still works after leaving a ledge
---@field buffer integer frames a pressed jump waits for the ground
---@field fall number the fall speed last frame (+ down)
local Player = {}
Player.AIR_ACCEL = 0.35
Player.BUFFER_FRAMES = 6
Player.COLOUR = 15909198
Player.COYOTE_FRAMES = 6
Player.GROUND_ACCEL = 0.6
Player.GROUND_BRAKE = 0.9
Player.GROUND_COS = 0.64
Player.JUMP_CUT = 4
Player.JUMP_SPEED = 11
Player.JUMP_STRETCH = 1.3
Player.LAND_SPEED = 2.5
Player.LAND_SQUASH = 0.7
Player.RADIUS = 96
Player.SQUASH_EASE = 0.7
Player.WALK_SPEED = 9
Player.WALL_COS = 0.9

--- Optional: the new version's player given what save returned.
---@param self platon.Player
---@param state table
function Player.onReload(self, state) end

--- Optional: what a hot reload carries to the new version (default: its plain fields).
---@param self platon.Player
---@return table
function Player.save(self) end

---@param self platon.Player
---@return boolean
function Player.canJump(self) end

---@param self platon.Player
---@param draw platon.draw
function Player.draw(self, draw) end

---@param self platon.Player
---@param along number
---@return number along
---@return number fall
function Player.jump(self, along) end

---@param self platon.Player
---@param input platon.Input
---@param along number
---@param fall number
---@return number along
---@return number fall
function Player.move(self, input, along, fall) end

---@param game platon.Game
---@param face integer
---@param x number
---@param y number
---@param degrees? number
---@return platon.Player
function Player.spawn(game, face, x, y, degrees) end

---@param self platon.Player
---@param input platon.Input
function Player.tick(self, input) end

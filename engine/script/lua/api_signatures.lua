-- The scripting API's signatures, from which `platon defs` writes the Lua language server's
-- definitions (---@meta) of the functions the engine's binding tables register: one entry per
-- function, { parameters, results, what it does } (docs/scripting.md says more). The generator
-- walks the live tables, trusted and sandboxed: a function with no entry here, or an entry with
-- no function, is an error (Definitions tests), so the two cannot drift apart.
-- Parameters: "name: type, name?: type" (? optional); results: "type name, type name".
return {
  ["platon.world.createEntity"] = { "shape: {circle?: number, sides?: integer, box?: number[], polygon?: number[]}",
                                    "integer entity", "Makes a body; insert it to put it in the world." },
  ["platon.world.destroyEntity"] = { "entity: integer", "", "Destroys a body (not the player's, from a sandbox)." },
  ["platon.world.valid"] = { "entity: integer", "boolean", "Whether the handle names a live body." },
  ["platon.world.insert"] = { "entity: integer, part: integer, x: integer, y: integer, degrees?: number", "",
                              "Puts a body on a face; an error where a wall is." },
  ["platon.world.erase"] = { "entity: integer, part: integer", "", "Takes a body off a face." },
  ["platon.world.position"] = { "entity: integer", "integer part, integer x, integer y",
                                "The body's anchor: its face and place, in units." },
  ["platon.world.angle"] = { "entity: integer", "number degrees", "The body's turn." },
  ["platon.world.velocity"] = { "entity: integer", "number vx, number vy", "Units per frame, in its face's frame." },
  ["platon.world.setVelocity"] = { "entity: integer, vx: number, vy: number", "", "Units per frame." },
  ["platon.world.subunit"] = { "entity: integer", "integer sx, integer sy",
                               "The motion below one unit it carries to its next frame (1/131072 units)." },
  ["platon.world.setSubunit"] = { "entity: integer, sx: integer, sy: integer", "",
                                  "Sets it (each within +-131071): to copy a body exactly." },
  ["platon.world.setAngularVelocity"] = { "entity: integer, degreesPerFrame: number", "", "Turns it each frame." },
  ["platon.world.setGravityEnabled"] = { "entity: integer, on: boolean", "", "Whether its face's gravity pulls it." },
  ["platon.world.setFilter"] = { "entity: integer, filter: {category?: integer, solidWith?: integer, "
                                 .. "overlapWith?: integer, pushable?: boolean}", "",
                                 "Which bodies it collides with, overlaps, and whether it can be pushed." },
  ["platon.world.contactCount"] = { "entity: integer", "integer", "Its solid contacts of the latest frame." },
  ["platon.world.contact"] = { "entity: integer, i: integer",
                               "number nx, number ny, integer tag, string kind, integer part, integer? line, "
                               .. "integer? other", "The i-th contact: its unit normal away from the line, and what." },
  ["platon.world.instanceCount"] = { "entity: integer", "integer", "Its copies: one on a face, more across edges." },
  ["platon.world.instance"] = { "entity: integer, i: integer", "integer part, integer x, integer y, number degrees",
                                "The i-th copy." },
  ["platon.world.gravity"] = { "part: integer", "number gx, number gy", "A face's gravity, per frame per frame." },
  ["platon.world.setGravity"] = { "part: integer, gx: number, gy: number", "", "Sets a face's gravity." },
  ["platon.world.line"] = { "part: integer, x0: integer, y0: integer, x1: integer, y1: integer, tag?: integer", "",
                            "Adds a solid line (build time only); tag from platon.tags." },
  ["platon.world.oneWay"] = { "part: integer, x0: integer, y0: integer, x1: integer, y1: integer, tag?: integer", "",
                              "Adds a one-way line, solid from its left (build time only)." },
  ["platon.world.lineCount"] = { "part: integer", "integer", "A face's lines." },
  ["platon.world.lineAt"] = { "part: integer, i: integer",
                              "integer x0, integer y0, integer x1, integer y1, integer tag, string kind", "The i-th line." },
  ["platon.world.refreshPierce"] = { "tag: integer", "", "Asks the rules again whether lines of this tag pierce." },
  ["platon.world.createPlatform"] = { "part: integer, points: integer[], tag?: integer, kind?: \"solid\"|\"oneway\"",
                                      "integer platform", "A moving platform of the lines (x0, y0, x1, y1, ...)." },
  ["platon.world.setPlatformMotion"] = { "platform: integer, dx: integer, dy: integer", "",
                                         "Moves it by (dx, dy) units every frame from the next on." },
  ["platon.world.platformOffset"] = { "platform: integer", "integer dx, integer dy",
                                      "How far it has moved since it was made." },
  ["platon.world.destroyPlatform"] = { "platform: integer", "", "Removes it." },
  ["platon.world.frame"] = { "", "integer", "The world's frames since the scene was loaded." },
  ["platon.world.stateHash"] = { "", "string", "The world's state hash, 16 hex digits." },
  ["platon.world.countOverlaps"] = { "", "integer", "Bodies overlapping walls or each other (0 in a sound world)." },
  ["platon.world.faceCount"] = { "", "integer", "The stage's faces." },
  ["platon.world.face"] = { "i: integer", "integer part", "The i-th face's id (1-based)." },
  ["platon.world.levelStart"] = { "", "integer? part, integer? x, integer? y, number? degrees",
                                  "The level file's start, or nothing." },

  ["platon.draw.circle"] = { "place: integer|\"screen\", x: number, y: number, r: number, colour: integer, "
                             .. "alpha?: integer", "boolean", "A disc; false when the frame's picture is full." },
  ["platon.draw.line"] = { "place: integer|\"screen\", x0: number, y0: number, x1: number, y1: number, "
                           .. "width: number, colour: integer", "boolean", "A line." },
  ["platon.draw.polygon"] = { "place: integer|\"screen\", points: number[], colour: integer", "boolean",
                              "A convex polygon, counter-clockwise." },
  ["platon.draw.text"] = { "place: integer|\"screen\", x: number, y: number, text: string, height: number, "
                           .. "colour: integer", "boolean", "Text." },
  ["platon.draw.enabled"] = { "", "boolean", "Whether anything is drawn (false headless)." },
  ["platon.draw.look"] = { "entity: integer, colour: integer, form?: \"shape\"|\"ball\"|\"none\", squash?: number", "",
                           "How the engine draws a body." },

  ["platon.sound.play"] = { "name: string, volume?: number, pan?: number", "boolean",
                            "Plays an effect of the scene's bank this frame." },
  ["platon.sound.music"] = { "name: string?", "", "Plays a tune from now on (nil: none)." },
  ["platon.sound.has"] = { "name: string, kind?: \"music\"", "boolean", "Whether the bank has it." },
  ["platon.sound.playing"] = { "", "string?", "The tune playing." },

  -- What level scripts, mods and a level's own rules get as `game` (scripts/scene.lua).
  ["game.message"] = { "text: any", "", "The message shown to the player (200 bytes at most)." },
  ["game.switchOn"] = { "id: integer", "boolean", "Whether switch id (1..999) is on." },
  ["game.toggle"] = { "id: integer", "", "Toggles switch id after this frame." },
  ["game.kill"] = { "", "", "Kills the player." },
  ["game.checkpoint"] = { "part: integer, x: integer, y: integer", "", "Moves the restart point." },
  ["game.frame"] = { "", "integer", "Frames played on the level (kept across hot reloads)." },
  ["game.player"] = { "", "integer?", "The player's entity." },
  ["game.won"] = { "", "boolean", "Whether the goal was reached." },
}

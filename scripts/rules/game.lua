-- The game's contact rules (trusted), for the game's line tags (their numbers and looks are the
-- engine's tag table, engine/stage/src/tags.cpp; platon.tags has them by word):
--   solid       plain wall or floor
--   hazard      touching it kills the player
--   goal        a trigger line (passable); the player entering it wins
--   checkpoint  a trigger line; entering it moves the restart point there
--   door n      solid while switch n is off, open while it is on
--   switch n    a trigger line; entering it toggles switch n
-- Warp lines (the solid's edges) always pierce. One-way lines are a line kind, not a tag. A mod
-- adds its own tags, and handlers to these, without touching this file (docs/scripting.md, "Tags").
local game = ...
local tags = platon.tags
local HAZARD, GOAL, CHECKPOINT = tags.hazard, tags.goal, tags.checkpoint
local DOOR, SWITCH = tags.door, tags.switch
local play = platon.sound.play

local function isPlayer(entity) return game.player ~= nil and entity == game.player.entity end

local rules = {}

function rules.pierce(entity, tag, kind)
  if kind == "warp" then return true end
  if tag == GOAL or tag == CHECKPOINT then return true end
  if tag >= SWITCH and tag < SWITCH + 1000 then return true end
  if tag >= DOOR and tag < DOOR + 1000 then return game.switches[tag - DOOR] == true end
  return false
end

function rules.beginContact(entity, tag, kind, part)
  if not isPlayer(entity) then return end
  if tag == GOAL then
    game.reachedGoal = true
  elseif tag == CHECKPOINT then
    game.touchedCheckpoint = true
  elseif tag >= SWITCH and tag < SWITCH + 1000 then
    game.pendingToggles[#game.pendingToggles + 1] = tag - SWITCH
    play("switch")
  end
end

function rules.contact(entity, tag)
  if tag == HAZARD and isPlayer(entity) then game.killed = true end
end

function rules.crushed(entity)
  if isPlayer(entity) then game.killed = true end
end

return rules

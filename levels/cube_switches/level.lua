-- Switches, doors, a hazard, a checkpoint and a timer. The route runs along one floor (y = 1200)
-- from face 0 over its right edge onto face 5 (that edge keeps y, so the floor simply continues;
-- the crossing is ~1300 units from the nearest corner).
--
--   face 0:  start | checkpoint | pit with a hazard floor | switch hanging above the floor  -> edge
--   face 5:  edge -> door 1 (shut while switch 1 is off) | goal | wall
--
-- Tags (scripts/rules/game.lua): 1 hazard, 2 goal, 3 checkpoint, 1000 + n door n, 2000 + n switch n.
-- The switch hangs 250 units above the floor, out of reach when walking: jump into it. Switch 1
-- then holds door 1 open for OPEN_FRAMES only; level.tick counts down and shuts it again.
local level = {}

local FLOOR = 1200
local HAZARD, GOAL, CHECKPOINT = 1, 2, 3
local DOOR, SWITCH = 1000, 2000
local OPEN_FRAMES = 420  -- 7 s: enough to run from the switch to the door, not to dawdle

level.start = { face = 0, x = 500, y = FLOOR + 120 }

function level.build(game)
  local world = game.world
  -- Face 0.
  world.line(0, 200, FLOOR, 200, FLOOR + 1600)                -- back wall
  world.line(0, 200, FLOOR, 1900, FLOOR)                      -- floor up to the pit
  world.line(0, 1200, FLOOR, 1200, FLOOR + 600, CHECKPOINT)   -- checkpoint: a trigger across the floor
  world.line(0, 1900, FLOOR, 1900, FLOOR - 300)               -- the pit: 300 wide, 300 deep,
  world.line(0, 1900, FLOOR - 300, 2200, FLOOR - 300, HAZARD) --   its bottom is deadly
  world.line(0, 2200, FLOOR - 300, 2200, FLOOR)
  world.line(0, 2200, FLOOR, 4096, FLOOR)                     -- floor on to the right edge
  world.line(0, 3000, FLOOR + 250, 3000, FLOOR + 600, SWITCH + 1) -- switch 1, hanging above
  -- Face 5 (its left edge is face 0's right edge, same y).
  world.line(5, 0, FLOOR, 3400, FLOOR)                        -- floor
  world.line(5, 1500, FLOOR, 1500, FLOOR + 1400, DOOR + 1)    -- door 1: far too tall to jump
  world.line(5, 2600, FLOOR, 2600, FLOOR + 800, GOAL)         -- the goal
  world.line(5, 3400, FLOOR, 3400, FLOOR + 1600)              -- end wall
end

local openedAt = nil  -- the frame switch 1 was seen on, while the door is open

function level.tick(game, frame)
  if frame == 1 then game.message("jump into the switch, then run: the door stays open 7 seconds") end
  if game.won() then return end
  local on = game.switchOn(1)
  if on and not openedAt then
    openedAt = frame
  elseif not on then
    openedAt = nil
  end
  if openedAt then
    local left = OPEN_FRAMES - (frame - openedAt)
    if left <= 0 then
      game.toggle(1)  -- applied after this frame; the door stays passable to anyone still in it
      game.message("the door shut: hit the switch again")
    elseif left % 60 == 0 then
      game.message("door open: " .. math.floor(left / 60) .. " s")
    end
  end
end

-- Hot reload: `openedAt` is this module's own state; hand it to the new version of the file.
function level.save() return { openedAt = openedAt } end
function level.onReload(_, saved) openedAt = saved and saved.openedAt end

return level

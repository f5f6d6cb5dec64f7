-- Cube, turning bridge: the lines, start and goal are in cube_bridge.level; this script makes the
-- bridge and turns it. The bridge is a plank over the pit, turning about its middle a quarter turn
-- at a time, always the same way: it lies flat, turns upright, stands, turns flat again (its other
-- end now on the left). Where it should be is a function of the frame alone, so every run is the
-- same; each frame it turns towards that (a turn the player blocks catches up afterwards).
local level = {}

local PIVOT_X, PIVOT_Y = 2100, 1200  -- the pit's middle, at the floor's height
local HALF = 600                     -- the plank spans the pit: 1500 to 2700
local STEP = 1.5                     -- degrees a frame while it turns: a quarter turn in 60 frames
local TURN = 90 / STEP
local FLAT, UPRIGHT = 180, 90        -- frames it lies flat, and stands upright
local PERIOD = FLAT + TURN + UPRIGHT + TURN

local bridge

function level.build(game)
  bridge = game.world.createPlatform(0, { PIVOT_X - HALF, PIVOT_Y, PIVOT_X + HALF, PIVOT_Y })
end

-- Where the bridge should have turned to by frame f (degrees, growing without end), and what to
-- tell the player.
local function wanted(f)
  local cycle, t = math.floor((f - 1) / PERIOD), (f - 1) % PERIOD
  local base = cycle * 180
  if t < FLAT then return base, "the bridge lies flat: cross" end
  t = t - FLAT
  if t < TURN then return base + (t + 1) * STEP, "the bridge turns" end
  t = t - TURN
  if t < UPRIGHT then return base + 90, "the bridge stands: wait" end
  t = t - UPRIGHT
  return base + 90 + (t + 1) * STEP, "the bridge turns"
end

local said
function level.tick(game, frame)
  local want, text = wanted(frame)
  -- The shortest way from where it is to where it should be, at most a step and a half a frame.
  local behind = (want - game.world.platformAngle(bridge)) % 360
  if behind > 180 then behind = behind - 360 end
  game.world.setPlatformSpin(bridge, PIVOT_X, PIVOT_Y, math.max(-1.5 * STEP, math.min(1.5 * STEP, behind)))
  if text ~= said and not game.won() then
    game.message(text)
    said = text
  end
end

return level

-- Cube, lift: the lines, start and goal are in cube_lift.level; this script makes the lift and
-- drives it. The lift is a one-way platform (solid from above only) moved on a fixed cycle: waits
-- at the bottom, rises, waits at the top, comes down. One-way, it passes through anything below
-- it, so it never crushes the player. Jump onto it while it waits at the bottom, wait for the ride
-- up, then walk right onto the ledge.
local level = {}

local LEDGE = 2000
local LIFT_X0, LIFT_X1, LIFT_Y = 2350, 2850, 1250  -- the lift's line at the bottom
local SPEED = 5                                     -- units a frame
local TRAVEL = LEDGE - LIFT_Y                       -- 750: bottom to the ledge's height
local RISE = TRAVEL / SPEED                         -- 150 frames
-- The cycle, in frames: wait at the bottom, rise, wait at the top, come down.
local WAIT_BOTTOM, WAIT_TOP = 240, 180
local PERIOD = WAIT_BOTTOM + RISE + WAIT_TOP + RISE

local lift

function level.build(game)
  -- One line, left to right so that its solid side faces up.
  lift = game.world.createPlatform(0, { LIFT_X0, LIFT_Y, LIFT_X1, LIFT_Y }, 0, "oneway")
end

-- The lift's motion for frame f: from the cycle alone, so it is the same on every run.
local function motion(f)
  local t = (f - 1) % PERIOD
  if t < WAIT_BOTTOM then return 0, "the lift waits below: jump on" end
  t = t - WAIT_BOTTOM
  if t < RISE then return SPEED, "going up" end
  t = t - RISE
  if t < WAIT_TOP then return 0, "the lift waits at the ledge: walk off to the right" end
  return -SPEED, "going down"
end

local said
function level.tick(game, frame)
  local dy, text = motion(frame)
  game.world.setPlatformMotion(lift, 0, dy)
  if text ~= said and not game.won() then
    game.message(text)
    said = text
  end
end

return level

-- Cube, ferry: the lines, start and goal are in cube_ferry.level; this script makes the ferry and
-- drives it. The ferry is a solid platform, flush with the floor at the pit's near side: it waits
-- there, crosses the pit (and face 0's right edge: a platform goes over a face's edge onto the next
-- face and carries what stands on it), waits at the far side, flush with face 1's floor, and comes
-- back. Jump on while it waits, ride it over the edge, walk off at the far side to the goal.
local level = {}

local NEAR_X0, NEAR_X1, Y = 1600, 2200, 1200  -- the ferry's line at the near side (face 0)
local SPEED = 6                                -- units a frame
local TRAVEL = 4096 - NEAR_X0 + 800            -- 3296: its left end to x = 800 on face 1
local CROSS = math.floor(TRAVEL / SPEED)      -- 549 frames (the last 2 units in the frame after)
-- The cycle, in frames: wait at the near side, cross, wait at the far side, come back.
local WAIT_NEAR, WAIT_FAR = 240, 240
local PERIOD = WAIT_NEAR + CROSS + 1 + WAIT_FAR + CROSS + 1

local ferry

function level.build(game)
  ferry = game.world.createPlatform(0, { NEAR_X0, Y, NEAR_X1, Y }, 0, "solid")
end

-- The ferry's speed along its way for frame f (positive: away from the start), from the cycle
-- alone, so it is the same on every run; the last frame of a crossing moves what is left.
local function speed(f)
  local t = (f - 1) % PERIOD
  if t < WAIT_NEAR then return 0, "the ferry waits: jump on" end
  t = t - WAIT_NEAR
  if t < CROSS then return SPEED, "crossing" end
  if t == CROSS then return TRAVEL - CROSS * SPEED, "crossing" end
  t = t - CROSS - 1
  if t < WAIT_FAR then return 0, "the ferry waits at the far side: walk off to the right" end
  t = t - WAIT_FAR
  if t < CROSS then return -SPEED, "coming back" end
  return -(TRAVEL - CROSS * SPEED), "coming back"
end

local said
function level.tick(game, frame)
  local v, text = speed(frame)
  -- Along face 0's x, on whichever face the ferry is now (face 0's right edge keeps y, so face 1's
  -- x runs the same way).
  game.world.setPlatformMotion(ferry, v, 0)
  if text ~= said and not game.won() then
    game.message(text)
    said = text
  end
end

return level

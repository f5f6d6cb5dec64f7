-- A lift. The route starts on face 0's floor (y = 1200); the goal is up on a ledge (y = 2000),
-- 800 units up where no jump reaches (a jump rises ~170). The ledge runs over face 0's right edge
-- onto face 5 (that edge keeps y; the crossing is ~2000 units from either corner).
--
--   face 0:  start | lift (up and down between y = 1250 and the ledge's height) | ledge -> edge
--            (a room under the ledge: floor, and a wall at x = 3800 below the ledge)
--   face 5:  edge -> ledge | goal | wall
--
-- The lift is a one-way platform (solid from above only) moved by level.tick on a fixed cycle:
-- waits at the bottom, rises, waits at the top, comes down. One-way, it passes through anything
-- below it, so it never crushes the player. Jump onto it while it waits at the bottom, wait for the
-- ride up, then walk right onto the ledge.
local level = {}

local FLOOR, LEDGE = 1200, 2000
local GOAL = 2
local LIFT_X0, LIFT_X1, LIFT_Y = 2350, 2850, 1250  -- the lift's line at the bottom
local SPEED = 5                                     -- units a frame
local TRAVEL = LEDGE - LIFT_Y                       -- 750: bottom to the ledge's height
local RISE = TRAVEL / SPEED                         -- 150 frames
-- The cycle, in frames: wait at the bottom, rise, wait at the top, come down.
local WAIT_BOTTOM, WAIT_TOP = 240, 180
local PERIOD = WAIT_BOTTOM + RISE + WAIT_TOP + RISE

level.start = { face = 0, x = 600, y = FLOOR + 120 }

local lift

function level.build(game)
  local world = game.world
  -- Face 0.
  world.line(0, 200, FLOOR, 200, FLOOR + 1600)   -- back wall
  world.line(0, 200, FLOOR, 3800, FLOOR)         -- floor
  world.line(0, 3800, FLOOR, 3800, LEDGE)        -- the room's wall, under the ledge
  world.line(0, 2900, LEDGE, 4096, LEDGE)        -- the ledge, on to the right edge
  -- The lift: one line, left to right so that its solid side faces up.
  lift = world.createPlatform(0, { LIFT_X0, LIFT_Y, LIFT_X1, LIFT_Y }, 0, "oneway")
  -- Face 5 (its left edge is face 0's right edge, same y).
  world.line(5, 0, LEDGE, 1600, LEDGE)           -- the ledge goes on
  world.line(5, 1000, LEDGE, 1000, LEDGE + 700, GOAL)
  world.line(5, 1600, LEDGE, 1600, LEDGE + 1600) -- end wall
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

-- The player (trusted): a small sphere that walks, jumps and falls along its face's "down".
-- Velocities are in units per frame; the face's gravity gives "down", so when the player crosses
-- onto another face (and the world turns its velocity into that face's frame), down turns too.
local game = ...  -- luacheck: no unused (the game state: this player needs none, a copy of it may)
-- Private copies: nothing a script does to a table can swap what this file calls.
local world, draw = platon.world, platon.draw
local createEntity, insert, destroyEntity = world.createEntity, world.insert, world.destroyEntity
local position, gravity, contactCount, contact = world.position, world.gravity, world.contactCount, world.contact
local velocity, setVelocity = world.velocity, world.setVelocity
local look = draw.look
local play = platon.sound.play
local sqrt, min, max, pcall, error, setmetatable = math.sqrt, math.min, math.max, pcall, error, setmetatable

local Player = {}
Player.__index = Player

Player.RADIUS = 96          -- units
Player.COLOUR = 0xf2c14e    -- gold
Player.WALK_SPEED = 9       -- units per frame
Player.GROUND_ACCEL = 0.6   -- per frame, towards the walk speed
Player.GROUND_BRAKE = 0.9   -- per frame, towards standing still with no input
Player.AIR_ACCEL = 0.35
Player.JUMP_SPEED = 11      -- units per frame, straight up from the face's down
Player.JUMP_CUT = 4         -- releasing jump while rising from a jump caps the upward speed here
Player.COYOTE_FRAMES = 6    -- a jump still works this long after leaving a ledge
Player.BUFFER_FRAMES = 6    -- a jump pressed this long before landing happens on landing
Player.GROUND_COS = 0.64    -- a contact whose normal is within ~50 degrees of up is ground
Player.WALL_COS = 0.9       -- one within ~25 degrees of sideways is a wall; self.wall: the way off it (1, -1)
Player.LAND_SPEED = 2.5     -- units per frame: a landing from a fall this fast or faster is heard
Player.LAND_SQUASH = 0.7    -- the ball's height over its width on a hard landing (drawn only)
Player.JUMP_STRETCH = 1.3   -- and at a jump's start
Player.SQUASH_EASE = 0.7    -- each frame the squash keeps this much of its way back to 1

-- Errors (leaving nothing behind) when the place is taken by a wall or the face does not exist.
-- `degrees`: the ball's turn (a hot reload puts it back as it was: the ball is a 16-gon).
function Player.spawn(_, face, x, y, degrees)
  local e = createEntity { circle = Player.RADIUS, sides = 16 }
  local ok, err = pcall(insert, e, face, x, y, degrees or 0)
  if not ok then
    destroyEntity(e)
    error(err, 2)
  end
  look(e, Player.COLOUR, "ball")  -- the engine draws it, once, however many faces it spans
  return setmetatable({ entity = e, coyote = 0, buffer = 0, grounded = false, wall = 0, jumping = false, face = face,
                        fall = 0, squash = 1, facing = 1, downX = 0, downY = -1, rightX = 1, rightY = 0 }, Player)
end

local function approach(value, target, step)
  if value < target then return min(value + step, target) end
  return max(value - step, target)
end

function Player.tick(self, input)
  local e = self.entity
  local part = position(e)
  local gx, gy = gravity(part)
  local g = sqrt(gx * gx + gy * gy)
  local dx, dy = 0, -1  -- down
  if g > 0 then dx, dy = gx / g, gy / g end
  local rx, ry = -dy, dx  -- right
  -- The face's directions this frame, for what extends the player (a dash goes along right).
  self.downX, self.downY, self.rightX, self.rightY = dx, dy, rx, ry

  -- Over an edge: the world turned, and the player hears it.
  if part ~= self.face then
    if self.face ~= nil then play("cross") end
    self.face = part
  end

  local wasGrounded = self.grounded
  self.grounded, self.wall = false, 0
  for i = 1, contactCount(e) do
    local nx, ny = contact(e, i)
    if -(nx * dx + ny * dy) > Player.GROUND_COS then self.grounded = true end
    local side = nx * rx + ny * ry  -- a wall's normal points away from it, along right or left
    if side > Player.WALL_COS then self.wall = 1 elseif side < -Player.WALL_COS then self.wall = -1 end
  end
  -- The fall speed the frame before this one's contact stopped it: louder the harder it lands.
  if self.grounded and not wasGrounded and (self.fall or 0) > Player.LAND_SPEED then
    play("land", min(1, self.fall / 12))
    self.squash = Player.LAND_SQUASH
  end
  if self.grounded then self.coyote = Player.COYOTE_FRAMES elseif self.coyote > 0 then self.coyote = self.coyote - 1 end
  if input.pressed.jump then
    self.buffer = Player.BUFFER_FRAMES
  elseif self.buffer > 0 then
    self.buffer = self.buffer - 1
  end

  local vx, vy = velocity(e)
  local along = vx * rx + vy * ry
  local fall = vx * dx + vy * dy  -- > 0: falling

  local dir = (input.right and 1 or 0) - (input.left and 1 or 0)
  if dir ~= 0 then self.facing = dir end
  local accel = self.grounded and Player.GROUND_ACCEL or Player.AIR_ACCEL
  if dir ~= 0 then
    along = approach(along, dir * Player.WALK_SPEED, accel)
  elseif self.grounded then
    along = approach(along, 0, Player.GROUND_BRAKE)
  end

  -- The jump cut shortens the player's own jump only: a rise a springboard, a rule or a script
  -- gave it is its to keep.
  if self.grounded or fall >= 0 then self.jumping = false end
  if self.buffer > 0 and self:canJump() then
    along, fall = self:jump(along)
    self.buffer, self.coyote, self.jumping = 0, 0, true
    play("jump")
    self.squash = Player.JUMP_STRETCH
  elseif self.jumping and not input.jump and fall < -Player.JUMP_CUT then
    fall = -Player.JUMP_CUT
  end

  along, fall = self:move(input, along, fall)
  setVelocity(e, rx * along + dx * fall, ry * along + dy * fall)
  self.fall = fall
  -- Squash and stretch: the picture's, eased back to round (a look is never the simulation's).
  local squash = self.squash or 1
  if squash ~= 1 then
    squash = 1 + (squash - 1) * Player.SQUASH_EASE
    if squash > 0.99 and squash < 1.01 then squash = 1 end
    self.squash = squash
    look(e, Player.COLOUR, "ball", squash)
  end
end

-- Whether a jump asked for now happens: on the ground, or just off it (coyote time). Asked only
-- while a jump is wanted (pressed, or buffered). A double jump or a wall jump overrides it.
function Player.canJump(self) return self.coyote > 0 end

-- The jump: the speed along the face (+ right) and the fall speed (- up) it starts with, from the
-- speed along the face before it. A wall jump overrides it to push off the wall.
function Player.jump(_, along) return along, -Player.JUMP_SPEED end

-- The frame's last word on the speeds, after walking, the jump and its cut: along the face (+
-- right) and the fall (- up), returned as they are to be. Walking takes `along` back towards the
-- walk speed by GROUND_ACCEL (in the air AIR_ACCEL) a frame, and braking by GROUND_BRAKE with no
-- direction held; gravity adds to `fall` after it. A dash, a glide or a dive overrides it.
function Player.move(_, _, along, fall) return along, fall end

-- The engine draws the player's body by its look (set in spawn): a player that wants more (a
-- face, a trail) draws it here with platon.draw.
function Player.draw(_) end

return Player

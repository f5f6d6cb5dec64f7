-- Cube, switches: the lines, start and goal are in cube_switches.level. This script runs the
-- timer: switch 1 holds door 1 open for OPEN_FRAMES only; level.tick counts down and shuts it.
local level = {}

local OPEN_FRAMES = 420  -- 7 s: enough to run from the switch to the door, not to dawdle

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

-- The campaign's first switch, door and checkpoint say what they are where they stand.
function level.draw(_, draw)
  draw.text(0, 650, 2050, "checkpoint", 140, 0x80f0a0)
  draw.text(0, 2550, 2150, "switch: opens door 1", 140, 0xffe060)
  draw.text(1, 1100, 2850, "door 1", 120, 0xffe060)
end

-- Hot reload: `openedAt` is this module's own state; hand it to the new version of the file.
function level.save() return { openedAt = openedAt } end
function level.onReload(_, saved) openedAt = saved and saved.openedAt end

return level

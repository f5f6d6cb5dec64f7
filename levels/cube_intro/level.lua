-- Cube, first steps: the lines, start and goal are in cube_intro.level; this script only talks.
-- The campaign's first level teaches the controls where the player stands, and names the goal
-- where it waits.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("walk right: every edge turns the cube")
end

local WHITE, GOLD = 0xffffff, 0xffe080

function level.draw(_, draw)
  -- Text heights and gaps in face units: each line's top is a line and a half below the last.
  draw.text(0, 300, 1750, "Left/Right or A/D: walk", 150, WHITE)
  draw.text(0, 300, 1520, "Space: jump (hold it to jump higher)", 150, WHITE)
  draw.text(0, 300, 1290, "R: back to the last checkpoint   Esc: pause", 120, WHITE)
  draw.text(2, 1650, 1350, "GOAL: touch it", 140, GOLD)
end

return level

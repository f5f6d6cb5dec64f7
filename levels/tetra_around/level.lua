-- Tetrahedron, around: the lines, start and goal are in tetra_around.level; this script talks.
-- The campaign's first hazard says what it is where it lies.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("walk right: each edge tips you onto the next face")
end

function level.draw(_, draw)
  draw.text(1, 1250, 800, "spiked floor: deadly, jump it", 130, 0xff7060)
end

return level

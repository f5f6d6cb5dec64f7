local ffi, address, callbacks = ...
if not pcall(ffi.typeof, "struct platon_contact_slot") then
  ffi.cdef "struct platon_contact_slot { double entity, tag, kind, part, line, nx, ny, other, answer; };"
end
local c = ffi.cast("struct platon_contact_slot*", address)
local sqrt = math.sqrt
local KINDS = { [0] = "solid", "warp", "oneway", "entity" }
local out = {}
local pierce, contact = callbacks.pierce, callbacks.contact
if pierce then
  out.pierce = function()
    local line = c.line
    if line < 0 then line = nil end
    return pierce(c.entity, c.tag, KINDS[c.kind], c.part, line)
  end
end
if contact then
  out.contact = function()
    local line, other = c.line, c.other
    if line < 0 then line = nil end
    if other < 0 then other = nil end
    -- The slot holds the normal as it is; it is made a unit vector here, with the operations of
    -- lua::unitNormal in the same order (same doubles), so that a callback that ignores it does
    -- not pay for the square root: the JIT drops unused work.
    local x, y = c.nx, c.ny
    local length = sqrt(x * x + y * y)
    local nx, ny = 0, 0
    if length > 0 then nx, ny = x / length, y / length end
    -- The usual answers go back in the slot, so that the call returns nothing to read: nil (the
    -- defaults) 0, false 1, true 2; anything else (a response table) is returned, answer 3.
    local r = contact(c.entity, c.tag, KINDS[c.kind], c.part, line, nx, ny, other)
    if r == nil then c.answer = 0 return end
    if r == false then c.answer = 1 return end
    if r == true then c.answer = 2 return end
    c.answer = 3
    return r
  end
end
for _, name in ipairs { "beginContact", "overContact", "endContact", "touchContact", "crushed" } do
  local f = callbacks[name]
  if f then
    out[name] = function()
      local line, other = c.line, c.other
      if line < 0 then line = nil end
      if other < 0 then other = nil end
      return f(c.entity, c.tag, KINDS[c.kind], c.part, line, other)
    end
  end
end
return out

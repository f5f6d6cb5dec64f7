// How the engine draws an entity of the world, set by scripts (platon.draw.look): a colour and a
// form. Every entity is drawn from the world's own views each frame, so a crate a level makes shows
// with no drawing code of its own; a look only changes how. Looks are the picture's, never the
// simulation's: they are not in the state hash.
#pragma once
#include <cstdint>
#include <unordered_map>

#include "platon/core/draw_list.h"
#include "platon/physics/ids.h"

namespace platon::core {

struct Look {
  enum class Form : uint8_t {
    Shape,  // its polygon, as the physics has it, cut at each face's edges (the default)
    Ball,   // a ball of the polygon's radius, drawn once, on the face that holds its centre
    None,   // not drawn (a script draws it itself)
  };
  Color color{176, 138, 90, 255};  // a crate's wood
  Form form = Form::Shape;
  float squash = 1;  // a ball's height over its width (DrawShape::squash): squash and stretch
};

// The looks scripts set, by entity; an entity with none (or a destroyed one's handle) has the default.
class Looks {
 public:
  void set(physics::EntityId id, Look look) { looks_[id.index] = {id.generation, look}; }
  Look of(physics::EntityId id) const {
    const auto it = looks_.find(id.index);
    return it != looks_.end() && it->second.generation == id.generation ? it->second.look : Look{};
  }
  void clear() { looks_.clear(); }

 private:
  struct Entry {
    uint32_t generation;
    Look look;
  };
  std::unordered_map<uint32_t, Entry> looks_;
};

}  // namespace platon::core

// Read-only views of an entity, for scripts and the renderer: cheap to take every frame, no
// allocation. A view reads the world's own storage, so it is valid until the next call that
// changes the world (solve, insert, erase, rotate, create, destroy); take a fresh one each frame.
// Handles (EntityId) stay valid for the entity's whole life.
#pragma once
#include <cstddef>
#include <iterator>
#include <optional>
#include <span>

#include "platon/physics/convex.h"
#include "platon/physics/ids.h"
#include "platon/physics/rules.h"

namespace platon::physics {

struct Entity;  // the solver's own (physics/src/entity.h)

// One copy of the entity in one map part. While an entity straddles a warp edge it has an instance
// on each side of it; instance 0, the anchor, defines the entity's frame.
struct InstanceView {
  MapPartId part = 0;
  Vec2 position;                // the entity origin, in the part's coordinates
  Angle frame = 0;              // turn from the entity's frame into this part's (0 for the anchor)
  Angle angle = 0;              // the shape's rotation in this part: the entity's angle + frame
  std::span<const Vec2> shape;  // vertices relative to `position`, turned by `angle` and rounded
};

class EntityView {
 public:
  EntityId id() const;
  const Convex& shape() const;      // as created, unturned
  Angle angle() const;              // the shape's rotation in the entity's (the anchor's) frame
  Vec2w velocity() const;           // 1/65536 units per frame, in the entity's frame
  Vec2w subunit() const;            // motion below one unit carried to the next frame: 1/131072 units
  int32_t angularVelocity() const;  // binary-angle units per frame
  bool gravityEnabled() const;
  uint64_t userData() const;
  const EntityFilter& filter() const;

  // Instances: none before insert(), one on a face, two or more across warp edges.
  size_t instanceCount() const;
  bool inserted() const { return instanceCount() > 0; }
  InstanceView instance(size_t index) const;  // 0 is the anchor; throws Error when out of range
  std::optional<InstanceView> instanceIn(MapPartId part) const;
  // The anchor's part and position: where the entity "is".
  MapPartId part() const { return instance(0).part; }
  Vec2 position() const { return instance(0).position; }

  // Solid contacts of the latest solve(), in the order they happened (what Rules::contact saw).
  std::span<const Contact> contacts() const;
  // Its share of the latest solve()'s work: the lines, platform lines and bodies its moves were
  // tested against (SolveReport::tested), and a fixed amount for its step (as much as 16 tests).
  uint32_t work() const;

  class Instances;
  Instances instances() const;  // for (InstanceView i : view.instances())

  explicit EntityView(const Entity& entity) : entity_(&entity) {}

 private:
  const Entity* entity_;
};

class EntityView::Instances {
 public:
  class iterator {
   public:
    using value_type = InstanceView;
    using difference_type = std::ptrdiff_t;
    iterator() = default;
    iterator(const Entity* entity, size_t index) : entity_(entity), index_(index) {}
    InstanceView operator*() const { return EntityView(*entity_).instance(index_); }
    iterator& operator++() { return ++index_, *this; }
    iterator operator++(int) {
      iterator was = *this;
      ++index_;
      return was;
    }
    friend bool operator==(const iterator& a, const iterator& b) { return a.index_ == b.index_; }

   private:
    const Entity* entity_ = nullptr;
    size_t index_ = 0;
  };
  explicit Instances(const Entity& entity) : entity_(&entity) {}
  iterator begin() const { return {entity_, 0}; }
  iterator end() const { return {entity_, EntityView(*entity_).instanceCount()}; }
  size_t size() const { return EntityView(*entity_).instanceCount(); }
  InstanceView operator[](size_t i) const { return EntityView(*entity_).instance(i); }

 private:
  const Entity* entity_;
};

inline EntityView::Instances EntityView::instances() const { return Instances(*entity_); }

}  // namespace platon::physics

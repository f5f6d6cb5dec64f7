// The read-only views of an entity: thin reads of the solver's own storage.
#include "platon/physics/entity_view.h"

#include "entity.h"

namespace platon::physics {

EntityId EntityView::id() const { return entity_->id; }
const Convex& EntityView::shape() const { return entity_->shape; }
Angle EntityView::angle() const { return entity_->angle; }
Vec2w EntityView::velocity() const { return entity_->velocityQ16; }
Vec2w EntityView::subunit() const { return entity_->subunitQ17; }
int32_t EntityView::angularVelocity() const { return entity_->angularVelocity; }
bool EntityView::gravityEnabled() const { return entity_->gravity; }
uint64_t EntityView::userData() const { return entity_->userData; }
const EntityFilter& EntityView::filter() const { return entity_->filter; }
size_t EntityView::instanceCount() const { return entity_->instances.size(); }
std::span<const Contact> EntityView::contacts() const { return entity_->contactsOf(); }
uint32_t EntityView::work() const { return entity_->work; }

namespace {
InstanceView viewOf(const Entity& e, const Instance& inst) {
  return {inst.part, inst.position, inst.frame, static_cast<Angle>(e.angle + inst.frame), inst.shape};
}
}  // namespace

InstanceView EntityView::instance(size_t index) const {
  if (index >= entity_->instances.size())
    throw Error("entity " + std::to_string(entity_->id.index) + " has " + std::to_string(entity_->instances.size()) +
                " instances; there is no instance " + std::to_string(index));
  return viewOf(*entity_, entity_->instances[index]);
}

std::optional<InstanceView> EntityView::instanceIn(MapPartId part) const {
  const Instance* inst = entity_->instanceIn(part);
  if (!inst) return std::nullopt;
  return viewOf(*entity_, *inst);
}

}  // namespace platon::physics

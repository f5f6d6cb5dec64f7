#include "platon/core/scene.h"

namespace platon::core {

void Scene::addSystem(std::unique_ptr<System> system) { systems_.push_back(std::move(system)); }

physics::SolveReport Scene::step(const InputFrame& input) {
  for (const auto& s : systems_) s->beforeStep(*this, input);
  const physics::SolveReport report = world_.solve();
  for (const auto& s : systems_) s->afterStep(*this);
  return report;
}

void Scene::draw(DrawList& out) const {
  if (!out.enabled()) return;
  for (const auto& s : systems_) s->draw(*this, out);
}

}  // namespace platon::core

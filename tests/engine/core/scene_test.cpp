// Scenes run their systems around the physics step; the registry creates only what is named;
// draw lists record nothing without a renderer; input edges.
#include "platon/core/scene.h"

#include <gtest/gtest.h>

using namespace platon;

namespace {

// Records the order of calls, and sets a velocity before the step.
class Probe : public core::System {
 public:
  Probe(std::vector<std::string>& log, std::string name) : log_(log), name_(std::move(name)) {}
  void beforeStep(core::Scene& scene, const core::InputFrame& input) override {
    log_.push_back(name_ + " before " + std::to_string(scene.frame()) +
                   (input.wasPressed(core::Button::Jump) ? " jump" : ""));
  }
  void afterStep(core::Scene& scene) override { log_.push_back(name_ + " after " + std::to_string(scene.frame())); }
  void draw(const core::Scene&, core::DrawList& out) const override {
    out.circle(core::Place::onFace(3), {1, 2}, 5, {255, 0, 0, 255});
    out.text(core::Place::onScreen(), {10, 10}, "deaths: 0", 16, {});
  }

 private:
  std::vector<std::string>& log_;
  std::string name_;
};

}  // namespace

TEST(Scene, SystemsRunInOrderAroundThePhysicsStep) {
  std::vector<std::string> log;
  core::Scene scene;
  scene.addSystem(std::make_unique<Probe>(log, "a"));
  scene.addSystem(std::make_unique<Probe>(log, "b"));
  core::InputEdges edges;
  scene.step(edges.next(core::InputFrame::bit(core::Button::Jump)));
  scene.step(edges.next(core::InputFrame::bit(core::Button::Jump)));  // held, not pressed again
  EXPECT_EQ(log, (std::vector<std::string>{"a before 0 jump", "b before 0 jump", "a after 1", "b after 1", "a before 1",
                                           "b before 1", "a after 2", "b after 2"}));
}

TEST(Scene, DrawListsRecordOnlyWhenARendererAsks) {
  std::vector<std::string> log;
  core::Scene scene;
  scene.addSystem(std::make_unique<Probe>(log, "a"));
  core::DrawList headless;
  scene.draw(headless);
  EXPECT_TRUE(headless.shapes().empty());
  core::DrawList drawn(true);
  scene.draw(drawn);
  ASSERT_EQ(drawn.shapes().size(), 2u);
  EXPECT_EQ(drawn.shapes()[0].kind, core::ShapeKind::Circle);
  EXPECT_EQ(drawn.shapes()[0].place.face, 3u);
  EXPECT_EQ(drawn.shapes()[0].size, 5.0f);
  EXPECT_EQ(drawn.text(drawn.shapes()[1]), "deaths: 0");
  EXPECT_TRUE(drawn.shapes()[1].place.screen);
  drawn.clear();
  EXPECT_TRUE(drawn.shapes().empty());
}

TEST(SystemRegistry, CreatesOnlyWhatIsNamedAndNamesWhatIsKnown) {
  core::SystemRegistry registry;
  int created = 0;
  std::vector<std::string> log;
  registry.add("probe", [&](core::Scene&) {
    ++created;
    return std::make_unique<Probe>(log, "p");
  });
  registry.add("other",
               [&](core::Scene&) -> std::unique_ptr<core::System> { throw std::logic_error("never created"); });
  EXPECT_THROW(registry.add("probe", {}), std::invalid_argument);
  core::Scene scene;
  scene.addSystem(registry.create("probe", scene));
  EXPECT_EQ(created, 1);
  try {
    registry.create("render", scene);
    FAIL() << "no error for an unknown system";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown system 'render' (known: probe, other)");
  }
}

TEST(Input, ButtonNamesRoundTrip) {
  for (int i = 0; i < core::kButtonCount; ++i) {
    core::Button b{};
    ASSERT_TRUE(core::buttonFromName(core::buttonName(static_cast<core::Button>(i)), b));
    EXPECT_EQ(static_cast<int>(b), i);
  }
  core::Button b{};
  EXPECT_FALSE(core::buttonFromName("fire", b));
}

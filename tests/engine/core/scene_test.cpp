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

TEST(Actions, TheEnginesAreInButtonsOrderAndAModAddsItsOwnByName) {
  const std::vector<core::Action>& engine = core::engineActions();
  ASSERT_EQ(engine.size(), static_cast<size_t>(core::kButtonCount));
  EXPECT_EQ(core::actionIndex(engine, "jump"), static_cast<int>(core::Button::Jump));
  EXPECT_EQ(core::actionIndex(engine, "reload"), static_cast<int>(core::Button::Reload));
  EXPECT_EQ(core::actionIndex(engine, "fire"), std::nullopt);
  for (const core::Action& a : engine) EXPECT_TRUE(core::isActionName(a.name)) << a.name;
  std::vector<core::Action> actions = engine;
  core::addAction(actions, {"dash", "", {"X"}, {"x"}, "a dash", true, "dash.lua"});
  EXPECT_EQ(actions.back().label, "dash");  // none given: its name
  const std::pair<core::Action, std::string> refused[] = {
      {{"jump", "", {}, {}, "", true, "m.lua"}, "the action 'jump' is the engine's"},
      {{"dash", "", {}, {}, "", true, "m.lua"}, "the action 'dash' is dash.lua's"},
      {{"2fast", "", {}, {}, "", true, "m.lua"}, "'2fast' is no action name"},
      {{"pressed", "", {}, {}, "", true, "m.lua"}, "'pressed' is input.pressed"},
      {{"", "", {}, {}, "", true, "m.lua"}, "'' is no action name"},
  };
  for (const auto& [action, error] : refused) {
    try {
      core::addAction(actions, action);
      ADD_FAILURE() << action.name << " was added";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(error), std::string::npos) << e.what();
    }
  }
  for (int i = 0; i < 7; ++i) core::addAction(actions, {"a" + std::to_string(i), "", {}, {}, "", true, "m.lua"});
  try {
    core::addAction(actions, {"one_more", "", {}, {}, "", true, "m.lua"});
    ADD_FAILURE() << "a 17th action was added";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("more than 8 actions added"), std::string::npos) << e.what();
  }
}

// The settings' choices replace an action's defaults, never a tool's (reload stays F5).
TEST(Actions, BindingsAreTheDefaultsWithThePlayersChoices) {
  core::BindingChoices choices;
  choices.keys["jump"] = {"K"};
  choices.pad["left"] = {"leftshoulder"};
  choices.keys["reload"] = {"Q"};
  const core::KeyBindings b = core::bindingsFor(core::engineActions(), choices);
  EXPECT_EQ(b.keys[static_cast<size_t>(core::Button::Jump)], std::vector<std::string>{"K"});
  EXPECT_EQ(b.pad[static_cast<size_t>(core::Button::Jump)], (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(b.pad[static_cast<size_t>(core::Button::Left)], std::vector<std::string>{"leftshoulder"});
  EXPECT_EQ(b.keys[static_cast<size_t>(core::Button::Left)], (std::vector<std::string>{"Left", "A"}));
  EXPECT_EQ(b.keys[static_cast<size_t>(core::Button::Reload)], std::vector<std::string>{"F5"});
}

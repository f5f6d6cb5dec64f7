// Gamepads through SDL's game-controller API, plugged in while the game runs: SDL's virtual
// joystick stands in for a real pad. Once attached, the window picks it up (no restart), its A
// button is a press of Enter for the menus and holds Jump for the player, the stick moves, Start
// pauses; unplugged, it is let go and nothing stays held.
#include <SDL2/SDL.h>
#include <algorithm>
#include <cstdlib>

#include <gtest/gtest.h>

#include "platon/core/display.h"
#include "platon/core/input.h"
#include "platon/core/scene.h"
#include "platon/testing/temp_folder.h"

using namespace platon;

namespace {

bool has(const core::WindowInput& in, core::Key k) {
  return std::find(in.pressed.begin(), in.pressed.end(), k) != in.pressed.end();
}

TEST(Gamepad, PluggedInWhileRunningItDrivesTheMenusAndThePlayer) {
  setenv("SDL_VIDEODRIVER", "offscreen", 1);
  // SDL drops pad input while no window has the focus (right for the game); an offscreen window
  // never has it.
  setenv("SDL_JOYSTICK_ALLOW_BACKGROUND_EVENTS", "1", 1);
  platon::testing::TempFolder folder("gamepad");
  core::SystemRegistry registry;
  registry.addPlugin("rendering", "platon_render", {PLATON_PLUGIN_DIR});
  auto scene =
      core::loadScene(folder.write("scene.lua", "return { name = 'pad', systems = { 'rendering' } }"), registry);
  core::Display& display = *scene->findSystem("rendering")->display();
  display.setBindings(core::bindingsFor(core::engineActions()));  // what a Session binds
  display.pollEvents();                                           // the window is open, no pad yet
  ASSERT_EQ(SDL_InitSubSystem(SDL_INIT_JOYSTICK), 0) << SDL_GetError();

  SDL_VirtualJoystickDesc desc{};
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
  desc.naxes = SDL_CONTROLLER_AXIS_MAX;
  desc.nbuttons = 15;                 // A .. DPAD_RIGHT
  desc.button_mask = (1u << 15) - 1;  // virtual button i is controller button i
  desc.axis_mask = (1u << SDL_CONTROLLER_AXIS_MAX) - 1;
  desc.name = "test pad";
  const int device = SDL_JoystickAttachVirtualEx(&desc);
  ASSERT_GE(device, 0) << SDL_GetError();
  ASSERT_TRUE(SDL_IsGameController(device)) << "the virtual pad has no controller mapping";
  SDL_Joystick* pad = SDL_JoystickOpen(device);
  ASSERT_NE(pad, nullptr) << SDL_GetError();
  display.pollEvents();  // the "added" event: the window opens the pad
  ASSERT_NE(SDL_GameControllerFromInstanceID(SDL_JoystickInstanceID(pad)), nullptr)
      << "the window did not open the pad";

  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_A, 1);
  SDL_JoystickSetVirtualAxis(pad, SDL_CONTROLLER_AXIS_LEFTX, 30000);  // the stick right
  SDL_JoystickUpdate();
  core::WindowInput in = display.pollEvents();
  EXPECT_TRUE(has(in, core::Key::Enter)) << "A is Enter in the menus";
  EXPECT_EQ(in.lastPadButton, "a") << "the settings screen binds the button it names";
  EXPECT_TRUE(in.held & core::InputFrame::bit(core::Button::Jump)) << "A held is Jump";
  EXPECT_TRUE(in.held & core::InputFrame::bit(core::Button::Right)) << "the stick right is Right";
  EXPECT_FALSE(in.held & core::InputFrame::bit(core::Button::Left));

  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_A, 0);
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_START, 1);
  SDL_JoystickSetVirtualAxis(pad, SDL_CONTROLLER_AXIS_LEFTX, 0);
  SDL_JoystickUpdate();
  in = display.pollEvents();
  EXPECT_TRUE(has(in, core::Key::Escape)) << "Start pauses";
  EXPECT_FALSE(in.held & core::InputFrame::bit(core::Button::Jump));
  EXPECT_FALSE(in.held & core::InputFrame::bit(core::Button::Right)) << "the stick back in the middle";

  // The d-pad, then unplugged: the window lets the pad go (its handle closed), nothing held.
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_START, 0);
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_DPAD_LEFT, 1);
  SDL_JoystickUpdate();
  in = display.pollEvents();
  EXPECT_TRUE(in.held & core::InputFrame::bit(core::Button::Left)) << "the d-pad left is Left";

  // Rebound (the player's settings): X jumps and A no longer does (it still is Enter for the menus);
  // a name SDL does not know binds nothing and is returned.
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_DPAD_LEFT, 0);
  // A mod's action (bit 8) is bound like the engine's.
  core::BindingChoices choices;
  choices.pad["jump"] = {"x", "nosuchbutton"};
  std::vector<core::Action> actions = core::engineActions();
  core::addAction(actions, {"dash", "Dash", {"X"}, {"rightshoulder"}, "", true, "dash.lua"});
  EXPECT_EQ(display.setBindings(core::bindingsFor(actions, choices)), std::vector<std::string>{"nosuchbutton"});
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_X, 1);
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, 1);
  SDL_JoystickUpdate();
  in = display.pollEvents();
  EXPECT_TRUE(in.held & core::InputFrame::bit(core::Button::Jump)) << "X bound to Jump";
  EXPECT_TRUE(in.held & (1u << 8)) << "the right shoulder holds the mod's dash";
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, 0);
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_X, 0);
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_A, 1);
  SDL_JoystickUpdate();
  in = display.pollEvents();
  EXPECT_FALSE(in.held & core::InputFrame::bit(core::Button::Jump)) << "A is no longer Jump";
  EXPECT_TRUE(has(in, core::Key::Enter)) << "A is still Enter in the menus";
  SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_A, 0);
  SDL_JoystickUpdate();
  display.setBindings(core::bindingsFor(core::engineActions()));
  const SDL_JoystickID id = SDL_JoystickInstanceID(pad);
  SDL_JoystickClose(pad);
  ASSERT_EQ(SDL_JoystickDetachVirtual(device), 0) << SDL_GetError();
  in = display.pollEvents();
  EXPECT_EQ(in.held, 0) << "an unplugged pad holds nothing";
  EXPECT_EQ(SDL_GameControllerFromInstanceID(id), nullptr) << "the window did not close the unplugged pad";
}

}  // namespace

// A tap shorter than a frame (a key or a pad button pressed and released between two polls) is
// in the poll's taps though it is not held any more; TapCarry then plays it on the next frame.
TEST(Taps, APressAndReleaseBetweenTwoPollsIsATap) {
  setenv("SDL_VIDEODRIVER", "offscreen", 1);
  platon::testing::TempFolder folder("taps");
  core::SystemRegistry registry;
  registry.addPlugin("rendering", "platon_render", {PLATON_PLUGIN_DIR});
  auto scene =
      core::loadScene(folder.write("scene.lua", "return { name = 'taps', systems = { 'rendering' } }"), registry);
  core::Display& display = *scene->findSystem("rendering")->display();
  display.setBindings(core::bindingsFor(core::engineActions()));  // what a Session binds
  display.pollEvents();                                           // the window is open
  const std::pair<SDL_Scancode, core::Button> keys[] = {{SDL_SCANCODE_SPACE, core::Button::Jump},
                                                        {SDL_SCANCODE_A, core::Button::Left},
                                                        {SDL_SCANCODE_RIGHT, core::Button::Right},
                                                        {SDL_SCANCODE_R, core::Button::Restart}};
  for (const auto& [scancode, button] : keys) {
    for (const Uint32 type : {SDL_KEYDOWN, SDL_KEYUP}) {
      SDL_Event e{};
      e.type = type;
      e.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
      e.key.keysym.scancode = scancode;
      e.key.keysym.sym = SDL_GetKeyFromScancode(scancode);
      ASSERT_EQ(SDL_PushEvent(&e), 1) << SDL_GetError();
    }
    const core::WindowInput in = display.pollEvents();
    const core::Buttons bit = core::InputFrame::bit(button);
    EXPECT_FALSE(in.held & bit) << scancode << ": released before the poll";
    EXPECT_TRUE(in.tapped & bit) << scancode << ": the tap is lost";
    core::TapCarry carry;
    carry.add(in.tapped);
    carry.add(0);  // a poll with no frame played after it: the tap waits
    EXPECT_TRUE(carry.next(in.held) & bit) << "the next frame plays the tap";
    EXPECT_FALSE(carry.next(in.held) & bit) << "once";
  }
  // The window losing the keyboard says so (the game pauses on it).
  SDL_Event e{};
  e.type = SDL_WINDOWEVENT;
  e.window.event = SDL_WINDOWEVENT_FOCUS_LOST;
  ASSERT_EQ(SDL_PushEvent(&e), 1) << SDL_GetError();
  EXPECT_TRUE(display.pollEvents().focusLost);
  EXPECT_FALSE(display.pollEvents().focusLost);
}

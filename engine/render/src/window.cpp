#include "window.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <epoxy/gl.h>
#include <optional>
#include <stdexcept>

#include "platon/core/input.h"

namespace platon::render {
namespace {

using core::Button;
using core::InputFrame;

// Starts SDL's video on a screen. With no display to reach (DISPLAY unset, or a server that turns us
// away) SDL falls back to a driver with no screen, and the game would run where nobody sees it: only
// when asked for (SDL_VIDEODRIVER=offscreen: `platon shot`, the tests) is that a window. A display
// that is set is tried for a second: on a loaded machine its first connection can fail (seen with a
// fresh Xvfb that let other clients in a moment before and after).
void startVideo() {
  const char* asked = std::getenv("SDL_VIDEODRIVER");
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  const bool implicit = !asked || !*asked, hasX11 = x11 && *x11, hasWayland = wayland && *wayland;
  const bool hasDisplay = hasX11 || hasWayland;
  std::string why;
  for (int attempt = 0; attempt < (hasDisplay ? 6 : 1); ++attempt) {
    if (attempt > 0) SDL_Delay(200);
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
      why = SDL_GetError();
      continue;
    }
    const char* driver = SDL_GetCurrentVideoDriver();
    if (!implicit || !driver || (std::strcmp(driver, "offscreen") != 0 && std::strcmp(driver, "dummy") != 0)) return;
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    why = hasX11       ? std::string("DISPLAY=") + x11 + " could not be opened"
          : hasWayland ? std::string("WAYLAND_DISPLAY=") + wayland + " could not be opened"
                       : "neither DISPLAY nor WAYLAND_DISPLAY is set";
  }
  if (!implicit) throw std::runtime_error("no display (SDL could not start its video): " + why);
  throw std::runtime_error("no display to open a window on (" + why + "; SDL_VIDEODRIVER=offscreen runs without one)");
}

}  // namespace

Window::Window(const std::string& title, int width, int height) {
  startVideo();
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
  SDL_GL_SetAttribute(SDL_GL_MULTISAMPLEBUFFERS, 0);
  SDL_GL_SetAttribute(SDL_GL_MULTISAMPLESAMPLES, 0);
  // One context, made once: multisampling is an offscreen framebuffer (setMultisamples), not the
  // window's, so no context is made again to learn what the driver is (on llvmpipe a second
  // context cost a second start of the rasterizer, about 100 ms of start-up).
  const Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, flags);
  if (window_) context_ = SDL_GL_CreateContext(window_);
  if (!context_) {
    const std::string reason = SDL_GetError();
    if (window_) SDL_DestroyWindow(window_);
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    throw std::runtime_error("no OpenGL 3.3 core context: " + reason);
  }
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  software_ = renderer && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe") ||
                           std::strstr(renderer, "swrast"));
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples_);
  const char* wanted = std::getenv("PLATON_MULTISAMPLE");  // tools and tests; the game's settings say later
  setMultisamples(wanted && *wanted ? std::atoi(wanted) : -1);
  SDL_GL_SetSwapInterval(1);  // vsync when the driver has it; no error otherwise
  // No key holds an action until the bindings come (session::Session binds the scene's actions).
  // Gamepads: those present now arrive as "added" events on the first poll, later ones when
  // plugged in. No gamepad support (no such subsystem) is not an error.
  SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_MULTISAMPLE);
}

Window::~Window() {
  freeSamples();
  for (SDL_GameController* pad : pads_) SDL_GameControllerClose(pad);
  SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
  SDL_GL_DeleteContext(context_);
  SDL_DestroyWindow(window_);
  SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

namespace {

std::optional<core::Key> keyOf(SDL_Keycode key) {
  switch (key) {
    case SDLK_ESCAPE:
      return core::Key::Escape;
    case SDLK_TAB:
      return core::Key::Settings;
    case SDLK_RETURN:
    case SDLK_KP_ENTER:
      return core::Key::Enter;
    case SDLK_UP:
    case SDLK_w:
      return core::Key::Up;
    case SDLK_DOWN:
    case SDLK_s:
      return core::Key::Down;
    case SDLK_LEFT:
    case SDLK_a:
      return core::Key::Left;
    case SDLK_RIGHT:
    case SDLK_d:
      return core::Key::Right;
    case SDLK_r:
      return core::Key::Restart;
    case SDLK_F5:
      return core::Key::Reload;
    case SDLK_F2:
      return core::Key::Debug;
    case SDLK_BACKQUOTE:
      return core::Key::Console;
    case SDLK_BACKSPACE:
      return core::Key::Backspace;
    case SDLK_F3:
      return core::Key::ShowFps;
    case SDLK_F12:
      return core::Key::Screenshot;
    default:
      return std::nullopt;
  }
}

std::optional<core::Key> keyOf(SDL_GameControllerButton button) {
  switch (button) {
    case SDL_CONTROLLER_BUTTON_START:
      return core::Key::Escape;
    case SDL_CONTROLLER_BUTTON_A:
      return core::Key::Enter;
    case SDL_CONTROLLER_BUTTON_DPAD_UP:
      return core::Key::Up;
    case SDL_CONTROLLER_BUTTON_DPAD_DOWN:
      return core::Key::Down;
    case SDL_CONTROLLER_BUTTON_DPAD_LEFT:
      return core::Key::Left;
    case SDL_CONTROLLER_BUTTON_DPAD_RIGHT:
      return core::Key::Right;
    case SDL_CONTROLLER_BUTTON_BACK:
      return core::Key::Restart;
    case SDL_CONTROLLER_BUTTON_Y:  // the title's settings, as Tab (a pad player never needs the keyboard)
      return core::Key::Settings;
    default:
      return std::nullopt;
  }
}

}  // namespace

core::Buttons Window::heldButtons() const {
  int count = 0;
  const Uint8* keys = SDL_GetKeyboardState(&count);
  core::Buttons held = 0;
  for (int k = 0; k < count; ++k)
    if (keys[k]) held |= buttonOf(static_cast<SDL_Scancode>(k));
  return held;
}

namespace {

// Fills `table` (indexed by SDL's code for a key or a pad button) with the bit of each action the
// names bind (names[i]: action i's); `code` turns a name into that code, or returns `none`. Unknown
// names go to `unknown`.
template <size_t N, class Code>
void bindNames(core::Buttons (&table)[N], const std::vector<std::vector<std::string>>& names, Code code, int none,
               std::vector<std::string>& unknown) {
  std::fill(std::begin(table), std::end(table), core::Buttons{0});
  for (size_t b = 0; b < names.size() && b < core::kMaxActions; ++b)
    for (const std::string& name : names[b]) {
      const int c = static_cast<int>(code(name.c_str()));
      if (c == none || c < 0 || c >= static_cast<int>(N))
        unknown.push_back(name);
      else
        table[c] |= static_cast<core::Buttons>(1u << b);
    }
}

}  // namespace

std::vector<std::string> Window::setBindings(const core::KeyBindings& bindings) {
  std::vector<std::string> unknown;
  bindNames(buttons_, bindings.keys, SDL_GetScancodeFromName, SDL_SCANCODE_UNKNOWN, unknown);
  bindNames(padButtons_, bindings.pad, SDL_GameControllerGetButtonFromString, SDL_CONTROLLER_BUTTON_INVALID, unknown);
  return unknown;
}

void Window::setFullscreen(bool on) { SDL_SetWindowFullscreen(window_, on ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0); }

void Window::setVsync(bool on) { SDL_GL_SetSwapInterval(on ? 1 : 0); }

// A gamepad's buttons (as bound) and its left stick past a third of its travel, as the engine's.
core::Buttons Window::padButtons(SDL_GameController* pad) const {
  constexpr Sint16 kDead = 11000;
  const Sint16 x = SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_LEFTX);
  const Sint16 y = SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_LEFTY);
  core::Buttons held = 0;
  if (x < -kDead) held |= InputFrame::bit(Button::Left);
  if (x > kDead) held |= InputFrame::bit(Button::Right);
  if (y < -kDead) held |= InputFrame::bit(Button::Up);
  if (y > kDead) held |= InputFrame::bit(Button::Down);
  for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b)
    if (SDL_GameControllerGetButton(pad, static_cast<SDL_GameControllerButton>(b))) held |= padButtons_[b];
  return held;
}

void Window::keyDown(const SDL_KeyboardEvent& key, core::WindowInput& input) {
  input.keys.push_back({SDL_GetScancodeName(key.keysym.scancode), (key.keysym.mod & KMOD_CTRL) != 0,
                        (key.keysym.mod & KMOD_SHIFT) != 0, (key.keysym.mod & KMOD_ALT) != 0});
  if (key.repeat && key.keysym.sym == SDLK_BACKSPACE) input.pressed.push_back(core::Key::Backspace);
  if (key.repeat) return;
  input.tapped |= buttonOf(key.keysym.scancode);
  input.lastKey = SDL_GetScancodeName(key.keysym.scancode);
  if (key.keysym.sym == SDLK_F11) {
    const bool full = SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP;
    SDL_SetWindowFullscreen(window_, full ? 0 : SDL_WINDOW_FULLSCREEN_DESKTOP);
  } else if (const auto k = keyOf(key.keysym.sym)) {
    input.pressed.push_back(*k);
  }
}

// A pad plugged in is opened (no restart); one unplugged is let go.
void Window::padPlugged(const SDL_ControllerDeviceEvent& device) {
  if (device.type == SDL_CONTROLLERDEVICEADDED) {
    if (SDL_GameController* pad = SDL_GameControllerOpen(device.which)) pads_.push_back(pad);
    return;
  }
  for (size_t i = 0; i < pads_.size(); ++i)
    if (SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(pads_[i])) == device.which) {
      SDL_GameControllerClose(pads_[i]);
      pads_.erase(pads_.begin() + static_cast<std::ptrdiff_t>(i));
      return;
    }
}

void Window::padButtonDown(const SDL_ControllerButtonEvent& button, core::WindowInput& input) {
  const auto b = static_cast<SDL_GameControllerButton>(button.button);
  if (button.button < SDL_CONTROLLER_BUTTON_MAX) input.tapped |= padButtons_[button.button];
  if (const char* name = SDL_GameControllerGetStringForButton(b)) input.lastPadButton = name;
  if (const auto key = keyOf(b)) input.pressed.push_back(*key);
}

core::WindowInput Window::pollEvents() {
  core::WindowInput input;
  const float dpi = pixelsPerPoint();
  SDL_Event event;
  while (SDL_PollEvent(&event)) {
    switch (event.type) {
      case SDL_QUIT:
        input.closed = true;
        break;
      case SDL_WINDOWEVENT:
        if (event.window.event == SDL_WINDOWEVENT_FOCUS_LOST) input.focusLost = true;
        break;
      case SDL_TEXTINPUT:
        input.text += event.text.text;
        break;
      case SDL_MOUSEBUTTONDOWN:
      case SDL_MOUSEBUTTONUP:
        input.mouse.push_back(
            {event.type == SDL_MOUSEBUTTONDOWN ? core::MouseEvent::Kind::Down : core::MouseEvent::Kind::Up,
             event.button.button, static_cast<float>(event.button.x) * dpi, static_cast<float>(event.button.y) * dpi,
             0});
        break;
      case SDL_MOUSEWHEEL: {
        int x = 0, y = 0;
        SDL_GetMouseState(&x, &y);
        const float notches = event.wheel.preciseY != 0 ? event.wheel.preciseY : static_cast<float>(event.wheel.y);
        input.mouse.push_back(
            {core::MouseEvent::Kind::Wheel, 0, static_cast<float>(x) * dpi, static_cast<float>(y) * dpi, notches});
        break;
      }
      case SDL_KEYDOWN:
        keyDown(event.key, input);
        break;
      case SDL_CONTROLLERDEVICEADDED:
      case SDL_CONTROLLERDEVICEREMOVED:
        padPlugged(event.cdevice);
        break;
      case SDL_CONTROLLERBUTTONDOWN:
        padButtonDown(event.cbutton, input);
        break;
      default:
        break;
    }
  }
  input.held = heldButtons();
  for (SDL_GameController* pad : pads_) input.held |= padButtons(pad);
  int x = 0, y = 0;
  const Uint32 buttons = SDL_GetMouseState(&x, &y);
  input.mouseX = static_cast<float>(x) * dpi, input.mouseY = static_cast<float>(y) * dpi;
  input.mouseHeld = static_cast<uint8_t>(buttons & 7);
  const SDL_Keymod mods = SDL_GetModState();
  input.shift = mods & KMOD_SHIFT, input.ctrl = mods & KMOD_CTRL, input.alt = mods & KMOD_ALT;
  input.width = pixelWidth(), input.height = pixelHeight();
  return input;
}

void Window::resize(int width, int height) {
  SDL_SetWindowSize(window_, width, height);
  SDL_PumpEvents();
}

void Window::setTitle(const std::string& title) {
  if (title == title_) return;  // a round trip to the window system: only when it changes
  title_ = title;
  SDL_SetWindowTitle(window_, title.c_str());
}

int Window::pixelWidth() const {
  int w = 0, h = 0;
  SDL_GL_GetDrawableSize(window_, &w, &h);
  return w;
}

int Window::pixelHeight() const {
  int w = 0, h = 0;
  SDL_GL_GetDrawableSize(window_, &w, &h);
  return h;
}

float Window::pixelsPerPoint() const {
  int w = 0, h = 0;
  SDL_GetWindowSize(window_, &w, &h);
  return w > 0 ? static_cast<float>(pixelWidth()) / static_cast<float>(w) : 1.0f;
}

void Window::swap() { SDL_GL_SwapWindow(window_); }

void Window::setMultisamples(int samples) {
  // Auto: 4 samples on a GPU; none on a software rasterizer, which pays for each sample on every
  // pixel (about twice the frame).
  wantedSamples_ = samples < 0 ? (software_ ? 0 : 4) : std::min(samples, 16);
}

void Window::freeSamples() {
  if (frame_.framebuffer) glDeleteFramebuffers(1, &frame_.framebuffer);
  if (frame_.color) glDeleteRenderbuffers(1, &frame_.color);
  if (frame_.depth) glDeleteRenderbuffers(1, &frame_.depth);
  frame_ = {};
}

// The frame is drawn into a multisampled framebuffer of the drawable's size when samples are
// wanted (made again when the size or the count changes), else straight into the window's.
void Window::beginFrame() {
  const int samples = std::min(wantedSamples_, static_cast<int>(maxSamples_));
  const int w = pixelWidth(), h = pixelHeight();
  if (samples != frame_.samples || w != frame_.width || h != frame_.height) {
    freeSamples();
    if (samples > 1) {
      glGenFramebuffers(1, &frame_.framebuffer);
      glBindFramebuffer(GL_FRAMEBUFFER, frame_.framebuffer);
      glGenRenderbuffers(1, &frame_.color);
      glBindRenderbuffer(GL_RENDERBUFFER, frame_.color);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, frame_.color);
      glGenRenderbuffers(1, &frame_.depth);
      glBindRenderbuffer(GL_RENDERBUFFER, frame_.depth);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, w, h);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, frame_.depth);
      glBindRenderbuffer(GL_RENDERBUFFER, 0);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        std::fprintf(stderr, "platon: no %d-sample framebuffer here; drawing without multisampling\n", samples);
        freeSamples();
        wantedSamples_ = 0;
      }
    }
    frame_.samples = samples, frame_.width = w, frame_.height = h;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, frame_.framebuffer);
}

void Window::endFrame() {
  if (!frame_.framebuffer) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, frame_.framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, frame_.width, frame_.height, 0, 0, frame_.width, frame_.height, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<uint8_t> Window::readPixels(int& width, int& height) const {
  width = pixelWidth(), height = pixelHeight();
  std::vector<uint8_t> bottomUp(static_cast<size_t>(width) * height * 4), topDown(bottomUp.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  const size_t row = static_cast<size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(bottomUp.data() + (height - 1 - y) * row, row, topDown.data() + static_cast<size_t>(y) * row);
  return topDown;
}

}  // namespace platon::render

#include "window.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>

#include "platon/core/input.h"

namespace platon::render {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what + ": " + SDL_GetError()); }

// Arrows or WASD to move, Space (or W/Up) to jump, R restart, F5 reload.
uint8_t heldButtons() {
  const Uint8* keys = SDL_GetKeyboardState(nullptr);
  using core::Button;
  using core::InputFrame;
  uint8_t held = 0;
  if (keys[SDL_SCANCODE_LEFT] || keys[SDL_SCANCODE_A]) held |= InputFrame::bit(Button::Left);
  if (keys[SDL_SCANCODE_RIGHT] || keys[SDL_SCANCODE_D]) held |= InputFrame::bit(Button::Right);
  if (keys[SDL_SCANCODE_UP] || keys[SDL_SCANCODE_W]) held |= InputFrame::bit(Button::Up);
  if (keys[SDL_SCANCODE_DOWN] || keys[SDL_SCANCODE_S]) held |= InputFrame::bit(Button::Down);
  if (keys[SDL_SCANCODE_SPACE]) held |= InputFrame::bit(Button::Jump);
  if (keys[SDL_SCANCODE_R]) held |= InputFrame::bit(Button::Restart);
  if (keys[SDL_SCANCODE_F5]) held |= InputFrame::bit(Button::Reload);
  return held;
}

}  // namespace

Window::Window(const std::string& title, int width, int height) {
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) fail("no display (SDL could not start its video)");
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
  const Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
  for (const int samples : {4, 0}) {  // multisampling where the driver has it
    SDL_GL_SetAttribute(SDL_GL_MULTISAMPLEBUFFERS, samples > 0);
    SDL_GL_SetAttribute(SDL_GL_MULTISAMPLESAMPLES, samples);
    window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, flags);
    if (window_) context_ = SDL_GL_CreateContext(window_);
    if (context_) break;
    if (window_) SDL_DestroyWindow(window_);
    window_ = nullptr;
  }
  if (!context_) {
    const std::string reason = SDL_GetError();
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    throw std::runtime_error("no OpenGL 3.3 core context: " + reason);
  }
  SDL_GL_SetSwapInterval(1);  // vsync when the driver has it; no error otherwise
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_MULTISAMPLE);
}

Window::~Window() {
  SDL_GL_DeleteContext(context_);
  SDL_DestroyWindow(window_);
  SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

bool Window::pollEvents(uint8_t& held) {
  SDL_Event event;
  bool open = true;
  while (SDL_PollEvent(&event)) {
    if (event.type == SDL_QUIT) open = false;
    if (event.type == SDL_KEYDOWN && event.key.keysym.sym == SDLK_ESCAPE) open = false;
    if (event.type == SDL_KEYDOWN && event.key.keysym.sym == SDLK_F11) {
      const bool full = SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP;
      SDL_SetWindowFullscreen(window_, full ? 0 : SDL_WINDOW_FULLSCREEN_DESKTOP);
    }
  }
  held = heldButtons();
  return open;
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

// An SDL2 window with an OpenGL 3.3 core context: resizable, high-DPI aware, vsync when the driver
// has it, multisampled through an offscreen framebuffer (4 samples on a GPU unless set otherwise). Keyboard and gamepad
// state become the engine's buttons.
#pragma once
#include <SDL2/SDL.h>
#include <cstdint>
#include <epoxy/gl.h>
#include <string>
#include <vector>

#include "platon/core/display.h"

namespace platon::render {

class Window {
 public:
  // Throws std::runtime_error when there is no display or no GL 3.3 core context.
  Window(const std::string& title, int width, int height);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // Handles pending events: keys and gamepad buttons pressed, what is held now, a close. Gamepads
  // come and go while the game runs (SDL's game-controller API).
  core::WindowInput pollEvents();
  void resize(int width, int height);
  void setTitle(const std::string& title);
  // The drawable's size in pixels, and pixels per window point (2 on a high-DPI screen).
  int pixelWidth() const;
  int pixelHeight() const;
  float pixelsPerPoint() const;
  // Every frame is drawn between these two: the first binds where it is drawn (the multisampled
  // framebuffer, or the window's own), the second resolves it into the window's back buffer.
  void beginFrame();
  void endFrame();
  void swap();
  // Samples a pixel from the next frame on: 0 or 1 none, -1 auto (4 on a GPU, none on a software
  // rasterizer); no more than the driver has.
  void setMultisamples(int samples);
  // The back buffer's pixels, rows from the top, RGBA.
  std::vector<uint8_t> readPixels(int& width, int& height) const;
  // The player's keys (core::KeyBindings); returns the names SDL does not know.
  std::vector<std::string> setBindings(const core::KeyBindings& bindings);
  void setFullscreen(bool on);
  void setVsync(bool on);

 private:
  core::Buttons buttonOf(SDL_Scancode key) const { return key >= 0 && key < SDL_NUM_SCANCODES ? buttons_[key] : 0; }
  core::Buttons heldButtons() const;
  void keyDown(const SDL_KeyboardEvent& key, core::WindowInput& input);
  void padPlugged(const SDL_ControllerDeviceEvent& device);
  void padButtonDown(const SDL_ControllerButtonEvent& button, core::WindowInput& input);
  core::Buttons padButtons(SDL_GameController* pad) const;

  core::Buttons buttons_[SDL_NUM_SCANCODES] = {};             // by scancode: the InputFrame bits it holds
  core::Buttons padButtons_[SDL_CONTROLLER_BUTTON_MAX] = {};  // by gamepad button: likewise
  void freeSamples();

  struct SampledFrame {
    GLuint framebuffer = 0, color = 0, depth = 0;
    int samples = 0, width = 0, height = 0;
  };
  SampledFrame frame_;
  int wantedSamples_ = 0;
  GLint maxSamples_ = 0;
  bool software_ = false;
  SDL_Window* window_ = nullptr;
  SDL_GLContext context_ = nullptr;
  std::vector<SDL_GameController*> pads_;
  std::string title_;
};

}  // namespace platon::render

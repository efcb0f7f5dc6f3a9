// An SDL2 window with an OpenGL 3.3 core context, as a render::GlContext: the renderer loads its
// functions through SDL_GL_GetProcAddress, so this program never links OSMesa (nor libGL).
// Runs without a display under SDL_VIDEODRIVER=offscreen (EGL).
#pragma once

#include <SDL.h>

#include <string>

#include "render/gl_context.h"

namespace baize::tools {

class SdlGlContext : public render::GlContext {
 public:
  // Opens a resizable window of this size; throws std::runtime_error with SDL's message on failure.
  SdlGlContext(const std::string& title, int width_px, int height_px);
  ~SdlGlContext() override;
  SdlGlContext(const SdlGlContext&) = delete;
  SdlGlContext& operator=(const SdlGlContext&) = delete;

  Proc procAddress(const char* name) const override;

  SDL_Window* window() const { return window_; }
  // The size of the drawable area, px (may differ from the window's on high-density screens).
  void drawableSize(int& width_px, int& height_px) const;
  void swap() const { SDL_GL_SwapWindow(window_); }

 private:
  SDL_Window* window_ = nullptr;
  SDL_GLContext context_ = nullptr;
};

}  // namespace baize::tools

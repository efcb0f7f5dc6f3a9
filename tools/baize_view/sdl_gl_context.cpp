#include "tools/baize_view/sdl_gl_context.h"

#include <stdexcept>

namespace baize::tools {

SdlGlContext::SdlGlContext(const std::string& title, int width_px, int height_px) {
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    throw std::runtime_error(std::string("SDL cannot start its video: ") + SDL_GetError());
  }
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                             width_px, height_px,
                             SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
  if (window_ == nullptr) {
    const std::string error = SDL_GetError();
    SDL_Quit();
    throw std::runtime_error("SDL cannot open an OpenGL window: " + error);
  }
  context_ = SDL_GL_CreateContext(window_);
  if (context_ == nullptr) {
    const std::string error = SDL_GetError();
    SDL_DestroyWindow(window_);
    SDL_Quit();
    throw std::runtime_error("SDL cannot create an OpenGL 3.3 core context: " + error);
  }
  SDL_GL_MakeCurrent(window_, context_);
  SDL_GL_SetSwapInterval(1);  // follow the display's refresh where there is one
}

SdlGlContext::~SdlGlContext() {
  SDL_GL_DeleteContext(context_);
  SDL_DestroyWindow(window_);
  SDL_Quit();
}

render::GlContext::Proc SdlGlContext::procAddress(const char* name) const {
  return reinterpret_cast<Proc>(SDL_GL_GetProcAddress(name));
}

void SdlGlContext::drawableSize(int& width_px, int& height_px) const {
  SDL_GL_GetDrawableSize(window_, &width_px, &height_px);
}

}  // namespace baize::tools

#include "render/gl_functions.h"

#include <stdexcept>
#include <string>

namespace baize::render {

GlFunctions loadGlFunctions(const GlContext& context) {
  GlFunctions gl;
#define BAIZE_GL_LOAD(type, name)                                          \
  gl.name = reinterpret_cast<type>(context.procAddress("gl" #name));       \
  if (gl.name == nullptr) {                                                \
    throw std::runtime_error("the OpenGL context has no function gl" #name \
                             " (an OpenGL 3.3 core context is needed)");   \
  }
  BAIZE_GL_FUNCTIONS(BAIZE_GL_LOAD)
#undef BAIZE_GL_LOAD
  return gl;
}

}  // namespace baize::render

// Where the renderer gets its OpenGL from. The drawing code (render/gl_renderer.h) never links an
// OpenGL library: it loads every function through a provider's procAddress, so the same code draws
// into an off-screen OSMesa context (render/osmesa_context.h), an SDL2 window (tools/baize_view/)
// or a future EGL context. Linking libGL next to OSMesa in one program yields black images; loading
// through the context's own GetProcAddress avoids that.
#pragma once

namespace baize::render {

// A current OpenGL 3.3 (or later) core context.
class GlContext {
 public:
  using Proc = void (*)();
  virtual ~GlContext() = default;
  // The named GL function of this context (e.g. "glClear"), or nullptr when it has none.
  virtual Proc procAddress(const char* name) const = 0;
};

}  // namespace baize::render

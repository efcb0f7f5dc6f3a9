// An off-screen OpenGL context from OSMesa (Mesa's software rasteriser, llvmpipe): no display, no
// GPU. The renderer draws into its own framebuffer objects, so the context's own buffer is tiny.
// Mesa 25.1 removed OSMesa; this provider is one file pair behind GlContext so an EGL provider can
// replace it without touching the drawing code.
#pragma once

#include <vector>

#include "render/gl_context.h"

namespace baize::render {

class OsmesaContext : public GlContext {
 public:
  // Creates a core-profile context (3.3 asked for; llvmpipe gives 4.5) and makes it current.
  // Throws std::runtime_error when OSMesa cannot create or bind it.
  OsmesaContext();
  ~OsmesaContext() override;
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  Proc procAddress(const char* name) const override;

 private:
  void* context_ = nullptr;                   // OSMesaContext
  std::vector<unsigned char> colour_buffer_;  // the context's own (unused) RGBA buffer
};

}  // namespace baize::render

#include "render/osmesa_context.h"

#include <GL/osmesa.h>

#include <stdexcept>

namespace baize::render {
namespace {

// The context's own buffer is never drawn into (the renderer uses framebuffer objects), but OSMesa
// needs one to make the context current.
constexpr int kOwnBufferSide_px = 4;

}  // namespace

OsmesaContext::OsmesaContext()
    : colour_buffer_(static_cast<std::size_t>(kOwnBufferSide_px) * kOwnBufferSide_px * 4) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context == nullptr) {
    throw std::runtime_error(
        "OSMesa could not create an OpenGL 3.3 core context (is libosmesa6 with llvmpipe "
        "installed?)");
  }
  context_ = context;
  if (!OSMesaMakeCurrent(context, colour_buffer_.data(), GL_UNSIGNED_BYTE, kOwnBufferSide_px,
                         kOwnBufferSide_px)) {
    OSMesaDestroyContext(context);
    context_ = nullptr;
    throw std::runtime_error("OSMesa could not make its OpenGL context current");
  }
}

OsmesaContext::~OsmesaContext() {
  if (context_ != nullptr) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

GlContext::Proc OsmesaContext::procAddress(const char* name) const {
  return reinterpret_cast<Proc>(OSMesaGetProcAddress(name));
}

}  // namespace baize::render

#include "render/gl_renderer.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace baize::render {
namespace {

// How items reach the shader (the vertex's `shape.x`).
enum ShapeKind : int {
  kFlatGeometry = 0,  // triangles in the table plane
  kFlatDisc = 1,      // a quad in the table plane, cut to a disc in the shader
  kFlatRing = 2,
  kBall = 3,  // a quad facing the camera, shaded as a sphere
  kStripedBall = 4,
  kText = 5,           // a glyph: a quad in the plane whose coverage comes from the atlas texture
  kBallLabelDisc = 6,  // a flat disc facing the camera, on a ball (the white circle of a number)
  kBallLabelText = 7,  // a glyph facing the camera at a ball's centre: `local` is its offset (m)
};

// Numbers on balls: the white circle's radius and the font's em size, in ball radii (a two-digit
// number then fits inside the circle); below this many pixels of ball radius they are left out.
constexpr double kLabelDiscRadius = 0.5;
constexpr double kLabelEmSize = 0.68;
constexpr double kMinLabelledBallRadius_px = 6.0;
const Rgba kLabelDisc{0.98f, 0.98f, 0.96f, 1.0f};
const Rgba kLabelText{0.07f, 0.07f, 0.07f, 1.0f};

// Legend layout, in units of the text size: padding inside the panel, the swatch's radius.
constexpr double kLegendPadding = 0.5;
constexpr double kSwatchRadius = 0.4;
const Rgba kLegendPanel{0.0f, 0.0f, 0.0f, 0.6f};
const Rgba kLegendText{0.96f, 0.96f, 0.94f, 1.0f};

// Disc quads reach this far beyond the radius (in radii) so that the analytic edge has room to
// fade out even on a disc a few pixels across.
constexpr float kDiscQuadExtent = 1.5f;

struct Vertex {
  float position[3];  // the point, or a disc's centre, m
  float colour[4];
  float local[2];  // discs: the corner in radii; legend glyphs: atlas coordinates; ball
                   // numbers: the glyph corner's offset from the ball's centre (m)
  float shape[3];  // kind, then radius (m) and inner fraction (rings), or for ball numbers the
                   // glyph corner's atlas coordinates
};

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
layout(location = 2) in vec2 local;
layout(location = 3) in vec3 shape;
uniform mat4 view;
uniform mat4 projection;
out vec4 v_colour;
out vec2 v_local;
flat out int v_kind;
flat out float v_inner;
void main() {
  int kind = int(shape.x + 0.5);
  vec4 eye;
  if (kind == 1 || kind == 2) {
    eye = view * vec4(position + vec3(local * shape.y, 0.0), 1.0);  // lies on the cloth
  } else if (kind == 3 || kind == 4 || kind == 6) {
    eye = view * vec4(position, 1.0);  // a sphere's outline faces the camera
    eye.xy += local * shape.y;
  } else if (kind == 7) {
    eye = view * vec4(position, 1.0);
    eye.xy += local;
  } else {
    eye = view * vec4(position, 1.0);
  }
  gl_Position = projection * eye;
  v_colour = colour;
  v_local = kind == 7 ? shape.yz : local;  // a label glyph's atlas coordinates
  v_kind = kind;
  v_inner = shape.z;
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec4 v_colour;
in vec2 v_local;
flat in int v_kind;
flat in float v_inner;
uniform sampler2D atlas;
out vec4 fragment;
void main() {
  if (v_kind == 0) {
    fragment = v_colour;
    return;
  }
  if (v_kind == 5 || v_kind == 7) {
    fragment = vec4(v_colour.rgb, v_colour.a * texture(atlas, v_local).r);
    return;
  }
  float r = length(v_local);
  float edge = max(fwidth(r), 1e-4);  // one pixel, in radii
  float alpha = clamp((1.0 - r) / edge + 0.5, 0.0, 1.0);
  if (v_kind == 2) alpha *= clamp((r - v_inner) / edge + 0.5, 0.0, 1.0);
  if (alpha <= 0.0) discard;
  vec3 colour = v_colour.rgb;
  if (v_kind == 3 || v_kind == 4) {
    vec2 d = v_local / max(r, 1.0);
    vec3 normal = vec3(d, sqrt(max(1.0 - dot(d, d), 0.0)));
    vec3 base = colour;
    if (v_kind == 4 && abs(v_local.y) > 0.5) base = vec3(0.97, 0.97, 0.95);
    vec3 light = normalize(vec3(-0.35, 0.45, 0.82));
    float diffuse = max(dot(normal, light), 0.0);
    float highlight = pow(max(dot(normal, normalize(light + vec3(0.0, 0.0, 1.0))), 0.0), 60.0);
    colour = base * (0.30 + 0.70 * diffuse) + vec3(0.55) * highlight;
  }
  fragment = vec4(colour, v_colour.a * alpha);
}
)";

void put(std::vector<Vertex>& out, const Eigen::Vector3d& p, const Rgba& c, float lx, float ly,
         int kind, double radius, double inner) {
  out.push_back(
      Vertex{{static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())},
             {c.r, c.g, c.b, c.a},
             {lx, ly},
             {static_cast<float>(kind), static_cast<float>(radius), static_cast<float>(inner)}});
}

void addFlatTriangle(std::vector<Vertex>& out, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                     const Eigen::Vector2d& c, double z, const Rgba& colour) {
  for (const Eigen::Vector2d* p : {&a, &b, &c}) {
    put(out, Eigen::Vector3d(p->x(), p->y(), z), colour, 0, 0, kFlatGeometry, 0, 0);
  }
}

void addWall(std::vector<Vertex>& out, const Wall& wall) {
  const Eigen::Vector3d a(wall.from_m.x(), wall.from_m.y(), wall.bottom_m);
  const Eigen::Vector3d b(wall.to_m.x(), wall.to_m.y(), wall.bottom_m);
  const Eigen::Vector3d c(wall.to_m.x(), wall.to_m.y(), wall.top_m);
  const Eigen::Vector3d d(wall.from_m.x(), wall.from_m.y(), wall.top_m);
  for (const Eigen::Vector3d* p : {&a, &b, &c, &a, &c, &d}) {
    put(out, *p, wall.colour, 0, 0, kFlatGeometry, 0, 0);
  }
}

void addStroke(std::vector<Vertex>& out, const Stroke& stroke) {
  const double half = stroke.width_m / 2;
  for (std::size_t i = 1; i < stroke.points_m.size(); ++i) {
    const Eigen::Vector2d a = stroke.points_m[i - 1], b = stroke.points_m[i];
    const double length = (b - a).norm();
    if (length == 0) continue;
    const Eigen::Vector2d along = (b - a) / length * half;  // square caps close the joins
    const Eigen::Vector2d across(-along.y(), along.x());
    const Eigen::Vector2d p0 = a - along - across, p1 = b + along - across;
    const Eigen::Vector2d p2 = b + along + across, p3 = a - along + across;
    addFlatTriangle(out, p0, p1, p2, stroke.z_m, stroke.colour);
    addFlatTriangle(out, p0, p2, p3, stroke.z_m, stroke.colour);
  }
}

void addDisc(std::vector<Vertex>& out, const Disc& disc) {
  int kind = kFlatDisc;
  if (disc.style == DiscStyle::Ring) kind = kFlatRing;
  if (disc.style == DiscStyle::Ball) kind = kBall;
  if (disc.style == DiscStyle::StripedBall) kind = kStripedBall;
  const float e = kDiscQuadExtent;
  const float corners[6][2] = {{-e, -e}, {e, -e}, {e, e}, {-e, -e}, {e, e}, {-e, e}};
  for (const auto& corner : corners) {
    put(out, disc.centre_m, disc.colour, corner[0], corner[1], kind, disc.radius_m,
        disc.inner_fraction);
  }
}

// A ball's number: a white circle facing the camera and the digits centred on it.
void addBallLabel(std::vector<Vertex>& out, const Disc& ball, const GlyphAtlas& atlas) {
  const float e = kDiscQuadExtent;
  const float corners[6][2] = {{-e, -e}, {e, -e}, {e, e}, {-e, -e}, {e, e}, {-e, e}};
  for (const auto& corner : corners) {
    put(out, ball.centre_m, kLabelDisc, corner[0], corner[1], kBallLabelDisc,
        kLabelDiscRadius * ball.radius_m, 0);
  }
  const double metres_per_px = kLabelEmSize * ball.radius_m / atlas.pixelSize();
  const double cap_height_px = atlas.glyph('0').bearing_y;
  double pen = -0.5 * atlas.textWidth(ball.label);
  const double baseline = -0.5 * cap_height_px;
  for (char c : ball.label) {
    const Glyph& g = atlas.glyph(c);
    const double x0 = pen + g.bearing_x, x1 = x0 + g.width;
    const double y1 = baseline + g.bearing_y, y0 = y1 - g.height;  // eye space: y up
    const float u0 = static_cast<float>(g.x) / atlas.width();
    const float u1 = static_cast<float>(g.x + g.width) / atlas.width();
    const float v_top = static_cast<float>(g.y) / atlas.height();
    const float v_bottom = static_cast<float>(g.y + g.height) / atlas.height();
    const auto corner = [&](double x, double y, float u, float v) {
      put(out, ball.centre_m, kLabelText, static_cast<float>(x * metres_per_px),
          static_cast<float>(y * metres_per_px), kBallLabelText, u, v);
    };
    corner(x0, y1, u0, v_top);
    corner(x1, y1, u1, v_top);
    corner(x1, y0, u1, v_bottom);
    corner(x0, y1, u0, v_top);
    corner(x1, y0, u1, v_bottom);
    corner(x0, y0, u0, v_bottom);
    pen += g.advance;
  }
}

bool isBall(const DrawItem& item) {
  const Disc* disc = std::get_if<Disc>(&item);
  return disc != nullptr &&
         (disc->style == DiscStyle::Ball || disc->style == DiscStyle::StripedBall);
}

Eigen::Matrix4f toFloat(const Eigen::Matrix4d& m) { return m.cast<float>(); }

}  // namespace

GlRenderer::GlRenderer(const GlContext& context) : gl_(loadGlFunctions(context)) {
  const auto compile = [&](GLenum type, const char* source) {
    const GLuint shader = gl_.CreateShader(type);
    gl_.ShaderSource(shader, 1, &source, nullptr);
    gl_.CompileShader(shader);
    GLint ok = 0;
    gl_.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[2048] = {};
      gl_.GetShaderInfoLog(shader, sizeof log, nullptr, log);
      gl_.DeleteShader(shader);
      throw std::runtime_error(std::string("the renderer's shader does not compile: ") + log);
    }
    return shader;
  };
  const GLuint vertex = compile(GL_VERTEX_SHADER, kVertexShader);
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  program_ = gl_.CreateProgram();
  gl_.AttachShader(program_, vertex);
  gl_.AttachShader(program_, fragment);
  gl_.LinkProgram(program_);
  gl_.DeleteShader(vertex);
  gl_.DeleteShader(fragment);
  GLint linked = 0;
  gl_.GetProgramiv(program_, GL_LINK_STATUS, &linked);
  if (!linked) {
    char log[2048] = {};
    gl_.GetProgramInfoLog(program_, sizeof log, nullptr, log);
    gl_.DeleteProgram(program_);
    throw std::runtime_error(std::string("the renderer's shaders do not link: ") + log);
  }
  view_location_ = gl_.GetUniformLocation(program_, "view");
  projection_location_ = gl_.GetUniformLocation(program_, "projection");
  atlas_location_ = gl_.GetUniformLocation(program_, "atlas");

  gl_.GenVertexArrays(1, &vertex_array_);
  gl_.GenBuffers(1, &vertex_buffer_);
  gl_.BindVertexArray(vertex_array_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  const auto attribute = [&](GLuint index, GLint size, std::size_t offset) {
    gl_.EnableVertexAttribArray(index);
    gl_.VertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                            reinterpret_cast<const void*>(offset));
  };
  attribute(0, 3, offsetof(Vertex, position));
  attribute(1, 4, offsetof(Vertex, colour));
  attribute(2, 2, offsetof(Vertex, local));
  attribute(3, 3, offsetof(Vertex, shape));

  GLint max_samples = 1;
  gl_.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::max(1, std::min(kWantedSamples, static_cast<int>(max_samples)));
}

GlRenderer::~GlRenderer() {
  releaseFramebuffers();
  if (atlas_texture_ != 0) gl_.DeleteTextures(1, &atlas_texture_);
  if (label_texture_ != 0) gl_.DeleteTextures(1, &label_texture_);
  gl_.DeleteBuffers(1, &vertex_buffer_);
  gl_.DeleteVertexArrays(1, &vertex_array_);
  gl_.DeleteProgram(program_);
}

void GlRenderer::releaseFramebuffers() {
  if (multisample_framebuffer_ != 0) {
    gl_.DeleteFramebuffers(1, &multisample_framebuffer_);
    gl_.DeleteRenderbuffers(1, &multisample_colour_);
    gl_.DeleteFramebuffers(1, &resolved_framebuffer_);
    gl_.DeleteRenderbuffers(1, &resolved_colour_);
  }
  multisample_framebuffer_ = multisample_colour_ = resolved_framebuffer_ = resolved_colour_ = 0;
  width_px_ = height_px_ = 0;
}

void GlRenderer::resize(int width_px, int height_px) {
  if (width_px == width_px_ && height_px == height_px_) return;
  releaseFramebuffers();
  const auto make = [&](GLuint& framebuffer, GLuint& colour, int samples) {
    gl_.GenFramebuffers(1, &framebuffer);
    gl_.GenRenderbuffers(1, &colour);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, colour);
    if (samples > 1) {
      gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width_px, height_px);
    } else {
      gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_px, height_px);
    }
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw std::runtime_error("the OpenGL context cannot make a " + std::to_string(width_px) +
                               " x " + std::to_string(height_px) + " px framebuffer");
    }
  };
  make(multisample_framebuffer_, multisample_colour_, samples_);
  make(resolved_framebuffer_, resolved_colour_, 1);
  width_px_ = width_px;
  height_px_ = height_px;
}

void GlRenderer::draw(const Picture& picture, const Camera& camera) {
  validateImageSize(camera.width_px, camera.height_px);
  resize(camera.width_px, camera.height_px);

  std::vector<Vertex> vertices;
  std::vector<const Disc*> balls;
  const auto add = [&](const DrawItem& item) {
    if (const Mesh* mesh = std::get_if<Mesh>(&item)) {
      for (std::size_t i = 0; i + 2 < mesh->triangles_m.size(); i += 3) {
        addFlatTriangle(vertices, mesh->triangles_m[i], mesh->triangles_m[i + 1],
                        mesh->triangles_m[i + 2], mesh->z_m, mesh->colour);
      }
    } else if (const Stroke* stroke = std::get_if<Stroke>(&item)) {
      addStroke(vertices, *stroke);
    } else if (const Wall* wall = std::get_if<Wall>(&item)) {
      addWall(vertices, *wall);
    } else {
      addDisc(vertices, std::get<Disc>(item));
    }
  };
  for (const DrawItem& item : picture.items) {
    if (isBall(item)) {
      balls.push_back(&std::get<Disc>(item));
    } else {
      add(item);
    }
  }
  // Balls last, far to near (eye-space z grows towards the camera); ties keep picture order.
  const auto depth = [&](const Disc* d) { return (camera.view * d->centre_m.homogeneous()).z(); };
  std::stable_sort(balls.begin(), balls.end(),
                   [&](const Disc* a, const Disc* b) { return depth(a) < depth(b); });
  // Numbers need a font sized to the balls as drawn (the nearest ball in the angled view).
  double ball_radius_px = 0;
  for (const Disc* ball : balls) {
    if (ball->label.empty()) continue;
    const Eigen::Vector3d side = camera.view.block<1, 3>(0, 0).transpose() * ball->radius_m;
    ball_radius_px =
        std::max(ball_radius_px,
                 (camera.pixelOf(ball->centre_m + side) - camera.pixelOf(ball->centre_m)).norm());
  }
  const bool labels = ball_radius_px >= kMinLabelledBallRadius_px;
  if (labels) {
    const int size = std::clamp(static_cast<int>(std::lround(kLabelEmSize * ball_radius_px)),
                                kMinAtlasTextSize_px, kMaxAtlasTextSize_px);
    useAtlas(label_atlas_, label_texture_, size);
  }
  for (const Disc* ball : balls) {
    addDisc(vertices, *ball);
    if (labels && !ball->label.empty()) addBallLabel(vertices, *ball, *label_atlas_);
  }
  for (const DrawItem& item : picture.foreground) add(item);

  gl_.BindFramebuffer(GL_FRAMEBUFFER, multisample_framebuffer_);
  gl_.Viewport(0, 0, camera.width_px, camera.height_px);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  if (samples_ > 1) gl_.Enable(GL_MULTISAMPLE);
  gl_.ClearColor(picture.background.r, picture.background.g, picture.background.b, 1.0f);
  gl_.Clear(GL_COLOR_BUFFER_BIT);

  const Eigen::Matrix4f view = toFloat(camera.view), projection = toFloat(camera.projection);
  drawVertices(vertices.data(), vertices.size(), view.data(), projection.data());
  if (!picture.legend.empty()) drawLegend(picture, camera);

  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, multisample_framebuffer_);
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_framebuffer_);
  gl_.BlitFramebuffer(0, 0, width_px_, height_px_, 0, 0, width_px_, height_px_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  const GLenum error = gl_.GetError();
  if (error != GL_NO_ERROR) {
    throw std::runtime_error("OpenGL error " + std::to_string(error) + " while drawing");
  }
}

void GlRenderer::drawVertices(const void* vertices, std::size_t count, const float* view,
                              const float* projection) {
  gl_.UseProgram(program_);
  gl_.UniformMatrix4fv(view_location_, 1, GL_FALSE, view);  // Eigen is column-major too
  gl_.UniformMatrix4fv(projection_location_, 1, GL_FALSE, projection);
  gl_.Uniform1i(atlas_location_, 0);
  gl_.BindVertexArray(vertex_array_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(count * sizeof(Vertex)), vertices,
                 GL_STREAM_DRAW);
  gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(count));
}

// The legend in pixel coordinates (x right, y down from the top-left corner): a translucent
// panel, then per row a shaded ball swatch and the text.
void GlRenderer::drawLegend(const Picture& picture, const Camera& camera) {
  const std::vector<LegendRow>& legend = picture.legend;
  const int text_size = legendTextSize(height_px_);
  useAtlas(atlas_, atlas_texture_, text_size);
  const GlyphAtlas& atlas = *atlas_;
  const double line = atlas.lineHeight();
  const double pad = kLegendPadding * text_size;
  const double radius = kSwatchRadius * text_size;
  double text_width = 0;
  for (const LegendRow& row : legend) {
    text_width = std::max<double>(text_width,
                                  atlas.textWidth(row.text) + (row.swatch ? 2 * radius + pad : 0));
  }
  const double panel_width = 2 * pad + text_width;
  const double panel_height = 2 * pad + line * static_cast<double>(legend.size());
  // The corner where the panel hides least: fewest trace and marking points (sampled about a pixel
  // apart, so this measures line length), each ball and marker counting as much as a ball's width
  // of line. Ties go to the earlier corner: top left, top right, bottom left, bottom right.
  const Eigen::Vector2d corners[4] = {
      {kLegendMargin_px, kLegendMargin_px},
      {width_px_ - kLegendMargin_px - panel_width, kLegendMargin_px},
      {kLegendMargin_px, height_px_ - kLegendMargin_px - panel_height},
      {width_px_ - kLegendMargin_px - panel_width, height_px_ - kLegendMargin_px - panel_height}};
  double hidden[4] = {0, 0, 0, 0};
  const auto count = [&](const Eigen::Vector3d& point_m, double weight) {
    const Eigen::Vector2d p = camera.pixelOf(point_m);
    for (int k = 0; k < 4; ++k) {
      if (p.x() >= corners[k].x() && p.x() <= corners[k].x() + panel_width &&
          p.y() >= corners[k].y() && p.y() <= corners[k].y() + panel_height) {
        hidden[k] += weight;
      }
    }
  };
  for (const DrawItem& item : picture.items) {
    if (const Stroke* stroke = std::get_if<Stroke>(&item)) {
      for (const Eigen::Vector2d& p : stroke->points_m) count({p.x(), p.y(), stroke->z_m}, 1);
    } else if (const Disc* disc = std::get_if<Disc>(&item)) {
      const Eigen::Vector3d edge = disc->centre_m + Eigen::Vector3d(disc->radius_m, 0, 0);
      count(disc->centre_m, 2 * (camera.pixelOf(edge) - camera.pixelOf(disc->centre_m)).norm());
    }
  }
  const int best = static_cast<int>(std::min_element(hidden, hidden + 4) - hidden);
  const double left = corners[best].x(), top = corners[best].y();
  const double right = left + panel_width, bottom = top + panel_height;

  std::vector<Vertex> vertices;
  addFlatTriangle(vertices, {left, top}, {right, top}, {right, bottom}, 0, kLegendPanel);
  addFlatTriangle(vertices, {left, top}, {right, bottom}, {left, bottom}, 0, kLegendPanel);
  for (std::size_t i = 0; i < legend.size(); ++i) {
    const LegendRow& row = legend[i];
    const double row_top = top + pad + line * static_cast<double>(i);
    double pen_x = left + pad;
    if (row.swatch) {
      // In pixel space with y down, a sphere seen from +z looks lit from the lower left; the
      // swatch only needs to read as a ball of that colour.
      addDisc(vertices, Disc{Eigen::Vector3d(pen_x + radius, row_top + line / 2, 0),
                             radius,
                             row.colour,
                             row.striped ? DiscStyle::StripedBall : DiscStyle::Ball,
                             0,
                             {}});
      pen_x += 2 * radius + pad;
    }
    const double baseline = std::round(row_top + (line + atlas.ascender()) / 2 - line * 0.1);
    pen_x = std::round(pen_x);
    for (char c : row.text) {
      const Glyph& g = atlas.glyph(c);
      if (g.width > 0 && g.height > 0) {
        const double x0 = pen_x + g.bearing_x, y0 = baseline - g.bearing_y;
        const double x1 = x0 + g.width, y1 = y0 + g.height;
        const float u0 = static_cast<float>(g.x) / atlas.width();
        const float v0 = static_cast<float>(g.y) / atlas.height();
        const float u1 = static_cast<float>(g.x + g.width) / atlas.width();
        const float v1 = static_cast<float>(g.y + g.height) / atlas.height();
        const auto corner = [&](double x, double y, float u, float v) {
          put(vertices, Eigen::Vector3d(x, y, 0), kLegendText, u, v, kText, 0, 0);
        };
        corner(x0, y0, u0, v0);
        corner(x1, y0, u1, v0);
        corner(x1, y1, u1, v1);
        corner(x0, y0, u0, v0);
        corner(x1, y1, u1, v1);
        corner(x0, y1, u0, v1);
      }
      pen_x += g.advance;
    }
  }
  // Pixels to clip space: x from [0, W] to [-1, 1], y from [0, H] (down) to [1, -1].
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();
  projection(0, 0) = 2.0f / static_cast<float>(width_px_);
  projection(0, 3) = -1.0f;
  projection(1, 1) = -2.0f / static_cast<float>(height_px_);
  projection(1, 3) = 1.0f;
  const Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  drawVertices(vertices.data(), vertices.size(), view.data(), projection.data());
}

void GlRenderer::useAtlas(std::unique_ptr<GlyphAtlas>& atlas, GLuint& texture, int size) {
  gl_.ActiveTexture(GL_TEXTURE0);
  if (atlas && atlas->pixelSize() == size) {
    gl_.BindTexture(GL_TEXTURE_2D, texture);
    return;
  }
  atlas = std::make_unique<GlyphAtlas>(defaultFontPath(), size);
  if (texture == 0) gl_.GenTextures(1, &texture);
  gl_.BindTexture(GL_TEXTURE_2D, texture);
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas->width(), atlas->height(), 0, GL_RED,
                 GL_UNSIGNED_BYTE, atlas->coverage().data());
  // Legend glyphs land on whole pixels; ball numbers are scaled in the angled view.
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

int legendTextSize(int image_height_px) {
  return std::clamp(image_height_px / kLegendLinesPerImage, kMinLegendTextSize_px,
                    kMaxLegendTextSize_px);
}

Image GlRenderer::readImage() {
  if (resolved_framebuffer_ == 0) throw std::logic_error("readImage before any draw");
  Image image;
  image.width_px = width_px_;
  image.height_px = height_px_;
  const std::size_t row_bytes = static_cast<std::size_t>(width_px_) * 4;
  std::vector<std::uint8_t> bottom_up(row_bytes * height_px_);
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, resolved_framebuffer_);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.Finish();
  gl_.ReadPixels(0, 0, width_px_, height_px_, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  // OpenGL's rows start at the bottom; images start at the top.
  image.rgba.resize(bottom_up.size());
  for (int y = 0; y < height_px_; ++y) {
    std::copy_n(bottom_up.data() + (height_px_ - 1 - y) * row_bytes, row_bytes,
                image.rgba.data() + y * row_bytes);
  }
  const GLenum error = gl_.GetError();
  if (error != GL_NO_ERROR) {
    throw std::runtime_error("OpenGL error " + std::to_string(error) + " while reading pixels");
  }
  return image;
}

void GlRenderer::copyTo(unsigned framebuffer) {
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, resolved_framebuffer_);
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  gl_.BlitFramebuffer(0, 0, width_px_, height_px_, 0, 0, width_px_, height_px_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
}

std::string GlRenderer::glVersion() const {
  const auto text = [&](GLenum name) {
    const GLubyte* s = gl_.GetString(name);
    return s == nullptr ? std::string("?") : std::string(reinterpret_cast<const char*>(s));
  };
  return text(GL_VERSION) + " (" + text(GL_RENDERER) + ")";
}

}  // namespace baize::render

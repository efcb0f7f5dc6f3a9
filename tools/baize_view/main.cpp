// baize-view: plays a shot in a window. A scene is stepped through the event loop as the clock runs
// (a person can then aim, strike and strike again); a result file is played from its exact
// trajectories. See docs/render.md for the keys.
#include <SDL.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "engine/io/json_reader.h"
#include "engine/io/scene.h"
#include "render/camera.h"
#include "render/gl_renderer.h"
#include "render/png_writer.h"
#include "engine/io/whole_file.h"
#include "render/shot_picture.h"
#include "render/shot_record.h"
#include "tools/baize_view/playback.h"
#include "tools/baize_view/sdl_gl_context.h"
#include "tools/baize_view/table_session.h"

namespace baize::tools {
namespace {

constexpr int kExitUsage = 2;
constexpr int kExitFailure = 1;
// With --frames the clock steps by this much per frame, s: the same frames every run.
constexpr double kFixedFrameStep_s = 1.0 / 60;
// The aim line: this long per m/s of cue speed, m, and this wide in pixels.
constexpr double kAimLengthPerSpeed_m = 0.12;
constexpr double kAimWidth_px = 2.0;
// At most this many frames in --frames mode (ten minutes at 60 frames a second).
constexpr int kMaxFrames = 36000;
// A window's frames come at most this often, s, where the display does not pace them.
constexpr double kShortestFrame_s = 1.0 / 120;
// SDL's video drivers that open no window a person can see.
bool windowless(const char* driver) {
  return driver != nullptr &&
         (std::string(driver) == "offscreen" || std::string(driver) == "dummy");
}
// The clock's end while a scene's shot is still being stepped.
constexpr double kEndNotYetKnown = std::numeric_limits<double>::infinity();

struct ViewFlags {
  std::string input;
  int width_px = 1280;
  int height_px = 720;
  std::string view = "top";
  int frames = 0;  // 0: run until the window closes
  std::string screenshot_path;
};

bool isResult(const std::string& path) {
  const nlohmann::json document = engine::JsonReader::parseFile(path);
  return document.is_object() && document.contains("trajectories");
}

class Viewer {
 public:
  explicit Viewer(const ViewFlags& flags)
      : flags_(flags),
        view_(render::viewNamed(flags.view)),
        window_("baize-view", flags.width_px, flags.height_px),
        renderer_(window_) {
    if (flags.frames == 0 && windowless(SDL_GetCurrentVideoDriver())) {
      throw std::invalid_argument(
          std::string("there is no display to show a window on (SDL video driver '") +
          SDL_GetCurrentVideoDriver() +
          "'): run it where DISPLAY or WAYLAND_DISPLAY is set, or draw frames without one with "
          "--frames N --screenshot FILE");
    }
    if (isResult(flags.input)) {
      loaded_ = render::loadShotRecord(flags.input);
      playback_ = Playback(loaded_.end_time_s);
    } else {
      session_.emplace(engine::loadScene(flags.input));
      playback_ = Playback(kEndNotYetKnown);
    }
  }

  int run() {
    auto last = std::chrono::steady_clock::now();
    for (int frame = 1;; ++frame) {
      if (!handleEvents()) return 0;
      if (flags_.frames > 0) {
        playback_.advance(kFixedFrameStep_s);
      } else {
        const auto now = std::chrono::steady_clock::now();
        playback_.advance(std::chrono::duration<double>(now - last).count());
        last = now;
      }
      stepShot();
      drawFrame();
      if (flags_.frames > 0 && frame >= flags_.frames) {
        if (!flags_.screenshot_path.empty()) {
          render::writePng(renderer_.readImage(), flags_.screenshot_path);
          std::cout << "screenshot: " << flags_.screenshot_path << " (" << camera_.width_px << " x "
                    << camera_.height_px << " px, frame " << frame << ", t = " << std::fixed
                    << std::setprecision(3) << playback_.time_s() << " s)\n";
        }
        return 0;
      }
      window_.swap();
      updateTitle();
      paceFrame();
    }
  }

 private:
  bool handleEvents() {
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
      if (event.type == SDL_QUIT) return false;
      if (event.type == SDL_KEYDOWN) {
        switch (event.key.keysym.sym) {
          case SDLK_ESCAPE:
          case SDLK_q:
            return false;
          case SDLK_SPACE:
            playback_.togglePlaying();
            break;
          case SDLK_PLUS:
          case SDLK_EQUALS:
          case SDLK_KP_PLUS:
            playback_.faster();
            break;
          case SDLK_MINUS:
          case SDLK_KP_MINUS:
            playback_.slower();
            break;
          case SDLK_LEFT:
            playback_.scrub(-1);
            break;
          case SDLK_RIGHT:
            playback_.scrub(1);
            break;
          case SDLK_t:
            playback_.toggleTraces();
            break;
          case SDLK_l:
            legend_ = !legend_;
            break;
          case SDLK_r:
            playback_.restart();
            break;
          case SDLK_v:
            view_ = view_ == render::View::Top ? render::View::Angled : render::View::Top;
            break;
          case SDLK_UP:
            if (session_) session_->changeSpeed(1);
            break;
          case SDLK_DOWN:
            if (session_) session_->changeSpeed(-1);
            break;
          case SDLK_w:
            if (session_) session_->moveTip(0, 1);
            break;
          case SDLK_s:
            if (session_) session_->moveTip(0, -1);
            break;
          case SDLK_a:
            if (session_) session_->moveTip(-1, 0);
            break;
          case SDLK_d:
            if (session_) session_->moveTip(1, 0);
            break;
          default:
            break;
        }
      }
      if (event.type == SDL_MOUSEMOTION && canAim()) {
        aimAt(event.motion.x, event.motion.y);
      }
      if (event.type == SDL_MOUSEBUTTONDOWN && event.button.button == SDL_BUTTON_LEFT && canAim()) {
        aimAt(event.button.x, event.button.y);
        if (const std::optional<std::string> error = session_->strike()) {
          std::cerr << "baize-view: the shot was refused: " << *error << '\n';
        } else {
          playback_ = Playback(kEndNotYetKnown);
        }
      }
    }
    return true;
  }

  // Waits out the rest of kShortestFrame_s since the last frame: a display that does not pace
  // swaps would otherwise have the viewer spin a core.
  void paceFrame() {
    const auto now = std::chrono::steady_clock::now();
    const double spent_s = std::chrono::duration<double>(now - frame_start_).count();
    if (spent_s < kShortestFrame_s)
      SDL_Delay(static_cast<Uint32>((kShortestFrame_s - spent_s) * 1000) + 1);
    frame_start_ = std::chrono::steady_clock::now();
  }

  // The shot on show: the one being stepped, or the one read from a file.
  const render::ShotRecord& shot() const { return session_ ? session_->shot() : loaded_; }

  // Steps a scene's shot to the clock; once it is over, the clock's end is known.
  void stepShot() {
    if (!session_ || session_->atRest()) return;
    session_->advanceTo(playback_.time_s());
    if (!session_->atRest()) return;
    playback_.setEndTime(session_->shot().end_time_s);
    if (session_->failure())
      std::cerr << "baize-view: the shot failed: " << *session_->failure() << '\n';
  }

  bool canAim() const { return session_.has_value() && session_->atRest() && playback_.atEnd(); }

  void aimAt(int window_x, int window_y) {
    if (camera_.width_px == 0) return;
    int window_w = 0, window_h = 0;
    SDL_GetWindowSize(window_.window(), &window_w, &window_h);
    // Mouse positions are in window units; the drawable may be larger (high-density screens).
    const Eigen::Vector2d pixel(window_x * static_cast<double>(camera_.width_px) / window_w,
                                window_y * static_cast<double>(camera_.height_px) / window_h);
    const std::optional<Eigen::Vector2d> at = camera_.tablePointAt(pixel, shot().ball_set.radius_m);
    if (at) session_->aimAt(*at);
  }

  void drawFrame() {
    int w = 0, h = 0;
    window_.drawableSize(w, h);
    w = std::clamp(w, render::kMinImageSide_px, render::kMaxImageSide_px);
    h = std::clamp(h, render::kMinImageSide_px, render::kMaxImageSide_px);
    render::PictureOptions options;
    options.time_s = playback_.time_s();
    options.traces = playback_.traces();
    options.legend = legend_;
    options.pixel_size_m = render::pixelSizeFor(shot().table, w, h);
    render::Picture picture = render::buildShotPicture(shot(), options);
    if (canAim()) {
      const Eigen::Vector2d from = session_->cueBallAtRest();
      const double heading = session_->cue().heading_rad;
      const Eigen::Vector2d to = from + kAimLengthPerSpeed_m * session_->cue().speed_mps *
                                            Eigen::Vector2d(std::cos(heading), std::sin(heading));
      render::Stroke aim;
      aim.points_m = {from, to};
      aim.width_m = kAimWidth_px * options.pixel_size_m;
      aim.colour = render::Rgba{0.95f, 0.95f, 0.9f, 1};
      picture.items.emplace_back(std::move(aim));
    }
    camera_ = render::cameraFor(picture, view_, w, h);
    renderer_.draw(picture, camera_);
    renderer_.copyTo(0);
  }

  void updateTitle() {
    std::ostringstream title;
    title << std::fixed << std::setprecision(2) << "baize-view  t " << playback_.time_s() << " / ";
    if (std::isfinite(playback_.endTime_s()))
      title << playback_.endTime_s();
    else
      title << "...";
    title << " s  x" << playback_.speed() << (playback_.playing() ? "" : "  (paused)");
    if (session_) {
      title << "  |  cue " << session_->cue().speed_mps << " m/s, side "
            << session_->cue().side_offset << " R, height " << session_->cue().height_offset << " R"
            << (canAim() ? "  (click to strike)" : "");
    }
    if (title.str() != title_) {
      title_ = title.str();
      SDL_SetWindowTitle(window_.window(), title_.c_str());
    }
  }

  ViewFlags flags_;
  render::View view_;
  SdlGlContext window_;
  render::GlRenderer renderer_;
  render::ShotRecord loaded_;  // a result file's shot
  std::optional<TableSession> session_;
  Playback playback_;
  render::Camera camera_;
  std::string title_;
  bool legend_ = false;
  std::chrono::steady_clock::time_point frame_start_ = std::chrono::steady_clock::now();
};

int runViewer(const ViewFlags& flags) {
  try {
    render::validateImageSize(flags.width_px, flags.height_px);
    render::viewNamed(flags.view);
    if (flags.frames < 0 || flags.frames > kMaxFrames) {
      throw std::invalid_argument("--frames = " + std::to_string(flags.frames) +
                                  " is not allowed: it must lie in [0, " +
                                  std::to_string(kMaxFrames) + "]");
    }
    if (!flags.screenshot_path.empty() && flags.frames == 0) {
      throw std::invalid_argument("--screenshot needs --frames N (the frame to save)");
    }
    if (!flags.screenshot_path.empty()) {  // checked (parents made) before any drawing
      try {
        engine::prepareWholeFile(flags.screenshot_path);
      } catch (const std::invalid_argument& refused) {
        throw std::invalid_argument("--screenshot = " + flags.screenshot_path +
                                    " is not allowed: " + refused.what());
      }
    }
    Viewer viewer(flags);
    return viewer.run();
  } catch (const std::invalid_argument& e) {
    std::cerr << "baize-view: error: " << e.what() << '\n';
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "baize-view: error: " << e.what() << '\n';
    return kExitFailure;
  }
}

}  // namespace
}  // namespace baize::tools

int main(int argc, char** argv) {
  baize::tools::ViewFlags flags;
  CLI::App app{"baize-view: play a shot in a window; on a scene, aim and strike again",
               "baize-view"};
  app.add_option("input", flags.input, "a scene file or a result file (docs/results.md)")
      ->required();
  app.add_option("--width", flags.width_px, "window width, px (default 1280)");
  app.add_option("--height", flags.height_px, "window height, px (default 720)");
  app.add_option("--view", flags.view, "top (default) or angled; the v key switches");
  app.add_option("--frames", flags.frames,
                 "draw this many frames (1/60 s of the shot each) and exit, without a person");
  app.add_option("--screenshot", flags.screenshot_path,
                 "with --frames: save the last frame here (PNG)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == 0) return app.exit(error);
    std::cerr << "baize-view: error: " << error.what() << "\nRun 'baize-view --help' for usage.\n";
    return 2;
  }
  return baize::tools::runViewer(flags);
}

#pragma once
/// @file
/// Where the studio's frames go: a desktop window (GLFW), or headless frames drawn through EGL
/// into an offscreen image with simulated mouse and keys (tests, scripts, screenshots).

#include <imgui.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "reconfig/render/egl_context.h"
#include "reconfig/render/image.h"
#include "reconfig/render/render_target.h"
#include "key_queue.h"
#include "studio.h"

namespace reconfig::studio {

/// The ImGui context with the studio's style and the OpenGL 3 renderer backend; needs a
/// current GL 3.3 context. One at a time.
class UiContext {
 public:
  UiContext();
  ~UiContext();
  UiContext(const UiContext&) = delete;
  UiContext& operator=(const UiContext&) = delete;
};

/// The mouse and keyboard as a headless frame sees them. Keys are GLFW codes (keys.h).
struct SimulatedInput {
  ImVec2 mouse{-1, -1};
  bool buttons[3] = {false, false, false};  ///< left, right, middle
  float wheel = 0;                          ///< consumed by the next frame
  std::set<int> keys_down;                  ///< held for as long as they are in the set
  KeyQueue key_events;                      ///< presses and releases as a window gets them, any number per frame
  bool ctrl = false, shift = false, alt = false;
};

/// Headless studio: an EGL context, the UI and a frame image of a fixed size. Frames advance a
/// virtual clock by 1/60 s, so playback is deterministic; the collision service still runs on
/// its own thread in real time.
class HeadlessFrontend {
 public:
  HeadlessFrontend(int width, int height, StudioOptions options = {});
  ~HeadlessFrontend();

  Studio& studio() { return *studio_; }
  SimulatedInput& input() { return input_; }
  /// Runs one frame with the current input; returns its wall time in milliseconds (UI, 3D
  /// and drawing the UI, finished on the GL side).
  double run_frame();
  /// Runs frames until the collision picture describes the current design and the
  /// picture-in-picture it opened has found its view, or `timeout`.
  /// @return whether it got there
  bool run_until_collisions_current(std::chrono::milliseconds timeout);
  /// Runs frames while the picture-in-picture searches for its view, or until `deadline`.
  /// @return whether the search ended
  bool run_while_pip_searches(std::chrono::steady_clock::time_point deadline);
  /// The last frame's image.
  render::Image screenshot() const { return frame_.read_pixels(); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  render::EglContext context_;  // first: everything below needs it
  std::unique_ptr<UiContext> ui_;
  render::RenderTarget frame_;
  std::unique_ptr<Studio> studio_;
  SimulatedInput input_;
  std::set<int> queued_down_;  ///< keys down by the replayed `input_.key_events`
  int width_, height_;
  std::chrono::steady_clock::time_point clock_;
};

/// Runs the studio in a desktop window until the user quits, or for `frames` frames (> 0),
/// then saves the last one as `screenshot` (if not empty): a check that the window path works.
/// @throws render::ContextError when no window can be opened
void run_in_window(StudioOptions options, const std::optional<std::filesystem::path>& scene, int width, int height,
                   int frames = 0, const std::filesystem::path& screenshot = {});

}  // namespace reconfig::studio

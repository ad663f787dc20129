#include <epoxy/gl.h>
// After epoxy, which provides the GL declarations: GLFW must not include GL/gl.h.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "frontend.h"
#include "key_queue.h"
#include "keys.h"
#include "reconfig/render/glfw_window.h"
#include "reconfig/render/image.h"
#include "reconfig/render/render_target.h"

namespace reconfig::studio {

static_assert(keys::kSpace == GLFW_KEY_SPACE && keys::kA == GLFW_KEY_A && keys::kF == GLFW_KEY_F &&
                  keys::kG == GLFW_KEY_G && keys::kH == GLFW_KEY_H && keys::kI == GLFW_KEY_I &&
                  keys::kK == GLFW_KEY_K && keys::kO == GLFW_KEY_O && keys::kP == GLFW_KEY_P &&
                  keys::kS == GLFW_KEY_S && keys::kV == GLFW_KEY_V && keys::kZ == GLFW_KEY_Z &&
                  keys::kEscape == GLFW_KEY_ESCAPE && keys::kEnter == GLFW_KEY_ENTER && keys::kTab == GLFW_KEY_TAB &&
                  keys::kBackspace == GLFW_KEY_BACKSPACE && keys::kInsert == GLFW_KEY_INSERT &&
                  keys::kDelete == GLFW_KEY_DELETE && keys::kRight == GLFW_KEY_RIGHT && keys::kLeft == GLFW_KEY_LEFT &&
                  keys::kDown == GLFW_KEY_DOWN && keys::kUp == GLFW_KEY_UP && keys::kPageUp == GLFW_KEY_PAGE_UP &&
                  keys::kPageDown == GLFW_KEY_PAGE_DOWN && keys::kHome == GLFW_KEY_HOME && keys::kEnd == GLFW_KEY_END,
              "keys.h must use GLFW's key codes (every key it names)");

namespace {

KeyQueue* g_key_queue = nullptr;  // the open window's (one at a time)

/// Queues GLFW's key events instead of handing them to ImGui at once (key_queue.h); key
/// repeats are ImGui's own business (it repeats held keys itself).
void queue_key(GLFWwindow*, int key, int scancode, int action, int mods) {
  if (g_key_queue && action != GLFW_REPEAT) g_key_queue->push({key, action == GLFW_PRESS, scancode, mods});
}

}  // namespace

void run_in_window(StudioOptions options, const std::optional<std::filesystem::path>& scene, int width, int height,
                   int frames, const std::filesystem::path& screenshot) {
  render::GlfwWindow window("Reconfig Studio", width, height);
  UiContext ui;
  ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);
  KeyQueue key_queue;
  g_key_queue = &key_queue;
  glfwSetKeyCallback(window.handle(), queue_key);  // in place of the backend's, which it replays
  {
    Studio studio(std::move(options));
    if (scene) studio.open(*scene);
    std::string title;
    for (int frame = 1; !studio.quit_requested(); ++frame) {
      window.poll_events(1.0 / 60);
      if (window.close_requested()) {
        window.cancel_close();
        studio.request_close();
      }
      for (const KeyEvent& event : key_queue.take_frame())
        ImGui_ImplGlfw_KeyCallback(window.handle(), event.key, event.scancode, event.down ? GLFW_PRESS : GLFW_RELEASE,
                                   event.mods);
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      studio.frame(std::chrono::steady_clock::now());
      ImGui::Render();
      int fb_width = 0, fb_height = 0;
      window.framebuffer_size(fb_width, fb_height);
      glViewport(0, 0, fb_width, fb_height);
      glClearColor(0.9f, 0.9f, 0.92f, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (frames > 0 && frame >= frames) {
        if (!screenshot.empty()) render::write_png(screenshot, render::read_bound_framebuffer(fb_width, fb_height));
        break;
      }
      window.swap_buffers();
      const Document* document = studio.document();
      const std::string next = document ? "Reconfig Studio — " + document->file().filename().string() +
                                              (document->modified() ? " •" : "")
                                        : "Reconfig Studio";
      if (next != title) window.set_title(title = next);
    }
  }
  g_key_queue = nullptr;  // (the backend's shutdown restores the callbacks it found)
  ImGui_ImplGlfw_Shutdown();
}

}  // namespace reconfig::studio

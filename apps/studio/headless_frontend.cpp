#include <backends/imgui_impl_opengl3.h>
#include <epoxy/gl.h>

#include <thread>

#include "frontend.h"
#include "keys.h"

namespace reconfig::studio {

HeadlessFrontend::HeadlessFrontend(int width, int height, StudioOptions options)
    : ui_(std::make_unique<UiContext>()), width_(width), height_(height), clock_(std::chrono::steady_clock::now()) {
  ImGuiIO& io = ImGui::GetIO();
  // The same key map the GLFW backend installs, so text fields and navigation work too.
  io.KeyMap[ImGuiKey_Tab] = keys::kTab;
  io.KeyMap[ImGuiKey_LeftArrow] = keys::kLeft;
  io.KeyMap[ImGuiKey_RightArrow] = keys::kRight;
  io.KeyMap[ImGuiKey_UpArrow] = keys::kUp;
  io.KeyMap[ImGuiKey_DownArrow] = keys::kDown;
  io.KeyMap[ImGuiKey_PageUp] = keys::kPageUp;
  io.KeyMap[ImGuiKey_PageDown] = keys::kPageDown;
  io.KeyMap[ImGuiKey_Home] = keys::kHome;
  io.KeyMap[ImGuiKey_End] = keys::kEnd;
  io.KeyMap[ImGuiKey_Insert] = keys::kInsert;
  io.KeyMap[ImGuiKey_Delete] = keys::kDelete;
  io.KeyMap[ImGuiKey_Backspace] = keys::kBackspace;
  io.KeyMap[ImGuiKey_Space] = keys::kSpace;
  io.KeyMap[ImGuiKey_Enter] = keys::kEnter;
  io.KeyMap[ImGuiKey_Escape] = keys::kEscape;
  io.KeyMap[ImGuiKey_A] = keys::kA;
  io.KeyMap[ImGuiKey_Z] = keys::kZ;
  frame_.resize(width, height);
  studio_ = std::make_unique<Studio>(std::move(options));
}

HeadlessFrontend::~HeadlessFrontend() {
  studio_.reset();
  ui_.reset();
}

double HeadlessFrontend::run_frame() {
  const auto start = std::chrono::steady_clock::now();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = {static_cast<float>(width_), static_cast<float>(height_)};
  io.DeltaTime = 1.0f / 60;
  io.MousePos = input_.mouse;
  for (int b = 0; b < 3; ++b) io.MouseDown[b] = input_.buttons[b];
  io.MouseWheel = input_.wheel;
  input_.wheel = 0;
  for (const KeyEvent& event : input_.key_events.take_frame()) {
    if (event.down) queued_down_.insert(event.key);
    else queued_down_.erase(event.key);
  }
  for (bool& down : io.KeysDown) down = false;
  for (const int key : input_.keys_down) io.KeysDown[key] = true;
  for (const int key : queued_down_) io.KeysDown[key] = true;
  io.KeyCtrl = input_.ctrl;
  io.KeyShift = input_.shift;
  io.KeyAlt = input_.alt;

  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  clock_ += std::chrono::microseconds(16667);
  studio_->frame(clock_);
  ImGui::Render();
  frame_.bind();
  glClearColor(0.9f, 0.9f, 0.92f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  render::RenderTarget::unbind();
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool HeadlessFrontend::run_until_collisions_current(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    const Document* document = studio_->document();
    if (!document) return false;
    document->collisions().wait_until_complete(std::chrono::milliseconds(20));
    run_frame();
    const auto snapshot = studio_->collisions();
    if (snapshot && snapshot->complete && snapshot->version == document->version()) break;
    if (std::chrono::steady_clock::now() > deadline) return false;
  }
  run_frame();  // it may have come after the panels looked in the last one: now they all see it
  return run_while_pip_searches(deadline);
}

bool HeadlessFrontend::run_while_pip_searches(std::chrono::steady_clock::time_point deadline) {
  while (studio_->pip().searching()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    run_frame();
  }
  return true;
}

}  // namespace reconfig::studio

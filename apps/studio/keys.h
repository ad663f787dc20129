#pragma once
/// @file
/// Key codes the studio reads from ImGui's KeysDown[]: GLFW's codes (what the GLFW backend of
/// ImGui 1.86 writes there). The headless frontend injects the same codes, so scripts and
/// tests press the same keys a user does. glfw_frontend.cpp checks these against GLFW.

namespace reconfig::studio::keys {

constexpr int kSpace = 32;
constexpr int kA = 65;  ///< letters are their upper-case ASCII codes
constexpr int kF = 70;
constexpr int kG = 71;
constexpr int kH = 72;
constexpr int kI = 73;
constexpr int kK = 75;
constexpr int kO = 79;
constexpr int kP = 80;
constexpr int kS = 83;
constexpr int kV = 86;
constexpr int kZ = 90;
constexpr int kEscape = 256;
constexpr int kEnter = 257;
constexpr int kTab = 258;
constexpr int kBackspace = 259;
constexpr int kInsert = 260;
constexpr int kDelete = 261;
constexpr int kRight = 262;
constexpr int kLeft = 263;
constexpr int kDown = 264;
constexpr int kUp = 265;
constexpr int kPageUp = 266;
constexpr int kPageDown = 267;
constexpr int kHome = 268;
constexpr int kEnd = 269;

/// The code of a key name as scripts write it ("space", "delete", "left", "i", "z", …), or -1.
int from_name(const char* name);

}  // namespace reconfig::studio::keys

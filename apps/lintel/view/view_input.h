// The viewer's input, one path for both sources: a window's key and mouse callbacks and a
// --script file both produce InputEvents, and the frame loop applies them to an InputState.
// Script format (docs/view.md): one event per line, "FRAME ACTION ARGS", frames non-decreasing:
//   0 key down W        5 key up W        6 key press C        7 mouse down right
//   7 mouse move 20 -4  8 mouse up right   9 screenshot [FILE]  10 quit
// '#' starts a comment. Errors name the file and the line.
#pragma once

#include <lintel/status.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace lintel::view {

// Keys by their own codes: 'A'..'Z' and '0'..'9' as ASCII, the rest named below.
enum Key : int {
  kKeySpace = ' ',
  kKeyShift = 256,
  kKeyEscape = 257,
  kKeyCount = 258,
};
// "W", "w", "SHIFT", "SPACE", "ESCAPE" -> code; -1 for anything else.
int key_from_name(const std::string& name);

enum class InputType : uint8_t { KeyDown, KeyUp, MouseMove, MouseDown, MouseUp, Screenshot, Quit };

struct InputEvent {
  InputType type = InputType::KeyDown;
  int key = 0;                 // KeyDown/KeyUp
  int button = 0;              // MouseDown/MouseUp: 0 left, 1 right
  float dx = 0.0f, dy = 0.0f;  // MouseMove: pixels, +x right, +y down (as a window reports)
  std::string path;            // Screenshot: where (empty: --screenshot's path)
};

// What is held and what happened this frame.
struct InputState {
  std::array<bool, kKeyCount> down{};
  bool right_button = false;
  float look_dx = 0.0f, look_dy = 0.0f;  // mouse motion this frame while the right button was held
  std::vector<int> pressed;              // keys that went down this frame, in order (toggles)
  std::vector<std::string> screenshots;  // screenshot requests this frame (paths, maybe empty)
  bool quit = false;

  // Clears the per-frame parts (pressed, look, screenshots); held keys stay held.
  void begin_frame();
  void apply(const InputEvent& event);
};

struct ScriptEvent {
  uint64_t frame = 0;
  InputEvent event;
};

// Parses a script (the format above). `name` is used in messages ("FILE:LINE: fault").
Status parse_script(const std::string& text, const std::string& name, std::vector<ScriptEvent>& out);
Status load_script(const std::string& path, std::vector<ScriptEvent>& out);

// Hands out a script's events frame by frame.
class ScriptPlayer {
 public:
  explicit ScriptPlayer(std::vector<ScriptEvent> events) : events_(std::move(events)) {}
  // Applies every event of `frame` to `state`.
  void feed(uint64_t frame, InputState& state);
  bool finished() const { return next_ >= events_.size(); }

 private:
  std::vector<ScriptEvent> events_;
  size_t next_ = 0;
};

}  // namespace lintel::view

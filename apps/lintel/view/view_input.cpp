// Input events, their state, and the --script parser (format in view_input.h and docs/view.md).
#include "view_input.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lintel::view {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool parse_number(const std::string& text, float& out) {
  try {
    size_t used = 0;
    out = std::stof(text, &used);
    return used == text.size() && std::isfinite(out);
  } catch (const std::exception&) {
    return false;
  }
}

bool parse_frame(const std::string& text, uint64_t& out) {
  if (text.empty() || text.size() > 12) return false;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  out = std::stoull(text);
  return true;
}

// One line's action (the words after the frame number) -> events.
Status parse_action(const std::vector<std::string>& w, std::vector<InputEvent>& out) {
  const std::string action = w.empty() ? "" : w[0];
  auto need = [&](size_t n, const char* usage) -> Status {
    return w.size() == n ? Status() : Status::error("'" + action + "' expects: " + usage);
  };
  if (action == "key") {
    if (Status s = need(3, "key down|up|press KEY"); !s) return s;
    const int key = key_from_name(w[2]);
    if (key < 0) return Status::error("unknown key '" + w[2] + "' (A-Z, 0-9, shift, space, escape)");
    InputEvent e;
    e.key = key;
    if (w[1] == "down" || w[1] == "press") {
      e.type = InputType::KeyDown;
      out.push_back(e);
    }
    if (w[1] == "up" || w[1] == "press") {
      e.type = InputType::KeyUp;
      out.push_back(e);
    }
    if (out.empty()) return Status::error("key '" + w[1] + "': expected down, up or press");
    return {};
  }
  if (action == "mouse") {
    if (w.size() >= 2 && w[1] == "move") {
      if (Status s = need(4, "mouse move DX DY"); !s) return s;
      InputEvent e;
      e.type = InputType::MouseMove;
      if (!parse_number(w[2], e.dx) || !parse_number(w[3], e.dy))
        return Status::error("mouse move: '" + w[2] + " " + w[3] + "' is not two finite numbers");
      out.push_back(e);
      return {};
    }
    if (Status s = need(3, "mouse down|up left|right, or mouse move DX DY"); !s) return s;
    InputEvent e;
    if (w[1] == "down")
      e.type = InputType::MouseDown;
    else if (w[1] == "up")
      e.type = InputType::MouseUp;
    else
      return Status::error("mouse '" + w[1] + "': expected down, up or move");
    if (w[2] == "left")
      e.button = 0;
    else if (w[2] == "right")
      e.button = 1;
    else
      return Status::error("mouse button '" + w[2] + "': expected left or right");
    out.push_back(e);
    return {};
  }
  if (action == "screenshot") {
    if (w.size() > 2) return Status::error("'screenshot' expects: screenshot [FILE]");
    InputEvent e;
    e.type = InputType::Screenshot;
    if (w.size() == 2) e.path = w[1];
    out.push_back(e);
    return {};
  }
  if (action == "quit") {
    if (Status s = need(1, "quit"); !s) return s;
    InputEvent e;
    e.type = InputType::Quit;
    out.push_back(e);
    return {};
  }
  return Status::error("unknown action '" + action + "' (key, mouse, screenshot, quit)");
}

}  // namespace

int key_from_name(const std::string& name) {
  const std::string u = upper(name);
  if (u.size() == 1 &&
      (std::isupper(static_cast<unsigned char>(u[0])) || std::isdigit(static_cast<unsigned char>(u[0]))))
    return u[0];
  if (u == "SHIFT") return kKeyShift;
  if (u == "SPACE") return kKeySpace;
  if (u == "ESCAPE" || u == "ESC") return kKeyEscape;
  return -1;
}

void InputState::begin_frame() {
  pressed.clear();
  screenshots.clear();
  look_dx = look_dy = 0.0f;
}

void InputState::apply(const InputEvent& e) {
  switch (e.type) {
    case InputType::KeyDown:
      if (e.key >= 0 && e.key < kKeyCount) {
        if (!down[size_t(e.key)]) pressed.push_back(e.key);
        down[size_t(e.key)] = true;
      }
      break;
    case InputType::KeyUp:
      if (e.key >= 0 && e.key < kKeyCount) down[size_t(e.key)] = false;
      break;
    case InputType::MouseMove:
      if (right_button) {
        look_dx += e.dx;
        look_dy += e.dy;
      }
      break;
    case InputType::MouseDown:
      if (e.button == 1) right_button = true;
      break;
    case InputType::MouseUp:
      if (e.button == 1) right_button = false;
      break;
    case InputType::Screenshot:
      screenshots.push_back(e.path);
      break;
    case InputType::Quit:
      quit = true;
      break;
  }
}

Status parse_script(const std::string& text, const std::string& name, std::vector<ScriptEvent>& out) {
  out.clear();
  std::istringstream in(text);
  std::string line;
  uint64_t previous = 0;
  for (size_t number = 1; std::getline(in, line); ++number) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty()) continue;
    const std::string where = name + ":" + std::to_string(number) + ": ";
    uint64_t frame = 0;
    if (!parse_frame(w[0], frame))
      return Status::error(where + "'" + w[0] + "' is not a frame number (a line is: FRAME ACTION ARGS)");
    if (frame < previous)
      return Status::error(where + "frame " + std::to_string(frame) + " comes after frame " + std::to_string(previous) +
                           " (frames must not decrease)");
    previous = frame;
    std::vector<InputEvent> events;
    if (Status s = parse_action(std::vector<std::string>(w.begin() + 1, w.end()), events); !s)
      return Status::error(where + s.message());
    for (InputEvent& e : events) out.push_back({frame, std::move(e)});
  }
  return {};
}

Status load_script(const std::string& path, std::vector<ScriptEvent>& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::error(path + ": cannot open the script");
  // A script is typed by hand or written by a test: 16 MiB is far beyond either, and keeps a
  // wrong file (a video, /dev/zero) from being read whole.
  constexpr size_t kMaxScriptBytes = size_t(16) << 20;
  std::string text(kMaxScriptBytes + 1, '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(size_t(in.gcount()));
  if (text.size() > kMaxScriptBytes) return Status::error(path + ": script larger than 16 MiB");
  if (text.find('\0') != std::string::npos) return Status::error(path + ": not a text file (NUL byte)");
  return parse_script(text, path, out);
}

void ScriptPlayer::feed(uint64_t frame, InputState& state) {
  while (next_ < events_.size() && events_[next_].frame <= frame) state.apply(events_[next_++].event);
}

}  // namespace lintel::view

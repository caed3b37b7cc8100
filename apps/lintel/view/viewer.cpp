// The viewer's frame loop (see viewer.h). One thread: Renderer::render submits and waits on the
// same queue the presenter submits to, and Vulkan requires a queue's users to be serialised.
#include "viewer.h"

#include "overlay.h"

#include <lintel/render/image_io.h>
#include <lintel/timeline.h>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace lintel::view {
namespace {

const char* cull_name(render::CameraCull c) {
  switch (c) {
    case render::CameraCull::Portal:
      return "PORTAL";
    case render::CameraCull::PortalHiz:
      return "PORTAL+HIZ";
    case render::CameraCull::Frustum:
      return "FRUSTUM";
    default:
      return "NONE";
  }
}

const char* const kViewNames[] = {"FINAL", "ALBEDO", "NORMAL", "DEPTH", "SHADOW", "GI", "AO"};
constexpr uint32_t kViewCount = 7;

std::string fixed(double v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// GLFW key -> the viewer's Key code (view_input.h); -1 for keys the viewer ignores.
int key_from_glfw(int key) {
  if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9)) return key;  // ASCII
  if (key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT) return kKeyShift;
  if (key == GLFW_KEY_ESCAPE) return kKeyEscape;
  if (key == GLFW_KEY_SPACE) return kKeySpace;
  return -1;
}

WindowInputQueue& queue_of(GLFWwindow* w) { return *static_cast<WindowInputQueue*>(glfwGetWindowUserPointer(w)); }

void on_key(GLFWwindow* w, int key, int, int action, int) {
  const int k = key_from_glfw(key);
  if (k < 0 || action == GLFW_REPEAT) return;
  InputEvent e;
  e.type = action == GLFW_PRESS ? InputType::KeyDown : InputType::KeyUp;
  e.key = k;
  queue_of(w).events.push_back(e);
}

void on_button(GLFWwindow* w, int button, int action, int) {
  if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) return;
  InputEvent e;
  e.type = action == GLFW_PRESS ? InputType::MouseDown : InputType::MouseUp;
  e.button = button == GLFW_MOUSE_BUTTON_RIGHT ? 1 : 0;
  // While looking around the cursor is hidden and unbounded, so a turn is not stopped by the
  // screen's edge; GLFW keeps reporting (virtual) positions, which on_cursor turns into moves.
  if (e.button == 1) glfwSetInputMode(w, GLFW_CURSOR, action == GLFW_PRESS ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
  queue_of(w).events.push_back(e);
}

void on_cursor(GLFWwindow* w, double x, double y) {
  WindowInputQueue& q = queue_of(w);
  if (q.cursor_known) {
    InputEvent e;
    e.type = InputType::MouseMove;
    e.dx = float(x - q.cursor_x);
    e.dy = float(y - q.cursor_y);
    q.events.push_back(e);
  }
  q.cursor_x = x, q.cursor_y = y, q.cursor_known = true;
}

}  // namespace

Viewer::Viewer(World& world, WindowDevice& device, const ViewerOptions& options, const View& start,
               std::optional<std::vector<ScriptEvent>> script)
    : world_(world), device_(device), options_(options), camera_(start) {
  if (script) script_.emplace(std::move(*script));
  const int doorway = world_.find_timeline("doorway");
  if (!world_.timelines.empty()) timeline_ = &world_.timelines[size_t(std::max(0, doorway))];
  if (timeline_) timeline_t_ = timeline_->keys.front().t;
}

Viewer::~Viewer() {
  if (presenter_) (void)presenter_->wait_idle();
  renderer_.reset();
  context_.reset();
  presenter_.reset();
  if (device_.window()) glfwSetWindowUserPointer(device_.window(), nullptr);
}

Status Viewer::open() {
  if (Status s = gpu::Context::wrap(device_.external(), context_); !s) return s;
  if (Status s = Presenter::create(device_, options_.render.width, options_.render.height, presenter_); !s) return s;
  if (Status s = rebuild_renderer(); !s) return s;
  if (GLFWwindow* w = device_.window()) {
    glfwSetWindowUserPointer(w, &window_input_);
    glfwSetKeyCallback(w, &on_key);
    glfwSetMouseButtonCallback(w, &on_button);
    glfwSetCursorPosCallback(w, &on_cursor);
  }
  return check_validation();
}

Status Viewer::rebuild_renderer() {
  if (presenter_)
    if (Status s = presenter_->wait_idle(); !s) return s;
  renderer_.reset();
  // Per-pixel cell ids feed the tint overlay; the frame's colours do not depend on them.
  options_.render.readback_cells = true;
  if (Status s = render::Renderer::create(*context_, world_, options_.render, renderer_); !s) return s;
  if (!renderer_->setup_note().empty() && !options_.quiet)
    std::fprintf(stderr, "lintel: note: %s\n", renderer_->setup_note().c_str());
  return {};
}

Status Viewer::check_validation() {
  const std::vector<std::string> messages = device_.take_validation_messages();
  if (messages.empty()) return {};
  std::string first = messages.front();
  for (char& c : first)
    if (c == '\n' || c == '\r') c = ' ';
  return Status::internal("validation (" + std::to_string(messages.size()) + " messages): " + first);
}

void Viewer::gather_window_input(InputState& state) {
  glfwPollEvents();
  for (const InputEvent& e : window_input_.events) state.apply(e);
  window_input_.events.clear();
  if (glfwWindowShouldClose(device_.window())) state.quit = true;
}

Status Viewer::handle_toggles(const InputState& input) {
  bool rebuild = false;
  for (int key : input.pressed) {
    switch (key) {
      case 'C':
        options_.render.camera_cull =
            options_.render.camera_cull == render::CameraCull::Portal      ? render::CameraCull::PortalHiz
            : options_.render.camera_cull == render::CameraCull::PortalHiz ? render::CameraCull::Frustum
            : options_.render.camera_cull == render::CameraCull::Frustum   ? render::CameraCull::None
                                                                           : render::CameraCull::Portal;
        rebuild = true;
        break;
      case 'G':
        options_.render.gi = !options_.render.gi, rebuild = true;
        break;
      case 'O':
        options_.render.ao = !options_.render.ao, rebuild = true;
        break;
      case 'V':
        options_.render.view = (options_.render.view + 1) % kViewCount;
        if (renderer_ && !rebuild)
          if (Status s = renderer_->set_debug_view(options_.render.view); !s) return s;
        break;
      case 'P':
        options_.play_timeline = timeline_ && !options_.play_timeline;
        break;
      case 'H':
        options_.overlays = !options_.overlays;
        break;
      default:
        break;
    }
  }
  return rebuild ? rebuild_renderer() : Status();
}

void Viewer::update_camera(const InputState& input, float dt_s) {
  if (options_.play_timeline && timeline_) {
    // This frame shows the current time; the clock then advances for the next one, so frame f of a
    // scripted run is the timeline at start + f / 30 s, as `lintel walk` numbers its frames at 30 fps.
    View v = timeline_view(*timeline_, timeline_t_);
    v.aspect = camera_.view().aspect;
    camera_.set(v);
    timeline_t_ += dt_s;
    if (timeline_t_ > timeline_->keys.back().t) timeline_t_ = timeline_->keys.front().t;  // loop
    return;
  }
  camera_.update(input, dt_s);
}

std::vector<std::string> Viewer::hud_lines(double build_us, double frame_ms) const {
  const uint32_t cell = tracker_.cell();
  std::vector<std::string> lines;
  lines.push_back("CELL " + world_.cells[cell].name + "  LAST " + last_transition_);
  lines.push_back("CELLS " + std::to_string(visible_.cells.size()) + "  INSTANCES " +
                  std::to_string(visible_.instances.size()) + "  POPS " + std::to_string(visible_.stats.pops) +
                  "  BUILD " + fixed(build_us, 1) + " US  FRAME " +
                  (frame_ms > 0.0 ? fixed(frame_ms, 1) + " MS" : std::string("-")));  // the first frame has no previous
  std::string state = std::string("CULL ") + cull_name(options_.render.camera_cull) + "  VIEW " +
                      kViewNames[options_.render.view % kViewCount] + "  GI " + (options_.render.gi ? "ON" : "OFF") +
                      "  AO " + (options_.render.ao ? "ON" : "OFF");
  if (timeline_)
    state += "  TIMELINE " + std::string(options_.play_timeline ? "PLAY " : "PAUSE ") + fixed(timeline_t_, 1) + " S";
  lines.push_back(state);
  return lines;
}

Status Viewer::save_screenshot(const std::string& path, const std::vector<uint8_t>& rgba8, ViewerSummary& summary) {
  if (Status s = render::write_png(path, {options_.render.width, options_.render.height, rgba8}); !s) return s;
  summary.screenshots.push_back(path);
  return {};
}

Status Viewer::run(ViewerSummary& summary) {
  summary = {};
  InputState input;
  render::RenderedFrame frame;
  std::vector<uint8_t> presented;
  std::vector<double> frame_ms;
  double last_frame_ms = 0.0;
  const float script_dt_s = 1.0f / 30.0f;  // scripted runs step a fixed time: the same script, the same path
  auto previous = std::chrono::steady_clock::now();

  for (uint64_t f = 0; options_.max_frames == 0 || f < options_.max_frames; ++f) {
    const auto t_start = std::chrono::steady_clock::now();
    input.begin_frame();
    if (script_) script_->feed(f, input);
    if (device_.window()) gather_window_input(input);
    // Quit (script, Escape, window closed) ends the run after this frame, so that a screenshot
    // asked for in the same frame is still taken.
    const bool last = input.quit || input.down[kKeyEscape];
    if (Status s = handle_toggles(input); !s) return s;
    const float dt_s = script_ ? script_dt_s : std::min(0.1f, std::chrono::duration<float>(t_start - previous).count());
    previous = t_start;
    update_camera(input, dt_s);
    View view = camera_.view();
    view.aspect = float(options_.render.width) / float(options_.render.height);
    if (Status s = validate_view(view); !s) return Status::error("camera: " + s.message());

    if (Status s = f == 0 ? tracker_.reset(world_, view.eye_world) : tracker_.update(world_, view.eye_world); !s)
      return s;
    for (const CellTransition& t : tracker_.transitions())
      last_transition_ = (t.from == kNoCell ? std::string("START") : world_.cells[t.from].name) + " -> " +
                         world_.cells[t.to].name + " (" + transition_reason_name(t.reason) + ")";
    const auto t0 = std::chrono::steady_clock::now();
    if (Status s = builder_.build(world_, view, tracker_.cell(), options_.render.visibility, visible_); !s) return s;
    const double build_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();

    // The frame from the visible set just built (the renderer builds none of its own).
    if (Status s = renderer_->render(visible_, view, frame); !s) return s;
    if (options_.overlays) {
      const Canvas canvas{frame.rgba8.data(), int(frame.width), int(frame.height)};
      tint_cells(canvas, frame.cell_ids, kNoCell);
      outline_regions(canvas, visible_, tracker_.cell());
      draw_hud(canvas, hud_lines(build_us, last_frame_ms), frame.height >= 480 ? 2 : 1);
    }
    const bool shoot = !input.screenshots.empty();
    if (Status s = presenter_->present(frame.rgba8, shoot ? &presented : nullptr); !s) return s;
    for (const std::string& p : input.screenshots)
      if (Status s = save_screenshot(p.empty() ? options_.screenshot : p, presented, summary); !s) return s;
    if (Status s = check_validation(); !s) return s;

    last_frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_start).count();
    frame_ms.push_back(last_frame_ms);
    summary.frames = f + 1;
    summary.last_view = view;
    summary.last_cell = tracker_.cell();
    if (last || (script_ && script_->finished() && options_.max_frames == 0)) break;
  }
  // --screenshot with no scripted screenshot: the last frame, presented once more and read back.
  if (!options_.screenshot.empty() && summary.screenshots.empty() && summary.frames > 0) {
    if (Status s = presenter_->present(frame.rgba8, &presented); !s) return s;
    if (Status s = save_screenshot(options_.screenshot, presented, summary); !s) return s;
  }
  if (Status s = presenter_->wait_idle(); !s) return s;
  if (Status s = check_validation(); !s) return s;
  if (!frame_ms.empty()) {
    std::sort(frame_ms.begin(), frame_ms.end());
    summary.median_frame_ms = frame_ms[frame_ms.size() / 2];
  }
  return {};
}

}  // namespace lintel::view

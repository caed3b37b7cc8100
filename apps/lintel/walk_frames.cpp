#include "walk_frames.h"

#include "cli_common.h"

#include <lintel/file_commit.h>
#include <lintel/render/image_io.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace lintel::cli {
namespace {

bool ffmpeg_available() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

}  // namespace

Status WalkFrames::init(const World& world, const std::string& dir, const RenderArgs& args, const std::string& device) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path parent = fs::absolute(fs::path(dir), ec).parent_path();
  if (!fs::is_directory(parent)) return Status::error("--frames " + dir + ": parent directory does not exist");
  const fs::file_status existing = fs::symlink_status(dir, ec);
  if (fs::is_symlink(existing))
    return Status::error("--frames " + dir + ": is a symbolic link; refusing to write through it (pass its target)");
  if (fs::exists(existing) && !fs::is_directory(existing))
    return Status::error("--frames " + dir + ": exists and is not a directory");
  dir_ = dir;
  args_ = args;
  args_.device = device;
  render::RenderOptions options;
  if (Status s = render_options_from(args_, options); !s) return s;
  options.gi_persist = true;
  // The renderer first: a missing device or feature then leaves no empty folder behind.
  if (Status s = open_render_session(world, args_, options, session_); !s) return s;
  fs::create_directory(dir, ec);
  if (!fs::is_directory(fs::symlink_status(dir, ec)))
    return Status::error("--frames " + dir + ": cannot create the directory");
  return {};
}

void WalkFrames::note_moved(std::span<const uint32_t> moved) {
  if (moved.empty()) return;
  const size_t before = moved_.size();
  moved_.insert(moved_.end(), moved.begin(), moved.end());
  std::inplace_merge(moved_.begin(), moved_.begin() + std::ptrdiff_t(before), moved_.end());
  moved_.erase(std::unique(moved_.begin(), moved_.end()), moved_.end());
}

Status WalkFrames::render(size_t frame, const View& view, const VisibleSet& visible, const World& world) {
  if (Status s = session_.renderer->update_world(world, moved_); !s) return s;
  moved_.clear();
  render::RenderedFrame out;
  if (Status s = session_.renderer->render(visible, view, out); !s) return s;
  total_ms_ += out.wall_ms;
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05zu.png", frame);
  const std::string path = (std::filesystem::path(dir_) / name).string();
  if (Status s = render::write_png(path, {out.width, out.height, std::move(out.rgba8)}); !s) return s;
  written_.push_back(path);
  return {};
}

Status WalkFrames::finish(double fps, bool quiet) {
  if (written_.empty()) return {};
  // At most 24 tiles, evenly spread over the walk.
  const size_t tiles = std::min<size_t>(24, written_.size());
  std::vector<render::Rgba8Image> frames;
  for (size_t k = 0; k < tiles; ++k) {
    render::Rgba8Image img;
    const size_t i = tiles == 1 ? 0 : k * (written_.size() - 1) / (tiles - 1);
    if (Status s = render::read_png(written_[i], img); !s) return s;
    frames.push_back(std::move(img));
  }
  const std::string sheet = (std::filesystem::path(dir_) / "contact_sheet.png").string();
  if (Status s = render::write_png(sheet, render::contact_sheet(frames, 6, 320)); !s) return s;
  if (!quiet)
    std::printf("frames: %zu PNGs in %s, contact sheet %s\n", written_.size(), printable(dir_).c_str(),
                printable(sheet).c_str());
  if (ffmpeg_available()) {
    // ffmpeg writes a fresh temporary (never the target itself, which may be a link or a device);
    // commit_temporary checks the target again and renames.
    const std::string mp4 = (std::filesystem::path(dir_) / "walk.mp4").string();
    std::string tmp;
    if (Status s = make_temporary_beside(mp4, ".mp4", tmp); !s) return s;
    const std::string cmd = "ffmpeg -y -loglevel error -framerate " + std::to_string(fps) + " -i " +
                            shell_quote(dir_ + "/frame_%05d.png") +
                            " -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' " + shell_quote(tmp);
    if (std::system(cmd.c_str()) != 0) {
      std::remove(tmp.c_str());
      return Status::error("ffmpeg failed to write " + mp4);
    }
    if (Status s = commit_temporary(tmp, mp4); !s) return s;
    if (!quiet) std::printf("video: %s\n", printable(mp4).c_str());
  } else if (!quiet) {
    std::printf("video: skipped (ffmpeg not found)\n");
  }
  return {};
}

}  // namespace lintel::cli

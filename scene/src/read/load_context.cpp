// Message formatting for the scene loader: one line, file first, element second, fault last.
#include "read/load_context.h"

#include <cmath>
#include <cstdio>

namespace lintel::scene_read {

LoadContext::LoadContext(std::string label, std::vector<std::string>* warnings)
    : label_(one_line(label, 4096)), warnings_(warnings) {}  // PATH_MAX: paths stay whole

static std::string compose(const std::string& label, std::string_view element, std::string_view fault) {
  std::string out = label;
  if (!element.empty()) out += ": " + one_line(element, 240);
  out += ": " + one_line(fault, 400);
  return out;
}

Status LoadContext::fail(std::string_view element, std::string_view fault) const {
  return Status::error(compose(label_, element, fault));
}

void LoadContext::warn(std::string_view element, std::string_view fault) const {
  if (warnings_) warnings_->push_back(compose(label_, element, fault));
}

std::string describe(std::string_view kind, size_t index, std::string_view name) {
  std::string out = std::string(kind) + " " + std::to_string(index);
  if (!name.empty()) out += " '" + one_line(name, 64) + "'";
  return out;
}

std::string one_line(std::string_view text, size_t max_chars) {
  // Trailing newlines are common in library messages; drop them instead of showing '?'.
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.remove_suffix(1);
  std::string out;
  out.reserve(text.size() < max_chars ? text.size() : max_chars);
  for (char c : text) {
    if (out.size() >= max_chars) {
      out += "...";
      break;
    }
    const unsigned char u = static_cast<unsigned char>(c);
    out += (u < 0x20 || u == 0x7f) ? '?' : c;
  }
  return out;
}

std::string number_text(double value) {
  char buf[40];
  // Whole numbers print exactly ("100000000", not "1e+08"), so that a value just over a limit does
  // not read as equal to it; others keep six significant digits.
  if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15)
    std::snprintf(buf, sizeof buf, "%.0f", value);
  else
    std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

}  // namespace lintel::scene_read

// parse_gltf_json: a DOM builder that does what nlohmann's own does, except that it steps over
// the left-out values, looking only at their integers; driven by the simple parser
// (json_simple_parse.h) and, where that declines, by nlohmann's SAX parser (the one json::parse
// runs), which gives every error message.
#include "read/gltf_json.h"

#include "read/gltf_compact.h"
#include "read/json_bounded.h"
#include "read/json_simple_parse.h"

#include <cstdint>
#include <exception>
#include <string_view>
#include <vector>

namespace lintel::scene_read {
namespace {

using nlohmann::json;

// Where a container sits, as far as the left-out parts need to know.
enum class Role : uint8_t { Other, Root, Accessors, Accessor };

// nlohmann::detail::json_sax_dom_parser (the DOM of json::parse: a repeated key keeps its last
// value), minus the left-out values.
class GltfDomBuilder {
 public:
  // With `compact`, the root's "accessors" and "meshes" go to it instead of the DOM.
  explicit GltfDomBuilder(CompactReader* compact = nullptr) : compact_(compact) {}

  json root;
  bool left_out_integer_too_wide = false;
  // An integer outside 32 bits in the kept DOM, outside every "extras" and "extensions" (the
  // integers preflight checks): while false, preflight need not walk the DOM for one.
  bool kept_integer_too_wide = false;

  bool null() { return compacting_ ? compact_->other() : scalar(nullptr); }
  bool boolean(bool v) { return compacting_ ? compact_->boolean(v) : scalar(v); }
  bool number_integer(json::number_integer_t v) {
    if (compacting_) return compact_->integer(v, true);
    if (skipping()) return left_out_integer(v < INT32_MIN || v > INT32_MAX);
    note_integer(v < INT32_MIN || v > INT32_MAX);
    return scalar(v);
  }
  bool number_unsigned(json::number_unsigned_t v) {
    if (compacting_) return compact_->integer(int64_t(v), v <= uint64_t(INT64_MAX));
    if (skipping()) return left_out_integer(v > uint64_t(INT32_MAX));
    note_integer(v > uint64_t(INT32_MAX));
    return scalar(v);
  }
  bool number_float(json::number_float_t v, const json::string_t&) {
    return compacting_ ? compact_->other() : scalar(v);
  }
  bool string(json::string_t& v) {  // moved from: the parsers reset it after
    return compacting_ ? compact_->string(v) : scalar(std::move(v));
  }
  bool binary(json::binary_t& v) { return scalar(std::move(v)); }

  bool start_object(std::size_t) { return compacting_ ? compact_->start_object() : start(json::value_t::object); }
  bool start_array(std::size_t) { return compacting_ ? compact_->start_array() : start(json::value_t::array); }
  bool end_object() { return end(); }
  bool end_array() { return end(); }

  bool key(json::string_t& k) {
    if (compacting_) return compact_->key(k);
    if (skip_depth_ > 0) return true;
    const Role role = stack_.back().role;
    if (compact_ && role == Role::Root && (k == "accessors" || k == "meshes")) {
      compacting_ = true;
      return compact_->begin(k == "meshes" ? CompactReader::Section::Meshes : CompactReader::Section::Accessors);
    }
    next_is_accessors_ = role == Role::Root && k == "accessors";
    if (role == Role::Accessor && (k == "min" || k == "max")) {
      skip_next_ = true;
      return true;
    }
    if (exempt_level_ == 0 && is_exempt_key(k)) exempt_next_ = true;
    // try_emplace: operator[]'s element (a repeated key keeps its slot), the key moved, not copied.
    object_element_ = &stack_.back().node->get_ref<json::object_t&>().try_emplace(std::move(k)).first->second;
    return true;
  }

  // As json::parse: the parse error itself, thrown.
  template <class Exception>
  bool parse_error(std::size_t, const std::string&, const Exception& ex) {
    throw ex;
  }

 private:
  struct Frame {
    json* node;
    Role role;
  };

  bool skipping() const { return skip_depth_ > 0 || skip_next_; }

  // "extras" or "extensions", the length compared first: this runs for every key of the document.
  static bool is_exempt_key(const std::string& k) {
    return (k.size() == 6 && k == "extras") || (k.size() == 10 && k == "extensions");
  }

  void note_integer(bool too_wide) {
    if (too_wide && !exempt_next_ && exempt_level_ == 0) kept_integer_too_wide = true;
  }

  bool left_out_integer(bool too_wide) {
    left_out_integer_too_wide = left_out_integer_too_wide || too_wide;
    skip_next_ = false;
    return true;
  }

  template <typename Value>
  bool scalar(Value&& v) {
    if (skipping()) {
      skip_next_ = false;
      return true;
    }
    add(json(std::forward<Value>(v)));
    exempt_next_ = false;
    return true;
  }

  bool start(json::value_t type) {
    if (skip_depth_ > 0 || skip_next_) {
      ++skip_depth_;
      skip_next_ = false;
      return true;
    }
    Role role = Role::Other;
    if (stack_.empty())
      role = type == json::value_t::object ? Role::Root : Role::Other;
    else if (stack_.back().role == Role::Root && next_is_accessors_ && type == json::value_t::array)
      role = Role::Accessors;
    else if (stack_.back().role == Role::Accessors && type == json::value_t::object)
      role = Role::Accessor;
    stack_.push_back({add(json(type)), role});
    if (exempt_next_) {
      exempt_level_ = stack_.size();
      exempt_next_ = false;
    }
    return true;
  }

  bool end() {
    if (compacting_) {
      const bool ok = compact_->end();
      compacting_ = compact_->active();
      return ok;
    }
    if (skip_depth_ > 0) {
      --skip_depth_;
      return true;
    }
    if (exempt_level_ == stack_.size()) exempt_level_ = 0;
    stack_.pop_back();
    return true;
  }

  json* add(json&& v) {
    if (stack_.empty()) {
      root = std::move(v);
      return &root;
    }
    json& parent = *stack_.back().node;
    if (parent.is_array()) {
      json::array_t& array = parent.get_ref<json::array_t&>();
      array.push_back(std::move(v));
      return &array.back();
    }
    *object_element_ = std::move(v);
    return object_element_;
  }

  std::vector<Frame> stack_;  // the open containers that are kept
  json* object_element_ = nullptr;
  bool next_is_accessors_ = false;  // the root's key just read is "accessors"
  bool skip_next_ = false;          // the value after a left-out key is left out
  size_t skip_depth_ = 0;           // > 0: inside a left-out container, this deep
  bool exempt_next_ = false;        // the value after an "extras" or "extensions" key is exempt
  size_t exempt_level_ = 0;         // > 0: inside an exempt container, opened at this stack size
  CompactReader* compact_;          // null: everything goes to the DOM
  bool compacting_ = false;         // the events are compact_'s (inside "accessors" or "meshes")
};

}  // namespace

std::string parse_gltf_json(const char* text, size_t size, nlohmann::json& out, bool* integers_fit,
                            CompactSections* compact) {
  if (integers_fit) *integers_fit = false;
  if (compact) {
    *compact = {};
    CompactReader reader(*compact);
    GltfDomBuilder builder(&reader);
    if (parse_simple_json(text, size, builder, kMaxJsonDepth, kMaxJsonValues) && !builder.left_out_integer_too_wide) {
      if (integers_fit) *integers_fit = !builder.kept_integer_too_wide;
      out = std::move(builder.root);
      return {};
    }
    *compact = {};  // not clean (or not simple): the whole document goes to the DOM
  }
  {
    GltfDomBuilder builder;
    if (parse_simple_json(text, size, builder, kMaxJsonDepth, kMaxJsonValues) && !builder.left_out_integer_too_wide) {
      if (integers_fit) *integers_fit = !builder.kept_integer_too_wide;
      out = std::move(builder.root);
      return {};
    }
  }
  // Everything the simple parser declined, from the start: the limits, nlohmann's parse, and
  // the whole DOM when a left-out integer is too wide.
  if (std::string why = json_bounds_error(text, size); !why.empty()) return why;
  GltfDomBuilder builder;
  try {
    json::sax_parse(text, text + size, &builder);
  } catch (const std::exception& e) {
    return json_parse_error_text(e);
  }
  // Preflight must see that integer where it is: the whole document, as parse_json_bounded reads it.
  if (builder.left_out_integer_too_wide) return parse_json_bounded(text, size, out);
  if (integers_fit) *integers_fit = !builder.kept_integer_too_wide;
  out = std::move(builder.root);
  return {};
}

}  // namespace lintel::scene_read

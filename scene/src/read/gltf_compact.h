// The two largest arrays of an imported level's glTF -- "accessors" and "meshes", two thirds of
// its JSON values -- read straight from the parser's events into tinygltf's Accessor and Mesh
// structs, without a DOM node per key. Building and freeing those nodes (a few hundred thousand
// small heap blocks) was most of what loading still cost after the JSON was parsed once.
//
// Only clean content is taken: every field one the loader reads, of the right JSON type, within
// 32 bits and valid (a known accessor type and component type, a positive count, no negative
// index). Anything else -- an "extras", a sparse accessor, a string where an index belongs -- makes
// the reader refuse (`clean()` false), and the loader parses the text again into the DOM, whose
// checks give the message they always gave (gltf_preflight.cpp, gltf_model_data.cpp).
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::scene_read {

// TINYGLTF_TYPE_* of an accessor's "type" string, -1 when it is not one of glTF's seven.
int gltf_accessor_type(const std::string& type);

struct CompactSections {
  bool has_accessors = false;  // the root had an "accessors" array (then `accessors` is it)
  bool has_meshes = false;
  std::vector<tinygltf::Accessor> accessors;
  std::vector<tinygltf::Mesh> meshes;
};

// Fed the SAX events of the value of a root key "accessors" or "meshes", from the array's start
// to its end. Each call returns false once the content is not clean (then stop: the result is void).
class CompactReader {
 public:
  enum class Section : uint8_t { Accessors, Meshes };

  explicit CompactReader(CompactSections& out) : out_(out) {}

  // The root key just read is `section`'s; its value must be an array (checked at the next event).
  bool begin(Section section);
  bool active() const { return !frames_.empty() || expecting_array_; }

  bool start_object();
  bool start_array();
  bool end();  // end of an object or array
  bool key(const std::string& k);
  bool integer(int64_t v, bool fits_int64);
  bool string(std::string& v);
  bool boolean(bool v);
  bool other();  // null, a float: never clean where the loader reads

 private:
  enum class Frame : uint8_t { AccessorArray, Accessor, MeshArray, Mesh, PrimitiveArray, Primitive, Attributes };
  // The field the next value goes to.
  enum class Field : uint8_t {
    None,
    BufferView,
    ByteOffset,
    ComponentType,
    Count,
    Type,
    Normalized,
    AccessorName,
    Skip,  // an accessor's min/max: read past, its integers only checked to fit 32 bits
    MeshName,
    Primitives,
    Attributes,
    Attribute,
    Indices,
    Material,
    Mode,
  };

  CompactSections& out_;
  std::vector<Frame> frames_;
  std::vector<uint16_t> seen_;  // per open frame: the fields given so far (bit per Field)
  bool expecting_array_ = false;
  Section section_ = Section::Accessors;
  Field field_ = Field::None;
  std::string attribute_;  // the attribute whose index comes next
  size_t skip_depth_ = 0;  // inside min/max: containers open
};

}  // namespace lintel::scene_read

// CompactReader: a small state machine over the SAX events of "accessors" and "meshes". It only
// ever says yes to content the DOM path would read into the same structs without a fault; every
// doubt is a refusal (see gltf_compact.h), so it has no messages of its own.
#include "read/gltf_compact.h"

namespace lintel::scene_read {
namespace {

bool fits_int32(int64_t v) { return v >= INT32_MIN && v <= INT32_MAX; }

bool component_type(int64_t v) { return v == 5120 || v == 5121 || v == 5122 || v == 5123 || v == 5125 || v == 5126; }

}  // namespace

int gltf_accessor_type(const std::string& type) {
  if (type == "SCALAR") return TINYGLTF_TYPE_SCALAR;
  if (type == "VEC2") return TINYGLTF_TYPE_VEC2;
  if (type == "VEC3") return TINYGLTF_TYPE_VEC3;
  if (type == "VEC4") return TINYGLTF_TYPE_VEC4;
  if (type == "MAT2") return TINYGLTF_TYPE_MAT2;
  if (type == "MAT3") return TINYGLTF_TYPE_MAT3;
  if (type == "MAT4") return TINYGLTF_TYPE_MAT4;
  return -1;
}

bool CompactReader::begin(Section section) {
  // A repeated root key: the DOM keeps the last value; simpler to let the DOM path have it.
  if ((section == Section::Accessors && out_.has_accessors) || (section == Section::Meshes && out_.has_meshes))
    return false;
  section_ = section;
  expecting_array_ = true;
  return true;
}

bool CompactReader::start_array() {
  if (skip_depth_ > 0 || field_ == Field::Skip) {
    ++skip_depth_;
    field_ = Field::None;
    return true;
  }
  if (expecting_array_) {
    expecting_array_ = false;
    const bool accessors = section_ == Section::Accessors;
    (accessors ? out_.has_accessors : out_.has_meshes) = true;
    frames_.push_back(accessors ? Frame::AccessorArray : Frame::MeshArray);
    seen_.push_back(0);
    return true;
  }
  if (field_ != Field::Primitives) return false;
  field_ = Field::None;
  frames_.push_back(Frame::PrimitiveArray);
  seen_.push_back(0);
  return true;
}

bool CompactReader::start_object() {
  if (skip_depth_ > 0 || field_ == Field::Skip) {
    ++skip_depth_;
    field_ = Field::None;
    return true;
  }
  if (expecting_array_ || frames_.empty()) return false;
  const Frame top = frames_.back();
  if (top == Frame::AccessorArray && field_ == Field::None) {
    tinygltf::Accessor& a = out_.accessors.emplace_back();
    a.bufferView = -1;
    a.byteOffset = 0;
    a.sparse.isSparse = false;
    frames_.push_back(Frame::Accessor);
  } else if (top == Frame::MeshArray && field_ == Field::None) {
    out_.meshes.emplace_back();
    frames_.push_back(Frame::Mesh);
  } else if (top == Frame::PrimitiveArray && field_ == Field::None) {
    tinygltf::Primitive& p = out_.meshes.back().primitives.emplace_back();
    p.mode = TINYGLTF_MODE_TRIANGLES;  // glTF's default, as the DOM path sets it
    frames_.push_back(Frame::Primitive);
  } else if (top == Frame::Primitive && field_ == Field::Attributes) {
    field_ = Field::None;
    frames_.push_back(Frame::Attributes);
  } else {
    return false;
  }
  seen_.push_back(0);
  return true;
}

bool CompactReader::end() {
  if (skip_depth_ > 0) {
    --skip_depth_;
    return true;
  }
  if (frames_.empty() || field_ != Field::None) return false;
  const Frame top = frames_.back();
  const uint16_t seen = seen_.back();
  frames_.pop_back();
  seen_.pop_back();
  if (top == Frame::Accessor) {  // componentType, count and type are required
    const uint16_t required = 1u << int(Field::ComponentType) | 1u << int(Field::Count) | 1u << int(Field::Type);
    return (seen & required) == required;
  }
  if (top == Frame::Primitive) return (seen & 1u << int(Field::Attributes)) != 0;
  return true;
}

bool CompactReader::key(const std::string& k) {
  if (skip_depth_ > 0) return true;
  if (frames_.empty() || field_ != Field::None) return false;
  Field field = Field::None;
  switch (frames_.back()) {
    case Frame::Accessor:
      if (k == "bufferView")
        field = Field::BufferView;
      else if (k == "byteOffset")
        field = Field::ByteOffset;
      else if (k == "componentType")
        field = Field::ComponentType;
      else if (k == "count")
        field = Field::Count;
      else if (k == "type")
        field = Field::Type;
      else if (k == "normalized")
        field = Field::Normalized;
      else if (k == "name")
        field = Field::AccessorName;
      else if (k == "min" || k == "max")
        field = Field::Skip;
      break;
    case Frame::Mesh:
      if (k == "name")
        field = Field::MeshName;
      else if (k == "primitives")
        field = Field::Primitives;
      break;
    case Frame::Primitive:
      if (k == "attributes")
        field = Field::Attributes;
      else if (k == "indices")
        field = Field::Indices;
      else if (k == "material")
        field = Field::Material;
      else if (k == "mode")
        field = Field::Mode;
      break;
    case Frame::Attributes:
      if (out_.meshes.back().primitives.back().attributes.count(k)) return false;  // given twice
      attribute_ = k;
      field_ = Field::Attribute;
      return true;
    default:
      return false;
  }
  if (field == Field::None) return false;  // a key the loader does not read: the DOM path decides
  uint16_t& seen = seen_.back();
  if (field != Field::Skip) {
    if (seen & 1u << int(field)) return false;  // given twice: the DOM keeps the last, let it
    seen |= uint16_t(1u << int(field));
  }
  field_ = field;
  return true;
}

bool CompactReader::integer(int64_t v, bool fits_int64) {
  if (skip_depth_ > 0 || field_ == Field::Skip) {
    if (field_ == Field::Skip) field_ = Field::None;
    return fits_int64 && fits_int32(v);  // a wide integer in min/max: the DOM path reports it
  }
  if (!fits_int64 || !fits_int32(v) || frames_.empty()) return false;
  const int i = int(v);
  const Field field = field_;
  field_ = Field::None;
  switch (field) {
    case Field::BufferView:
      out_.accessors.back().bufferView = i;
      return i >= 0;
    case Field::ByteOffset:
      out_.accessors.back().byteOffset = size_t(i);
      return i >= 0;
    case Field::ComponentType:
      out_.accessors.back().componentType = i;
      return component_type(v);
    case Field::Count:
      out_.accessors.back().count = size_t(i);
      return i >= 1;
    case Field::Attribute:
      out_.meshes.back().primitives.back().attributes.emplace(attribute_, i);
      return true;
    case Field::Indices:
      out_.meshes.back().primitives.back().indices = i;
      return i >= 0;
    case Field::Material:
      out_.meshes.back().primitives.back().material = i;
      return i >= 0;
    case Field::Mode:
      out_.meshes.back().primitives.back().mode = i;
      return true;
    default:
      return false;
  }
}

bool CompactReader::string(std::string& v) {
  if (skip_depth_ > 0) return true;
  const Field field = field_;
  field_ = Field::None;
  switch (field) {
    case Field::Skip:
      return true;
    case Field::Type:
      out_.accessors.back().type = gltf_accessor_type(v);
      return out_.accessors.back().type >= 0;
    case Field::AccessorName:
      out_.accessors.back().name = std::move(v);
      return true;
    case Field::MeshName:
      out_.meshes.back().name = std::move(v);
      return true;
    default:
      return false;
  }
}

bool CompactReader::boolean(bool v) {
  if (skip_depth_ > 0) return true;
  const Field field = field_;
  field_ = Field::None;
  if (field == Field::Skip) return true;
  if (field != Field::Normalized) return false;
  out_.accessors.back().normalized = v;
  return true;
}

bool CompactReader::other() {
  if (skip_depth_ > 0) return true;
  const bool skipped = field_ == Field::Skip;
  field_ = Field::None;
  return skipped;
}

}  // namespace lintel::scene_read

// Accessor -> checked byte range -> values. Reads go through memcpy, so unaligned data (which
// the spec forbids but writers produce) is read correctly instead of trapping.
#include "read/accessor_read.h"

#include "read/load_limits.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lintel::scene_read {
namespace {

struct ByteRange {
  const uint8_t* first = nullptr;  // element 0
  size_t count = 0;
  size_t stride = 0;
};

size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

std::string element_text(const std::string& element, const std::string& role) { return element + " (" + role + ")"; }

// Proves count elements of `element_size` bytes at the accessor's offset and stride fit in the
// buffer view, and the view in its buffer's loaded bytes. All sums in 64 bits, count checked
// against the view length before it multiplies anything.
Status locate_in_view(const LoadContext& ctx, const tinygltf::Model& model, int buffer_view, size_t byte_offset,
                      size_t count, const std::string& element, size_t element_size, bool strided, ByteRange& out) {
  if (buffer_view < 0 || size_t(buffer_view) >= model.bufferViews.size())
    return ctx.fail(element, "bufferView " + std::to_string(buffer_view) + " does not exist");
  const tinygltf::BufferView& view = model.bufferViews[size_t(buffer_view)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    return ctx.fail(
        element, "bufferView " + std::to_string(buffer_view) + " names missing buffer " + std::to_string(view.buffer));
  const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
  const uint64_t view_end = uint64_t(view.byteOffset) + uint64_t(view.byteLength);
  if (view_end > data.size())
    return ctx.fail(element, "bufferView " + std::to_string(buffer_view) + " ends at byte " + std::to_string(view_end) +
                                 ", buffer " + std::to_string(view.buffer) + " has " + std::to_string(data.size()));
  const uint64_t stride = strided && view.byteStride ? view.byteStride : element_size;
  if (stride < element_size)
    return ctx.fail(element, "byteStride " + std::to_string(stride) + " is smaller than the element (" +
                                 std::to_string(element_size) + " bytes)");
  if (count == 0) return ctx.fail(element, "count is 0");
  if (count > view.byteLength || byte_offset > view.byteLength)
    return ctx.fail(element, "count " + std::to_string(count) + " at byteOffset " + std::to_string(byte_offset) +
                                 " exceeds bufferView " + std::to_string(buffer_view) + " (" +
                                 std::to_string(view.byteLength) + " bytes)");
  const uint64_t needed = uint64_t(byte_offset) + stride * (uint64_t(count) - 1) + element_size;
  if (needed > view.byteLength)
    return ctx.fail(element, "count " + std::to_string(count) + " x stride " + std::to_string(stride) + " needs " +
                                 std::to_string(needed) + " bytes, bufferView " + std::to_string(buffer_view) +
                                 " has " + std::to_string(view.byteLength));
  out.first = data.data() + view.byteOffset + byte_offset;
  out.count = count;
  out.stride = static_cast<size_t>(stride);
  return {};
}

// An accessor's own elements in its buffer view (index accessors: no sparse, a bufferView).
Status locate(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Accessor& a,
              const std::string& element, size_t element_size, ByteRange& out) {
  if (a.sparse.isSparse) return ctx.fail(element, "a sparse accessor cannot hold indices");
  if (a.bufferView < 0) return ctx.fail(element, "has no bufferView (indices must be stored)");
  return locate_in_view(ctx, model, a.bufferView, a.byteOffset, a.count, element, element_size, true, out);
}

uint32_t index_component(const uint8_t* p, size_t size) {
  if (size == 1) return *p;
  if (size == 2) {
    uint16_t v;
    std::memcpy(&v, p, 2);
    return v;
  }
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

const tinygltf::Accessor* find_accessor(const tinygltf::Model& model, int index) {
  if (index < 0 || size_t(index) >= model.accessors.size()) return nullptr;
  return &model.accessors[size_t(index)];
}

// One 8- or 16-bit integer component of a vertex attribute as a float (texture coordinates in
// core glTF, positions and normals under KHR_mesh_quantization): its value, or with `normalized`
// mapped to [0, 1] (unsigned) or [-1, 1] (signed, the most negative value clamped), as glTF 2.0
// defines normalized integers. FLOAT components are copied as they are (read_float_accessor).
float integer_component(const uint8_t* p, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = float(int8_t(*p));
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? float(*p) / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t s;
      std::memcpy(&s, p, 2);
      return normalized ? std::max(float(s) / 32767.0f, -1.0f) : float(s);
    }
    default: {  // UNSIGNED_SHORT (vertex_component_type admits no other)
      uint16_t u;
      std::memcpy(&u, p, 2);
      return normalized ? float(u) / 65535.0f : float(u);
    }
  }
}

bool vertex_component_type(int component_type) {
  return component_type == TINYGLTF_COMPONENT_TYPE_FLOAT || component_type == TINYGLTF_COMPONENT_TYPE_BYTE ||
         component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || component_type == TINYGLTF_COMPONENT_TYPE_SHORT ||
         component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

// VEC2/VEC3 vertex accessors (FLOAT, or 8/16-bit integers: integer_component): one reader, the
// vector width as a parameter.
template <int N>
Status read_float_accessor(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& role,
                           ReadBudget& budget, std::vector<glm::vec<N, float>>& out) {
  static_assert(N >= 2 && N <= 4);
  const int type = N == 2 ? TINYGLTF_TYPE_VEC2 : N == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
  const std::string element = element_text("accessor " + std::to_string(accessor), role);
  const tinygltf::Accessor* a = find_accessor(model, accessor);
  if (!a) return ctx.fail(element, "does not exist (" + std::to_string(model.accessors.size()) + " accessors)");
  if (a->type != type || !vertex_component_type(a->componentType))
    return ctx.fail(element, "must be VEC" + std::to_string(N) +
                                 " of FLOAT (componentType 5126) or of 8- or 16-bit integers (5120-5123), got type " +
                                 std::to_string(a->type) + " componentType " + std::to_string(a->componentType));
  const size_t component = component_size(a->componentType);
  // Without a bufferView the elements are zeros (glTF 2.0), which a sparse part may replace.
  ByteRange range;
  if (a->bufferView >= 0) {
    if (Status s =
            locate_in_view(ctx, model, a->bufferView, a->byteOffset, a->count, element, component * N, true, range);
        !s)
      return s;
  } else if (a->count == 0) {
    return ctx.fail(element, "count is 0");
  } else if (a->count > kMaxZeroFilledElements) {
    return ctx.fail(element, "count " + std::to_string(a->count) + " without a bufferView is more than " +
                                 std::to_string(kMaxZeroFilledElements) + " zeros");
  }
  const size_t count = a->count;
  if (count > kMaxTotalVertices - budget.vertices)
    return ctx.fail(element, "more than " + std::to_string(kMaxTotalVertices) + " vertices in the scene");
  budget.vertices += count;
  const size_t base = out.size();
  out.resize(base + count, glm::vec<N, float>(0.0f));
  const bool floats = a->componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  auto decode = [&](const uint8_t* p, size_t i) -> Status {
    float values[N];
    if (floats) {  // the common case: one copy per element
      std::memcpy(values, p, sizeof values);
    } else {
      for (int c = 0; c < N; ++c)
        values[c] = integer_component(p + size_t(c) * component, a->componentType, a->normalized);
    }
    for (int c = 0; c < N; ++c) {
      const float v = values[c];
      if (!std::isfinite(v)) {
        out.resize(base);
        return ctx.fail(element, "element " + std::to_string(i) + " is not finite (NaN or Inf)");
      }
      out[base + i][c] = v;
    }
    return {};
  };
  if (a->bufferView >= 0)
    for (size_t i = 0; i < count; ++i)
      if (Status s = decode(range.first + i * range.stride, i); !s) return s;
  if (!a->sparse.isSparse) return {};
  // Sparse: `count` strictly increasing element indices, and as many replacement values, tightly
  // packed in their own buffer views.
  const auto& sparse = a->sparse;
  auto refuse = [&](const std::string& why) {
    out.resize(base);
    return ctx.fail(element, "sparse " + why);
  };
  if (sparse.count <= 0 || size_t(sparse.count) > count)
    return refuse("count " + std::to_string(sparse.count) + " is not in 1.." + std::to_string(count));
  const int ict = sparse.indices.componentType;
  if (ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    return refuse("indices componentType " + std::to_string(ict) + " is not UNSIGNED_BYTE/SHORT/INT");
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) return refuse("byteOffset is negative");
  ByteRange indices, values;
  if (Status s = locate_in_view(ctx, model, sparse.indices.bufferView, size_t(sparse.indices.byteOffset),
                                size_t(sparse.count), element + " sparse indices", component_size(ict), false, indices);
      !s) {
    out.resize(base);
    return s;
  }
  if (Status s = locate_in_view(ctx, model, sparse.values.bufferView, size_t(sparse.values.byteOffset),
                                size_t(sparse.count), element + " sparse values", component * N, false, values);
      !s) {
    out.resize(base);
    return s;
  }
  for (size_t k = 0; k < size_t(sparse.count); ++k) {
    const uint32_t i = index_component(indices.first + k * indices.stride, indices.stride);
    if (i >= count) return refuse("index " + std::to_string(i) + " at position " + std::to_string(k) + " is >= count");
    if (k > 0 && i <= index_component(indices.first + (k - 1) * indices.stride, indices.stride))
      return refuse("indices are not strictly increasing at position " + std::to_string(k));
    if (Status s = decode(values.first + k * values.stride, i); !s) return s;
  }
  return {};
}

}  // namespace

Status read_vec3_accessor(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& role,
                          ReadBudget& budget, std::vector<glm::vec3>& out) {
  return read_float_accessor<3>(ctx, model, accessor, role, budget, out);
}

Status read_vec2_accessor(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& role,
                          ReadBudget& budget, std::vector<glm::vec2>& out) {
  return read_float_accessor<2>(ctx, model, accessor, role, budget, out);
}

Status read_color_accessor(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& role,
                           ReadBudget& budget, std::vector<glm::vec4>& out) {
  const std::string element = element_text("accessor " + std::to_string(accessor), role);
  const tinygltf::Accessor* a = find_accessor(model, accessor);
  if (!a) return ctx.fail(element, "does not exist (" + std::to_string(model.accessors.size()) + " accessors)");
  // glTF 2.0 allows exactly these for COLOR_n; an integer colour that is not normalized would be
  // read as 0..255 and clamped to white, a silent wrong picture.
  const int ct = a->componentType;
  const bool integer = ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  if ((a->type != TINYGLTF_TYPE_VEC3 && a->type != TINYGLTF_TYPE_VEC4) ||
      (ct != TINYGLTF_COMPONENT_TYPE_FLOAT && !integer) || (integer && !a->normalized))
    return ctx.fail(element,
                    "must be VEC3 or VEC4 of FLOAT (componentType 5126) or of normalized UNSIGNED_BYTE or "
                    "UNSIGNED_SHORT (5121, 5123), got type " +
                        std::to_string(a->type) + " componentType " + std::to_string(ct) +
                        (integer ? " not normalized" : ""));
  const size_t base = out.size();
  if (a->type == TINYGLTF_TYPE_VEC4) {
    if (Status s = read_float_accessor<4>(ctx, model, accessor, role, budget, out); !s) return s;
  } else {
    std::vector<glm::vec3> rgb;
    if (Status s = read_float_accessor<3>(ctx, model, accessor, role, budget, rgb); !s) return s;
    for (const glm::vec3& c : rgb) out.emplace_back(c, 1.0f);
  }
  // Linear colour in [0, 1] (glTF 2.0); exporters' float rounding just outside it is clamped.
  for (size_t i = base; i < out.size(); ++i) out[i] = glm::clamp(out[i], glm::vec4(0.0f), glm::vec4(1.0f));
  return {};
}

Status read_index_accessor(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& role,
                           size_t vertex_count, uint32_t base, ReadBudget& budget, std::vector<uint32_t>& out) {
  const std::string element = element_text("accessor " + std::to_string(accessor), role);
  const tinygltf::Accessor* a = find_accessor(model, accessor);
  if (!a) return ctx.fail(element, "does not exist (" + std::to_string(model.accessors.size()) + " accessors)");
  const int ct = a->componentType;
  if (a->type != TINYGLTF_TYPE_SCALAR ||
      (ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
       ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
    return ctx.fail(element, "indices must be SCALAR of UNSIGNED_BYTE/SHORT/INT, got type " + std::to_string(a->type) +
                                 " componentType " + std::to_string(ct));
  const size_t size = component_size(ct);
  ByteRange range;
  if (Status s = locate(ctx, model, *a, element, size, range); !s) return s;
  if (range.count > kMaxTotalIndices - budget.indices)
    return ctx.fail(element, "more than " + std::to_string(kMaxTotalIndices) + " indices in the scene");
  budget.indices += range.count;
  const size_t first = out.size();
  out.resize(first + range.count);
  for (size_t i = 0; i < range.count; ++i) {
    const uint32_t index = index_component(range.first + i * range.stride, size);
    if (index >= vertex_count) {
      out.resize(first);
      return ctx.fail(element, "index " + std::to_string(index) + " at position " + std::to_string(i) +
                                   " is >= the vertex count " + std::to_string(vertex_count));
    }
    out[first + i] = base + index;
  }
  return {};
}

}  // namespace lintel::scene_read

// Material -> texture -> image -> decoded RGBA8, with every index checked and the image's size
// read from its header before a texel is allocated. stb_image (Debian's libstb) decodes; only PNG
// and JPEG, the two formats core glTF 2.0 allows, are accepted (stb would take a dozen more).
#include "read/texture_read.h"

#include "read/file_read.h"
#include "read/gltf_preflight.h"
#include "read/load_limits.h"
#include "read/uri_path.h"

#include <tiny_gltf.h>

#include <stb/stb_image.h>

#include <climits>
#include <cstring>
#include <memory>

namespace lintel::scene_read {
namespace {

std::string stb_reason() {
  const char* why = stbi_failure_reason();
  return why ? why : "unknown reason";
}

}  // namespace

TextureTable::TextureTable(const LoadContext& ctx, const tinygltf::Model& model, std::string base_dir,
                           std::vector<Texture>& textures)
    : ctx_(ctx),
      model_(model),
      base_dir_(std::move(base_dir)),
      textures_(textures),
      slot_of_image_(model.images.size(), -1) {}

Status TextureTable::base_color_texture(int material, int& out, TextureSampler& sampler) {
  return texture_of(model_.materials[size_t(material)].pbrMetallicRoughness.baseColorTexture,
                    "materials[" + std::to_string(material) + "].pbrMetallicRoughness.baseColorTexture", out, sampler);
}

Status TextureTable::emissive_texture(int material, int& out, TextureSampler& sampler) {
  return texture_of(model_.materials[size_t(material)].emissiveTexture,
                    "materials[" + std::to_string(material) + "].emissiveTexture", out, sampler);
}

Status TextureTable::texture_of(const tinygltf::TextureInfo& info, const std::string& element, int& out,
                                TextureSampler& sampler) {
  out = -1;
  sampler = TextureSampler{};
  if (info.index == -1) return {};  // tinygltf's "absent"
  if (info.index < 0 || size_t(info.index) >= model_.textures.size())
    return ctx_.fail(element, "texture index " + std::to_string(info.index) + " does not exist (" +
                                  std::to_string(model_.textures.size()) + " textures)");
  const tinygltf::Texture& texture = model_.textures[size_t(info.index)];
  const std::string texture_element = "textures[" + std::to_string(info.index) + "]";
  if (texture.source < 0)
    return ctx_.fail(texture_element, "has no source image (extension-only sources are not supported)");
  if (size_t(texture.source) >= model_.images.size())
    return ctx_.fail(texture_element, "source image " + std::to_string(texture.source) + " does not exist (" +
                                          std::to_string(model_.images.size()) + " images)");
  if (Status s = read_sampler(texture.sampler, sampler); !s) return s;
  return decode_image(size_t(texture.source), out);
}

Status TextureTable::read_sampler(int index, TextureSampler& out) const {
  out = TextureSampler{};
  if (index == -1) return {};  // no sampler: repeat, filters left to the viewer
  const std::string element = "samplers[" + std::to_string(index) + "]";
  if (index < 0 || size_t(index) >= model_.samplers.size())
    return ctx_.fail(element, "does not exist (" + std::to_string(model_.samplers.size()) + " samplers)");
  const tinygltf::Sampler& s = model_.samplers[size_t(index)];
  using Wrap = TextureSampler::Wrap;
  using Filter = TextureSampler::Filter;
  using MipMode = TextureSampler::MipMode;
  auto wrap = [&](int mode, const char* field, Wrap& w) -> Status {
    switch (mode) {
      case 10497:
        w = Wrap::Repeat;
        return {};
      case 33071:
        w = Wrap::ClampToEdge;
        return {};
      case 33648:
        w = Wrap::MirroredRepeat;
        return {};
      default:
        return ctx_.fail(element, std::string(field) + " " + std::to_string(mode) +
                                      " is not a glTF wrap mode (10497, 33071, 33648)");
    }
  };
  if (Status st = wrap(s.wrapS, "wrapS", out.wrap_s); !st) return st;
  if (Status st = wrap(s.wrapT, "wrapT", out.wrap_t); !st) return st;
  switch (s.magFilter) {
    case -1:
      break;  // undefined: linear
    case 9728:
      out.mag = Filter::Nearest;
      break;
    case 9729:
      out.mag = Filter::Linear;
      break;
    default:
      return ctx_.fail(element, "magFilter " + std::to_string(s.magFilter) + " is not a glTF filter (9728, 9729)");
  }
  switch (s.minFilter) {
    case -1:
      break;  // undefined: linear, linear between mip levels
    case 9728:
      out.min = Filter::Nearest;
      out.mip = MipMode::None;
      break;
    case 9729:
      out.min = Filter::Linear;
      out.mip = MipMode::None;
      break;
    case 9984:
      out.min = Filter::Nearest;
      out.mip = MipMode::Nearest;
      break;
    case 9985:
      out.min = Filter::Linear;
      out.mip = MipMode::Nearest;
      break;
    case 9986:
      out.min = Filter::Nearest;
      out.mip = MipMode::Linear;
      break;
    case 9987:
      out.min = Filter::Linear;
      out.mip = MipMode::Linear;
      break;
    default:
      return ctx_.fail(element,
                       "minFilter " + std::to_string(s.minFilter) + " is not a glTF filter (9728, 9729, 9984-9987)");
  }
  return {};
}

Status TextureTable::decode_image(size_t index, int& out) {
  if (slot_of_image_[index] >= 0) {
    out = slot_of_image_[index];
    return {};
  }
  const tinygltf::Image& image = model_.images[index];
  const std::string element =
      "images[" + std::to_string(index) + "]" + (image.name.empty() ? "" : " '" + one_line(image.name, 64) + "'");
  if (image.name.find('\0') != std::string::npos) return ctx_.fail(element, "name contains a NUL byte (\\u0000)");

  // The encoded file: `uri` is set only for external files; data: URI bytes were kept by
  // read_gltf_model (gltf_model_looks.cpp) in `image.image`; bufferView bytes are read in place.
  std::vector<uint8_t> file;
  const uint8_t* bytes = image.image.data();
  size_t size = image.image.size();
  if (!image.uri.empty()) {
    const std::string& uri = image.uri;
    std::string path;
    if (std::string why = resolve_relative_uri("image", base_dir_, uri, ctx_.allow_outside_paths(), path); !why.empty())
      return ctx_.fail(element, why);
    if (std::string why = read_file_bounded(path, kMaxTotalBufferBytes, file); !why.empty())
      return ctx_.fail(element, "cannot read '" + uri + "': " + why);
    bytes = file.data();
    size = file.size();
  } else if (image.bufferView >= 0) {
    // Preflight checked the view against its buffer's byteLength; check the loaded bytes too.
    const tinygltf::BufferView& view = model_.bufferViews[size_t(image.bufferView)];
    const std::vector<unsigned char>& data = model_.buffers[size_t(view.buffer)].data;
    if (uint64_t(view.byteOffset) + uint64_t(view.byteLength) > data.size())
      return ctx_.fail(element, "bufferView " + std::to_string(image.bufferView) + " exceeds its buffer");
    bytes = data.data() + view.byteOffset;
    size = view.byteLength;
  }
  static const uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const bool png = size >= 8 && std::memcmp(bytes, kPng, 8) == 0;
  const bool jpeg = size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
  if (size == 0) return ctx_.fail(element, "has no image data");
  if (!png && !jpeg) return ctx_.fail(element, "is not a PNG or JPEG image");
  if (size > size_t(INT_MAX)) return ctx_.fail(element, "is over 2 GiB");

  const int length = int(size);
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(bytes, length, &w, &h, &channels))
    return ctx_.fail(element, "cannot decode: " + stb_reason());
  if (w < 1 || h < 1 || uint32_t(w) > kMaxTextureSide || uint32_t(h) > kMaxTextureSide)
    return ctx_.fail(element, "is " + std::to_string(w) + "x" + std::to_string(h) + " pixels, over the limit of " +
                                  std::to_string(kMaxTextureSide) + "x" + std::to_string(kMaxTextureSide));
  const size_t texel_bytes = size_t(w) * size_t(h) * 4;
  if (texel_bytes > kMaxTotalTexelBytes - texel_bytes_)
    return ctx_.fail(element, "decoded images add up to more than " + std::to_string(kMaxTotalTexelBytes) + " bytes");

  int dw = 0, dh = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_memory(bytes, length, &dw, &dh, &channels, 4),
                                                         &stbi_image_free);
  if (!pixels) return ctx_.fail(element, "cannot decode: " + stb_reason());
  if (dw != w || dh != h) return ctx_.fail(element, "cannot decode: the size changed while decoding");
  texel_bytes_ += texel_bytes;

  Texture texture;
  texture.name = !image.name.empty()  ? image.name
                 : !image.uri.empty() ? image.uri
                                      : "images[" + std::to_string(index) + "]";
  texture.width = uint32_t(w);
  texture.height = uint32_t(h);
  texture.rgba8.assign(pixels.get(), pixels.get() + texel_bytes);  // stb: row 0 is the top row
  out = int(textures_.size());
  slot_of_image_[index] = out;
  textures_.push_back(std::move(texture));
  return {};
}

void TextureTable::note_drawn_material(int material) {
  const tinygltf::Material& m = model_.materials[size_t(material)];
  if (m.alphaMode != "BLEND") return;  // OPAQUE and MASK are drawn as the file says
  alpha_warned_.resize(model_.materials.size(), false);
  if (alpha_warned_[size_t(material)]) return;
  alpha_warned_[size_t(material)] = true;
  ctx_.warn(describe("material", size_t(material), m.name),
            "alphaMode BLEND is drawn with screen-door transparency (a 4 x 4 dither), not blended");
}

}  // namespace lintel::scene_read

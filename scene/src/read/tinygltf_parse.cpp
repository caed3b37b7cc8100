// tinygltf with an image loader that decodes nothing and file-system callbacks that only open the
// buffer files preflight listed, each read through read_file_bounded.
#include "read/tinygltf_parse.h"

#include "read/file_read.h"
#include "read/load_limits.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <exception>

namespace lintel::scene_read {
namespace {

struct FileAccess {
  const std::vector<std::string>* allowed = nullptr;
};

bool allowed(const std::string& path, void* user) {
  const auto* access = static_cast<const FileAccess*>(user);
  return std::find(access->allowed->begin(), access->allowed->end(), path) != access->allowed->end();
}

bool file_exists(const std::string& path, void* user) { return allowed(path, user); }

// No "~" or environment expansion: a URI names a file beside the scene, nothing else.
std::string expand_nothing(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  if (!allowed(path, user)) {
    if (err) *err += "not a buffer file of this scene: " + path;
    return false;
  }
  std::string why = read_file_bounded(path, kMaxTotalBufferBytes, *out);
  if (!why.empty() && err) *err += path + ": " + why;
  return why.empty();
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "the loader never writes files";
  return false;
}

// Images are not decoded here: texture_read.cpp decodes only the ones a drawn mesh uses. The
// bytes of a data: URI exist only now, so they are kept (tinygltf's "as_is" convention); a
// bufferView image is read from its view later, and an external file is never opened by tinygltf
// (not in the allowed list: it leaves a warning and the uri).
bool keep_data_uri_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                         const unsigned char* bytes, int size, void*) {
  if (image->bufferView >= 0 || !image->uri.empty() || size <= 0) return true;
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

}  // namespace

Status parse_with_tinygltf(const LoadContext& ctx, const uint8_t* bytes, size_t size, bool glb,
                           const std::string& base_dir, const std::vector<std::string>& external_files,
                           tinygltf::Model& model) {
  FileAccess access{&external_files};
  std::string err, warn;
  bool ok = false;
  try {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keep_data_uri_image, nullptr);
    loader.SetFsCallbacks({&file_exists, &expand_nothing, &read_whole_file, &refuse_write, &access});
    // tinygltf takes 32-bit lengths; files are capped at kMaxSceneFileBytes (1 GiB) before this.
    const auto length = static_cast<unsigned int>(size);
    ok = glb ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes, length, base_dir)
             : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes), length, base_dir);
  } catch (const std::exception& e) {
    return ctx.fail("glTF", std::string("parser failed: ") + e.what());
  } catch (...) {
    return ctx.fail("glTF", "parser failed with an unknown exception");
  }
  if (!ok) {
    // tinygltf accumulates several lines; the first names the fault.
    const std::string first = err.substr(0, err.find('\n'));
    return ctx.fail("glTF", first.empty() ? "tinygltf could not parse the file" : first);
  }
  return {};
}

}  // namespace lintel::scene_read

// read_gltf_model (scene/src/read/gltf_model.h), which fills tinygltf's Model from the loader's
// own DOM instead of running tinygltf's parser over the text a second time: the fields the
// readers use against what tinygltf itself makes of the same file, the stricter type checks, and
// that the scene library no longer calls tinygltf's parser at all.
#include "read/gltf_json.h"
#include "read/gltf_model.h"
#include "read/gltf_preflight.h"

#include "fixture_support.h"
#include "imported_level.h"

#include <lintel/doom_import.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace lintel::scene_read {
namespace {

using nlohmann::json;

std::vector<uint8_t> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// As the loader's old tinygltf callback: images not decoded, a data: URI's bytes kept as they are.
bool keep_data_uri_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                         const unsigned char* bytes, int size, void*) {
  if (image->bufferView >= 0 || !image->uri.empty() || size <= 0) return true;
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// tinygltf's own reading of the file, the reference. Empty string on success.
std::string tinygltf_model(const std::vector<uint8_t>& bytes, const std::string& base_dir, tinygltf::Model& out) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_data_uri_image, nullptr);
  std::string err, warn;
  const bool glb = looks_like_glb(bytes.data(), bytes.size());
  const bool ok = glb ? loader.LoadBinaryFromMemory(&out, &err, &warn, bytes.data(), unsigned(bytes.size()), base_dir)
                      : loader.LoadASCIIFromString(&out, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                   unsigned(bytes.size()), base_dir);
  return ok ? std::string() : "tinygltf: " + err;
}

// The loader's reading: one parse, preflight, read_gltf_model; with `compact` (as the loader
// does it) the clean accessors and meshes skip the DOM (gltf_compact.h). Empty string on success.
std::string lintel_model(const std::vector<uint8_t>& bytes, const std::string& base_dir, tinygltf::Model& out,
                         bool compact = true, bool* compacted = nullptr) {
  const LoadContext ctx("file", nullptr);
  GlbChunks chunks;
  const char* text = reinterpret_cast<const char*>(bytes.data());
  size_t size = bytes.size();
  const bool glb = looks_like_glb(bytes.data(), bytes.size());
  if (glb) {
    if (std::string why = split_glb(bytes.data(), bytes.size(), chunks); !why.empty()) return why;
    text = chunks.json;
    size = chunks.json_size;
  }
  json doc;
  bool fit = false;
  CompactSections sections;
  CompactSections* parts = compact ? &sections : nullptr;
  if (std::string why = parse_gltf_json(text, size, doc, &fit, parts); !why.empty()) return why;
  if (compacted) *compacted = sections.has_accessors && sections.has_meshes;
  PreflightResult preflight;
  if (Status s = preflight_gltf(ctx, doc, glb ? &chunks : nullptr, base_dir, preflight, fit, parts); !s)
    return s.message();
  if (Status s = read_gltf_model(ctx, doc, glb ? &chunks : nullptr, preflight, out, parts); !s) return s.message();
  return {};
}

// Every Model field that accessor_read, mesh_read, texture_read and light_assemble read.
void expect_same_fields(const tinygltf::Model& a, const tinygltf::Model& b, const std::string& label) {
  ASSERT_EQ(a.buffers.size(), b.buffers.size()) << label;
  for (size_t i = 0; i < a.buffers.size(); ++i)
    EXPECT_EQ(a.buffers[i].data, b.buffers[i].data) << label << " buffer " << i;
  ASSERT_EQ(a.bufferViews.size(), b.bufferViews.size()) << label;
  for (size_t i = 0; i < a.bufferViews.size(); ++i) {
    const tinygltf::BufferView &x = a.bufferViews[i], &y = b.bufferViews[i];
    EXPECT_EQ(x.buffer, y.buffer) << label << " view " << i;
    EXPECT_EQ(x.byteOffset, y.byteOffset) << label << " view " << i;
    EXPECT_EQ(x.byteLength, y.byteLength) << label << " view " << i;
    EXPECT_EQ(x.byteStride, y.byteStride) << label << " view " << i;
  }
  ASSERT_EQ(a.accessors.size(), b.accessors.size()) << label;
  for (size_t i = 0; i < a.accessors.size(); ++i) {
    const tinygltf::Accessor &x = a.accessors[i], &y = b.accessors[i];
    EXPECT_EQ(x.bufferView, y.bufferView) << label << " accessor " << i;
    EXPECT_EQ(x.byteOffset, y.byteOffset) << label << " accessor " << i;
    EXPECT_EQ(x.componentType, y.componentType) << label << " accessor " << i;
    EXPECT_EQ(x.count, y.count) << label << " accessor " << i;
    EXPECT_EQ(x.type, y.type) << label << " accessor " << i;
    EXPECT_EQ(x.sparse.isSparse, y.sparse.isSparse) << label << " accessor " << i;
  }
  ASSERT_EQ(a.meshes.size(), b.meshes.size()) << label;
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_EQ(a.meshes[i].name, b.meshes[i].name) << label << " mesh " << i;
    ASSERT_EQ(a.meshes[i].primitives.size(), b.meshes[i].primitives.size()) << label << " mesh " << i;
    for (size_t p = 0; p < a.meshes[i].primitives.size(); ++p) {
      const tinygltf::Primitive &x = a.meshes[i].primitives[p], &y = b.meshes[i].primitives[p];
      EXPECT_EQ(x.attributes, y.attributes) << label << " mesh " << i << " primitive " << p;
      EXPECT_EQ(x.indices, y.indices) << label << " mesh " << i << " primitive " << p;
      EXPECT_EQ(x.material, y.material) << label << " mesh " << i << " primitive " << p;
      EXPECT_EQ(x.mode, y.mode) << label << " mesh " << i << " primitive " << p;
    }
  }
  ASSERT_EQ(a.materials.size(), b.materials.size()) << label;
  for (size_t i = 0; i < a.materials.size(); ++i) {
    const tinygltf::Material &x = a.materials[i], &y = b.materials[i];
    EXPECT_EQ(x.name, y.name) << label << " material " << i;
    EXPECT_EQ(x.doubleSided, y.doubleSided) << label << " material " << i;
    EXPECT_EQ(x.pbrMetallicRoughness.baseColorFactor, y.pbrMetallicRoughness.baseColorFactor) << label;
    EXPECT_EQ(x.pbrMetallicRoughness.baseColorTexture.index, y.pbrMetallicRoughness.baseColorTexture.index) << label;
    EXPECT_EQ(x.pbrMetallicRoughness.baseColorTexture.texCoord, y.pbrMetallicRoughness.baseColorTexture.texCoord)
        << label;
  }
  ASSERT_EQ(a.textures.size(), b.textures.size()) << label;
  for (size_t i = 0; i < a.textures.size(); ++i) {
    EXPECT_EQ(a.textures[i].source, b.textures[i].source) << label << " texture " << i;
    EXPECT_EQ(a.textures[i].sampler, b.textures[i].sampler) << label << " texture " << i;
  }
  ASSERT_EQ(a.samplers.size(), b.samplers.size()) << label;
  for (size_t i = 0; i < a.samplers.size(); ++i) {
    const tinygltf::Sampler &x = a.samplers[i], &y = b.samplers[i];
    EXPECT_EQ(x.magFilter, y.magFilter) << label << " sampler " << i;
    EXPECT_EQ(x.minFilter, y.minFilter) << label << " sampler " << i;
    EXPECT_EQ(x.wrapS, y.wrapS) << label << " sampler " << i;
    EXPECT_EQ(x.wrapT, y.wrapT) << label << " sampler " << i;
  }
  ASSERT_EQ(a.images.size(), b.images.size()) << label;
  for (size_t i = 0; i < a.images.size(); ++i) {
    const tinygltf::Image &x = a.images[i], &y = b.images[i];
    EXPECT_EQ(x.name, y.name) << label << " image " << i;
    EXPECT_EQ(x.uri, y.uri) << label << " image " << i;
    EXPECT_EQ(x.bufferView, y.bufferView) << label << " image " << i;
    EXPECT_EQ(x.image, y.image) << label << " image " << i;
  }
  ASSERT_EQ(a.lights.size(), b.lights.size()) << label;
  for (size_t i = 0; i < a.lights.size(); ++i) {
    const tinygltf::Light &x = a.lights[i], &y = b.lights[i];
    EXPECT_EQ(x.name, y.name) << label << " light " << i;
    EXPECT_EQ(x.type, y.type) << label << " light " << i;
    EXPECT_EQ(x.color, y.color) << label << " light " << i;
    EXPECT_EQ(x.intensity, y.intensity) << label << " light " << i;
    EXPECT_EQ(x.range, y.range) << label << " light " << i;
    EXPECT_EQ(x.spot.innerConeAngle, y.spot.innerConeAngle) << label << " light " << i;
    EXPECT_EQ(x.spot.outerConeAngle, y.spot.outerConeAngle) << label << " light " << i;
  }
}

// Property: for every well-formed glTF file in the repository (the committed scenes, the good and
// warning fixtures: .gltf and .glb, external, embedded and data: URI buffers and images, lights,
// samplers, textures), read_gltf_model gives every field the readers use the value tinygltf's
// parser gives it, so a World loads as it did when tinygltf parsed the file.
TEST(GltfModel, WellFormedFilesGiveTinygltfsFields) {
  size_t files = 0, compacted_files = 0;
  for (const std::string& root :
       {std::string(LINTEL_SOURCE_DIR) + "/scenes", test::fixture("good"), test::fixture("warn")}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".gltf" && ext != ".glb") continue;
      const std::vector<uint8_t> bytes = read_bytes(entry.path());
      const std::string dir = entry.path().parent_path().string();
      tinygltf::Model reference, model, dom_model;
      ASSERT_EQ(tinygltf_model(bytes, dir, reference), "") << entry.path();
      bool compacted = false;
      ASSERT_EQ(lintel_model(bytes, dir, model, true, &compacted), "") << entry.path();
      expect_same_fields(reference, model, entry.path().string());
      ASSERT_EQ(lintel_model(bytes, dir, dom_model, false), "") << entry.path();
      expect_same_fields(reference, dom_model, entry.path().string() + " (DOM only)");
      ++files;
      compacted_files += compacted ? 1 : 0;
    }
  }
  EXPECT_GT(files, 15u);
  EXPECT_GT(compacted_files, 10u);  // the compact path is the one these files take
}

TEST(GltfModel, ImportedDoomLevelGivesTinygltfsFields) {
  if (!test::freedoom_installed()) GTEST_SKIP() << test::kFreedoomWad << " not installed (Debian package freedoom)";
  std::vector<uint8_t> glb;
  ASSERT_TRUE(test::imported_level_glb("E1M5", glb));
  tinygltf::Model reference, model;
  ASSERT_EQ(tinygltf_model(glb, "", reference), "");
  bool compacted = false;
  ASSERT_EQ(lintel_model(glb, "", model, true, &compacted), "");
  EXPECT_TRUE(compacted);
  EXPECT_GT(model.meshes.size(), 1000u);
  expect_same_fields(reference, model, "E1M5");
}

// Property: the compact path (gltf_compact.h) only ever takes content the DOM path reads the same
// way: for edits of a scene's accessors and meshes -- keys the loader does not read, wrong types,
// values out of range, a repeated key, sparse accessors -- the loader with the compact path gives
// the same result (the same fields, or the same message) as the DOM path alone.
TEST(GltfModel, CompactPathAgreesWithTheDomPathOnEditedAccessorsAndMeshes) {
  const std::string dir = std::string(LINTEL_SOURCE_DIR) + "/tests/scene/fixtures/good";
  const std::vector<uint8_t> original = read_bytes(dir + "/three_rooms.gltf");
  const json doc = json::parse(original.begin(), original.end());
  const std::vector<std::function<void(json&)>> edits = {
      [](json&) {},
      [](json&) {},  // the text gets a repeated "accessors" key below
      [](json& d) {
        d["accessors"][0]["extras"] = {{"a", 1}};
      },
      [](json& d) {
        d["accessors"][0]["sparse"] = {{"count", 1}};
      },
      [](json& d) { d["accessors"][0]["count"] = "3"; },
      [](json& d) { d["accessors"][0]["count"] = 0; },
      [](json& d) { d["accessors"][0]["componentType"] = 5130; },
      [](json& d) { d["accessors"][0]["type"] = "VEC5"; },
      [](json& d) { d["accessors"][0].erase("type"); },
      [](json& d) { d["accessors"][0]["bufferView"] = 99; },
      [](json& d) { d["accessors"][0]["bufferView"] = -1; },
      [](json& d) { d["accessors"][0]["byteOffset"] = -4; },
      [](json& d) {
        d["accessors"][0]["min"] = {4294967296.0, 1, 2};
      },
      [](json& d) {
        d["accessors"][0]["min"] = json::array({4294967296ll, 1, 2});
      },
      [](json& d) {
        d["accessors"][0]["max"] = {{"x", {1, {2, 3}}}};
      },
      [](json& d) { d["accessors"][0]["normalized"] = 1; },
      [](json& d) { d["accessors"] = json::object(); },
      [](json& d) { d["accessors"] = json::array({1}); },
      [](json& d) { d["meshes"][0]["extras"] = json::object(); },
      [](json& d) { d["meshes"][0]["name"] = 5; },
      [](json& d) { d["meshes"][0]["primitives"][0]["targets"] = json::array(); },
      [](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 999; },
      [](json& d) { d["meshes"][0]["primitives"][0]["indices"] = -2; },
      [](json& d) { d["meshes"][0]["primitives"][0]["mode"] = 1; },
      [](json& d) { d["meshes"][0]["primitives"][0]["material"] = 99; },
      [](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2147483648ll; },
      [](json& d) { d["meshes"][0]["primitives"][0]["attributes"] = json::object(); },
      [](json& d) { d["meshes"][0]["primitives"][0].erase("attributes"); },
      [](json& d) { d["meshes"][0]["primitives"] = json::array(); },
      [](json& d) { d["meshes"][0]["primitives"] = 3; },
      [](json& d) { d["meshes"] = json::array({json::object()}); },
      [](json& d) { d["meshes"] = "x"; },
  };
  for (size_t e = 0; e < edits.size(); ++e) {
    json d = doc;
    edits[e](d);
    std::string text = d.dump();
    // A repeated key, which a json object cannot hold: spliced into the text.
    if (e == 1) text.insert(text.find("\"accessors\"") + 12, "[], \"accessors\":");
    const std::vector<uint8_t> bytes(text.begin(), text.end());
    tinygltf::Model compact_model, dom_model;
    const std::string compact_result = lintel_model(bytes, dir, compact_model, true);
    const std::string dom_result = lintel_model(bytes, dir, dom_model, false);
    EXPECT_EQ(compact_result, dom_result) << "edit " << e;
    if (compact_result.empty() && dom_result.empty())
      expect_same_fields(dom_model, compact_model, "edit " + std::to_string(e));
  }
}

// Where tinygltf kept a silent default for a value of the wrong type, the loader names the fault.
TEST(GltfModel, WrongTypesAreFaultsNamingTheElement) {
  const std::string dir = std::string(LINTEL_SOURCE_DIR) + "/tests/scene/fixtures/good";
  const std::vector<uint8_t> original = read_bytes(dir + "/textured_table_data_uri_image.gltf");
  const json doc = json::parse(original.begin(), original.end());
  auto message = [&](const std::function<void(json&)>& edit) {
    json d = doc;
    edit(d);
    const std::string text = d.dump();
    World world;
    const Status s =
        load_world_from_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "doc.gltf", dir, world);
    return s.ok() ? std::string("ok") : s.message();
  };
  ASSERT_EQ(message([](json&) {}), "ok");
  const std::string mesh = "mesh 0 '" + doc["meshes"][0]["name"].get<std::string>() + "' primitive 0: ";
  EXPECT_EQ(message([](json& d) { d["meshes"][0]["primitives"][0]["indices"] = "3"; }),
            "doc.gltf: " + mesh + "indices must be an integer, got string");
  EXPECT_EQ(message([](json& d) { d["meshes"][0]["primitives"][0]["material"] = -1; }),
            "doc.gltf: " + mesh + "material -1 is negative");
  EXPECT_EQ(message([](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 1.5; }),
            "doc.gltf: " + mesh + "attributes.POSITION must be an integer, got number");
  EXPECT_EQ(message([](json& d) { d["meshes"][0]["primitives"][0].erase("attributes"); }),
            "doc.gltf: " + mesh + "'attributes' is missing");
  EXPECT_EQ(message([](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 999; }),
            "doc.gltf: " + mesh + "indices accessor 999 does not exist (" + std::to_string(doc["accessors"].size()) +
                " accessors)");
  EXPECT_EQ(message([](json& d) { d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = json::object(); }),
            "doc.gltf: materials[0].pbrMetallicRoughness.baseColorTexture: 'index' is missing");
  EXPECT_EQ(message([](json& d) { d["materials"][0]["doubleSided"] = 1; }),
            "doc.gltf: material 0 'Oak': doubleSided must be true or false, got integer");
  EXPECT_EQ(message([](json& d) {
              d["samplers"] = json::array({{{"wrapS", "REPEAT"}}});
            }),
            "doc.gltf: samplers[0]: wrapS must be an integer, got string");
  EXPECT_EQ(message([](json& d) { d["images"][0]["uri"] = 7; }),
            "doc.gltf: images[0]: uri must be a string, got integer");
  EXPECT_EQ(message([](json& d) { d["images"][0]["bufferView"] = 0; }),
            "doc.gltf: images[0]: has both 'bufferView' and 'uri' (glTF allows one)");
  EXPECT_EQ(message([](json& d) { d["materials"][1]["pbrMetallicRoughness"]["baseColorFactor"][2] = "1"; }),
            "doc.gltf: material 1 'Checker': baseColorFactor element 2 must be a number, got string");
  EXPECT_EQ(message([](json& d) { d["animations"] = json::array({1}); }),
            "doc.gltf: animations[0]: must be an object, got integer");
}

// Property: the scene library (the loader and `import rooms`) never calls tinygltf's parser, so a
// load parses the glTF JSON once, into the loader's own DOM. Read from the library's undefined
// symbols: a call to any TinyGLTF::Load* member would be one.
TEST(GltfModel, SceneLibraryDoesNotCallTinygltfsParser) {
  const std::string command = std::string(LINTEL_NM) + " -C --undefined-only '" + LINTEL_SCENE_LIBRARY + "'";
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), &pclose);
  ASSERT_TRUE(pipe) << command;
  std::string symbols;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe.get())) symbols.append(buffer, n);
  ASSERT_NE(symbols.find("tinygltf::DecodeDataURI"), std::string::npos) << "nm read nothing useful: " << command;
  EXPECT_EQ(symbols.find("tinygltf::TinyGLTF::"), std::string::npos)
      << symbols.substr(symbols.find("tinygltf::TinyGLTF::"), 200);
}

}  // namespace
}  // namespace lintel::scene_read

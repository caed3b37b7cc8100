// Shells become drawables so that one cull and one kind of draw covers everything the camera can
// see: a wall is culled against its cell's region like a chair is.
#include "render_scene.h"

#include <glm/gtc/packing.hpp>

#include <cstring>
#include <limits>

namespace lintel::render {
namespace {

float uint_bits(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);  // the shaders read it back with floatBitsToUint
  return f;
}

uint32_t sampler_bits(const TextureSampler& s) {
  return uint32_t(s.wrap_s) << kSamplerWrapSShift | uint32_t(s.wrap_t) << kSamplerWrapTShift |
         (s.mag == TextureSampler::Filter::Nearest ? kSamplerMagNearest : 0u) |
         (s.min == TextureSampler::Filter::Nearest ? kSamplerMinNearest : 0u) | uint32_t(s.mip) << kSamplerMipShift;
}

// The face bits of `mesh` (kFace*) drawn with `mesh_to_world`.
uint32_t face_bits(const Mesh& mesh, const glm::mat4& mesh_to_world) {
  uint32_t faces = (mesh.double_sided ? kFaceDoubleSided : 0u) |
                   (glm::determinant(glm::mat3(mesh_to_world)) < 0.0f ? kFaceMirrored : 0u);
  if (mesh.alpha_mode == Mesh::AlphaMode::Mask) {
    // Coverage = base alpha x texture alpha >= cutoff, as a test on the texture's alpha alone
    // (the shaders' cutout_threshold). Base alpha 0 gives +inf: nothing is drawn.
    const float threshold =
        mesh.base_color.a > 0.0f ? mesh.alpha_cutoff / mesh.base_color.a : std::numeric_limits<float>::infinity();
    faces |= kFaceAlphaMask | uint32_t(glm::packHalf1x16(threshold)) << kFaceAlphaThresholdShift;
  } else if (mesh.alpha_mode == Mesh::AlphaMode::Blend) {
    // Screen-door: coverage >= dither as a test on the texture's alpha, dither / base alpha.
    const float scale = mesh.base_color.a > 0.0f ? 1.0f / mesh.base_color.a : std::numeric_limits<float>::infinity();
    faces |= kFaceAlphaBlend | uint32_t(glm::packHalf1x16(scale)) << kFaceAlphaThresholdShift;
  }
  return faces;
}

GpuDrawInstance draw_instance(const glm::mat4& mesh_to_world, const Mesh& mesh, uint32_t cell) {
  const int texture = mesh.uvs.empty() ? -1 : mesh.base_color_texture;
  GpuDrawInstance d{};
  d.mesh_to_world = mesh_to_world;
  const glm::mat3 n = glm::transpose(glm::inverse(glm::mat3(mesh_to_world)));
  const uint32_t layer = texture < 0 ? kNoTexture : uint32_t(texture);
  float layer_bits;
  std::memcpy(&layer_bits, &layer, 4);
  d.normal_to_world_c0 = glm::vec4(n[0], layer_bits);  // w: the base-colour texture layer
  d.normal_to_world_c1 = glm::vec4(n[1], uint_bits(face_bits(mesh, mesh_to_world)));
  const int emissive_texture = mesh.uvs.empty() ? -1 : mesh.emissive_texture;
  d.normal_to_world_c2 = glm::vec4(n[2], uint_bits(sampler_bits(mesh.base_color_sampler) |
                                                   sampler_bits(mesh.emissive_sampler) << kSamplerEmissiveShift));
  d.albedo = mesh.base_color;
  d.emission = glm::vec4(mesh.emissive, uint_bits(emissive_texture < 0 ? kNoTexture : uint32_t(emissive_texture)));
  float cell_bits;
  std::memcpy(&cell_bits, &cell, 4);  // the shaders read it back with floatBitsToUint
  d.albedo.w = cell_bits;
  return d;
}

}  // namespace

bool any_cut_out(const RenderScene& scene) {
  for (const GpuDrawInstance& d : scene.draw_instances)
    if (glm::floatBitsToUint(d.normal_to_world_c1.w) & (kFaceAlphaMask | kFaceAlphaBlend)) return true;
  return false;
}

bool any_emission(const RenderScene& scene) {
  for (const GpuDrawInstance& d : scene.draw_instances)
    if (d.emission.r > 0.0f || d.emission.g > 0.0f || d.emission.b > 0.0f) return true;
  return false;
}

bool all_one_sided(const RenderScene& scene) {
  for (const GpuDrawInstance& d : scene.draw_instances)
    if (glm::floatBitsToUint(d.normal_to_world_c1.w) & (kFaceDoubleSided | kFaceMirrored)) return false;
  return true;
}

Status build_render_scene(const World& world, RenderScene& out) {
  out = RenderScene{};
  World& d = out.drawables;
  d = world;
  out.world_instance_count = uint32_t(world.instances.size());
  // One group per shell mesh, reused if two cells share a mesh.
  std::vector<int> group_of_mesh(world.meshes.size(), -1);
  for (uint32_t g = 0; g < d.groups.size(); ++g) group_of_mesh[d.groups[g].mesh] = int(g);
  for (uint32_t c = 0; c < d.cells.size(); ++c) {
    Cell& cell = d.cells[c];
    if (cell.shell_mesh < 0) continue;
    Instance shell;
    shell.name = cell.name + "#shell";
    shell.cell = c;
    shell.mesh = uint32_t(cell.shell_mesh);
    shell.mesh_to_world = cell.cell_to_world;
    shell.bounds_world = transform_aabb(cell.cell_to_world, d.meshes[shell.mesh].bounds_mesh);
    if (group_of_mesh[shell.mesh] < 0) {
      group_of_mesh[shell.mesh] = int(d.groups.size());
      d.groups.push_back({shell.mesh, {}});
    }
    shell.group = uint32_t(group_of_mesh[shell.mesh]);
    const uint32_t id = uint32_t(d.instances.size());
    d.groups[shell.group].instances.push_back(id);  // ids grow, so the list stays ascending
    cell.instances.push_back(id);
    d.instances.push_back(std::move(shell));
  }

  out.mesh_ranges.resize(d.meshes.size());
  for (size_t m = 0; m < d.meshes.size(); ++m) {
    const Mesh& mesh = d.meshes[m];
    out.mesh_ranges[m] = {uint32_t(mesh.indices.size()), uint32_t(out.indices.size()), int32_t(out.vertices.size())};
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      out.vertices.push_back(
          {mesh.positions[v], v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0, 1, 0),
           v < mesh.uvs.size() ? mesh.uvs[v] : glm::vec2(0.0f),
           glm::u16vec4(glm::round(glm::clamp(v < mesh.colors.size() ? mesh.colors[v] : glm::vec4(1.0f), 0.0f, 1.0f) *
                                   65535.0f))});
    out.indices.insert(out.indices.end(), mesh.indices.begin(), mesh.indices.end());
  }
  out.draw_instances.reserve(d.instances.size());
  for (const Instance& inst : d.instances) {
    const Mesh& mesh = d.meshes[inst.mesh];
    out.draw_instances.push_back(draw_instance(inst.mesh_to_world, mesh, inst.cell));
    out.bounds_world.extend(inst.bounds_world);
  }
  out.textures = pack_texture_layers(d);
  return gpu::pack_scene(d, out.mesh_ranges, out.cull_scene);
}

Status update_render_scene(const World& world, std::span<const uint32_t> moved, RenderScene& scene,
                           bool& doors_changed) {
  World& d = scene.drawables;
  doors_changed = false;
  if (world.cells.size() != d.cells.size() || world.portals.size() != d.portals.size() ||
      world.instances.size() != scene.world_instance_count || world.lights.size() != d.lights.size())
    return Status::error("world '" + world.source +
                         "' does not have the counts of the world the renderer was made for");
  for (uint32_t i : moved)
    if (i >= scene.world_instance_count)
      return Status::error("moved instance " + std::to_string(i) + " is out of range");
  for (size_t p = 0; p < world.portals.size(); ++p) {
    Portal& mine = d.portals[p];
    const Portal& theirs = world.portals[p];
    doors_changed =
        doors_changed || mine.open_from_to != theirs.open_from_to || mine.open_to_from != theirs.open_to_from;
    mine.open_from_to = theirs.open_from_to;
    mine.open_to_from = theirs.open_to_from;
  }
  if (moved.empty()) return {};
  for (uint32_t i : moved) {
    Instance& inst = d.instances[i];
    inst.mesh_to_world = world.instances[i].mesh_to_world;
    inst.bounds_world = world.instances[i].bounds_world;
    inst.cell = world.instances[i].cell;
    const Mesh& mesh = d.meshes[inst.mesh];
    scene.draw_instances[i] = draw_instance(inst.mesh_to_world, mesh, inst.cell);
    scene.bounds_world.extend(inst.bounds_world);
  }
  // Cell membership: the World's lists, then each cell's shell (shell ids follow every instance id,
  // so the lists stay ascending).
  for (size_t c = 0; c < d.cells.size(); ++c) {
    std::vector<uint32_t>& list = d.cells[c].instances;
    size_t shells = 0;
    while (shells < list.size() && list[list.size() - 1 - shells] >= scene.world_instance_count) ++shells;
    std::vector<uint32_t> tail(list.end() - std::ptrdiff_t(shells), list.end());
    list = world.cells[c].instances;
    list.insert(list.end(), tail.begin(), tail.end());
  }
  d.instance_moves += moved.size();  // caches of the drawables (the renderer's builder) re-derive
  return gpu::pack_scene(d, scene.mesh_ranges, scene.cull_scene);
}

}  // namespace lintel::render

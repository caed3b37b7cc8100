// The immutable scene model every Lintel layer reads: cells, portals, meshes, instances, draw
// groups, lights and camera timelines, resolved to world space once, at load time.
// Units are meters, +Y up. Spaces are named in members: *_world, *_cell (a cell node's space),
// *_mesh (a glTF mesh's own space).
#pragma once

#include <lintel/aabb.h>
#include <lintel/status.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lintel {

// Portal polygons have at most this many vertices (the scene format's limit).
inline constexpr uint32_t kMaxPortalVertices = 64;

// An RGBA8 image as stored in the file, decoded from PNG/JPEG but otherwise untouched.
// Albedo convention (the path tracer and the renderer both follow it; docs/scene-format.md):
//   albedo(uv) = Mesh::base_color.rgb * filter(srgb_to_linear(texels), uv)
// with the texels decoded to linear BEFORE filtering (what a VK_FORMAT_R8G8B8A8_SRGB image read
// through a linear sampler does), wrapped and filtered as the mesh's TextureSampler says (the
// g-buffer, the GI surfels and the path tracer all follow it, with a mip level from their
// footprint; docs/rendering.md), glTF uv (0, 0) = the top-left corner of the image (u to the
// right, v down), texel (i, j) centred at ((i + 0.5) / width, (j + 0.5) / height).
// srgb_to_linear is the IEC 61966-2-1 curve. Alpha is linear (not sRGB-encoded), filtered as the
// colour is, and used by Mesh::AlphaMode::Mask materials only.
struct Texture {
  std::string name;                // glTF image name, else its file uri, else "images[j]"; for messages
  uint32_t width = 0, height = 0;  // 1..8192 each
  // width*height*4, sRGB-encoded as in the file, row 0 = the image's first (top) row
  std::vector<uint8_t> rgba8;
};

// The glTF sampler of a base colour texture (samplers[textures[i].sampler]). A file that leaves
// a filter undefined gets linear filtering with linear mipmapping (glTF lets the viewer choose).
struct TextureSampler {
  enum class Wrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };  // 10497, 33071, 33648
  enum class Filter : uint8_t { Nearest, Linear };                    // texels: 9728, 9729
  enum class MipMode : uint8_t { None, Nearest, Linear };             // from minFilter 9728..9987
  Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat;
  Filter mag = Filter::Linear, min = Filter::Linear;
  MipMode mip = MipMode::Linear;
};

// Triangle geometry of one glTF mesh (its primitives merged, triangles only), or of the primitives
// of one material when the mesh uses several (one Mesh per material: docs/scene-format.md).
struct Mesh {
  std::string name;                  // glTF mesh name, may be empty
  int gltf_index = -1;               // index in the file's meshes array (the parts of one mesh share it)
  std::vector<glm::vec3> positions;  // mesh space
  std::vector<glm::vec3> normals;    // mesh space, one per position: the file's NORMAL, else area-weighted
  std::vector<uint32_t> indices;     // triangle list, 3 per triangle, all < positions.size()
  Aabb bounds_mesh;                  // the real extent of `positions` (never a unit box)
  glm::vec4 base_color{1.0f};        // glTF pbrMetallicRoughness.baseColorFactor of its primitives' material
  // TEXCOORD_0 of the primitives, one per position, or empty: empty when some primitive has no
  // TEXCOORD_0, which is a load error for a textured mesh. Not wrapped (the sampler wraps at lookup).
  std::vector<glm::vec2> uvs;
  // Index into World::textures: pbrMetallicRoughness.baseColorTexture of its primitives'
  // material, or -1. When >= 0, `uvs` has one entry per position. See Texture for the convention.
  int base_color_texture = -1;
  TextureSampler base_color_sampler;  // how base_color_texture is sampled (g-buffer, surfels, path tracer)
  // glTF material doubleSided of its primitives' material: false (the glTF default) = back faces
  // (clockwise as seen, after the node's transform) are culled for the camera.
  bool double_sided = false;
  // glTF material alphaMode and alphaCutoff of its primitives' material. Mask (cut-outs: leaves,
  // fences, grates): a point of the surface exists only where its coverage, base_color.a times
  // the base colour texture's alpha (filtered as its colour is) times the interpolated COLOR_0
  // alpha, is at least alpha_cutoff; the camera, the shadow maps, the GI surfels, the path tracer
  // and the ray-cast ground truth all see through the rest. Opaque: every point exists. Blend
  // (glass): seen through with screen-door transparency, a point showing on a fraction
  // `coverage` of the camera's pixels and of the shadow maps' texels (a 4 x 4 dither; the loader
  // warns that it is not blended), passed by a path-traced ray with probability 1 - coverage,
  // taken by the GI as a cut-out with cutoff 0.5, and always seen through by the ground truth.
  enum class AlphaMode : uint8_t { Opaque, Mask, Blend };
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;  // glTF's default; only Mask uses it
  // COLOR_0 of the primitives, linear RGBA in [0, 1], one per position, or empty (white): the
  // vertex colour multiplies the base colour (and texture), as glTF 2.0 defines it. A primitive
  // without COLOR_0 in a mesh where another has it is white. rgb multiplies the albedo; alpha
  // multiplies a cut-out's coverage (alpha_mode below) and is otherwise unused.
  std::vector<glm::vec4> colors;
  // Light the surface gives off by itself (lamp shades, screens, signs): glTF emissiveFactor
  // times KHR_materials_emissive_strength's emissiveStrength of its primitives' material, linear
  // RGB radiance in the lights' units (World::environment's), >= 0. Zero: the surface emits
  // nothing. The g-buffer shows it, the GI surfels and the path tracer emit it.
  glm::vec3 emissive{0.0f};
  // Index into World::textures: the material's emissiveTexture, or -1. Its texels (sRGB decoded,
  // filtered as base colours are) multiply `emissive`; it is read with `uvs` (the loader
  // refuses an emissive texture without them) and `emissive_sampler`.
  int emissive_texture = -1;
  TextureSampler emissive_sampler;
};

// One side of a portal as seen from the cell that can look through it.
struct PortalLink {
  uint32_t portal = 0;     // index into World::portals
  uint32_t neighbour = 0;  // the cell on the other side
};

// A portal whose far side is another place (docs/visibility.md, "Linked portals").
enum class PortalLinkKind : uint8_t {
  None,      // a plain opening: the far side is `to`, right behind the polygon
  Teleport,  // Portal::link_world is a rotation + translation onto a place elsewhere
  Mirror,    // Portal::link_world is the reflection in the portal's own plane; `to` == `from`
};

struct Cell {
  std::string name;  // unique
  int node = -1;     // glTF node index
  glm::mat4 cell_to_world{1.0f};
  glm::mat4 world_to_cell{1.0f};
  int shell_mesh = -1;  // the node's own mesh (walls, floor, ceiling): index into World::meshes, or -1
  // Closed volume bounding the cell's interior, in cell space, 3 vertices per triangle. Empty when
  // the scene gives none; then the volume is `volume_box_cell`.
  std::vector<glm::vec3> volume_triangles_cell;
  Aabb volume_box_cell;           // bounds of the volume (or of the shell when no volume is given)
  std::vector<PortalLink> links;  // portals this cell looks through (both sides of two-way ones)
  // Linked portals (teleports, mirrors) this cell looks through, in portal order: they are NOT in
  // `links`, so every reader of `links` (GPU cull, lights, GI, oracles) sees them as walls.
  std::vector<uint32_t> linked_portals;
  std::vector<uint32_t> instances;  // indices into World::instances
  std::vector<uint32_t> lights;     // indices into World::lights
};

struct Portal {
  std::string name;
  int node = -1;
  uint32_t from = 0;
  uint32_t to = 0;
  bool two_way = true;
  // Convex planar polygon, 3..kMaxPortalVertices vertices, wound so that its normal by the
  // right-hand rule points from `from` into `to`: counter-clockwise when seen from the `to` side,
  // clockwise as seen from inside `from`. The loader decides the side with the two cells' volume
  // probes beside the polygon (docs/scene-format.md, "Orientation").
  std::vector<glm::vec3> polygon_world;
  std::vector<glm::vec3> polygon_from_cell;  // the same vertices in `from`'s cell space
  std::vector<glm::vec3> polygon_to_cell;    // the same vertices in `to`'s cell space
  glm::vec3 normal_world{0.0f};              // unit, points from `from` into `to`
  float plane_d_world = 0.0f;                // dot(normal_world, p) == plane_d_world on the plane
  glm::vec3 centroid_world{0.0f};
  // Run-time door state, per direction of sight: open_from_to lets `from` see into `to`,
  // open_to_from lets `to` see into `from` (two-way portals only). Closed blocks visibility; the
  // viewer tracker still follows crossings through it. Scene format: extras.lintel.portal.open
  // (both directions). Toggle with World::set_portal_open (O(1)); no revision change needed.
  bool open_from_to = true;
  bool open_to_from = true;
  // Linked portal (one-way, seen and crossed from `from` only): a ray that enters the polygon at x
  // going along d goes on from link_world * x along link_world * d, in cell `to` (for a mirror
  // `to` == `from`). Rigid: rotation + translation for a teleport, the reflection in the portal's
  // plane for a mirror (portal_link.h builds and checks both). Scene format:
  // extras.lintel.portal.link (a matrix or a target portal's name), extras.lintel.portal.mirror.
  PortalLinkKind link = PortalLinkKind::None;
  glm::dmat4 link_world{1.0};
  int link_target = -1;  // the target portal when the link was given by name, else -1
  bool linked() const { return link != PortalLinkKind::None; }
};

// Which way one looks through a portal.
enum class PortalDirection : uint8_t { FromTo, ToFrom };

struct Instance {
  std::string name;
  int node = -1;
  uint32_t cell = 0;   // the cell node it sits below
  uint32_t mesh = 0;   // index into World::meshes
  uint32_t group = 0;  // index into World::groups
  glm::mat4 mesh_to_world{1.0f};
  Aabb bounds_world;  // Mesh::bounds_mesh transformed by mesh_to_world (box of the 8 corners)
};

// All instances that use one glTF mesh: drawn by one indirect command.
struct DrawGroup {
  uint32_t mesh = 0;
  std::vector<uint32_t> instances;  // indices into World::instances, ascending
};

struct Light {
  enum class Type { Point, Spot, Directional };
  std::string name;
  int node = -1;
  uint32_t cell = 0;
  Type type = Type::Point;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;  // glTF units: candela (point/spot), lux (directional)
  float range = 0.0f;      // 0 means unlimited
  float inner_cone_rad = 0.0f;
  float outer_cone_rad = 0.785398f;
  glm::vec3 position_world{0.0f};
  glm::vec3 direction_world{0.0f, 0.0f, -1.0f};  // unit; the node's -Z
};

struct TimelineKey {
  double t = 0.0;  // seconds, strictly increasing along a timeline
  glm::vec3 eye_world{0.0f};
  glm::vec3 target_world{0.0f, 0.0f, -1.0f};
};

// A door event on a timeline: at time t the named portal opens or closes (both directions).
struct TimelineEvent {
  double t = 0.0;      // seconds, non-decreasing along Timeline::events
  std::string portal;  // Portal::name
  bool open = true;
  int portal_index = -1;  // resolved against a World by resolve_timeline_events() (timeline.h)
};

// A key of a named instance's motion on a timeline: from time t the instance's mesh_to_world is
// T(translation_world) * R(rotation) * L, L = its transform when the timeline was resolved with
// the translation removed (so a key with only a translation keeps the authored orientation and
// scale, and a rotation turns the object about its own origin). Between two keys of one instance,
// translation is interpolated linearly and rotation by slerp; before its first key the instance
// stays where it is, after its last it stays there (timeline.h, resolve_timeline_instances).
struct TimelineInstanceKey {
  double t = 0.0;        // seconds; non-decreasing along Timeline::instance_keys, increasing per instance
  std::string instance;  // Instance::name
  bool has_translation = false;
  glm::vec3 translation_world{0.0f};  // default: the instance's translation at resolve time
  bool has_rotation = false;
  glm::vec4 rotation_xyzw{0.0f, 0.0f, 0.0f, 1.0f};  // unit quaternion (glTF order); default: none
  int instance_index = -1;  // resolved against a World by resolve_timeline_instances() (timeline.h)
};

struct Timeline {
  std::string name;
  double fps = 60.0;
  double fov_y_deg = 70.0;
  double aspect = 16.0 / 9.0;
  std::vector<TimelineKey> keys;                   // at least one
  std::vector<TimelineEvent> events;               // door events, t non-decreasing; may be empty
  std::vector<TimelineInstanceKey> instance_keys;  // moving instances; may be empty
};

// The sky of a scene that names none and has no light sources (no lights, no emissive mesh): a neutral white environment, as glTF
// viewers use, so such a scene is seen (under automatic exposure its level does not matter).
inline constexpr float kDefaultEnvironmentRadiance = 1.0f;

struct World {
  std::string source;  // the file it was loaded from (for messages)
  int version = 1;
  // Set by finalize_world() to a number larger than before and unique in the process: anything
  // that caches data derived from a World (the builder's prepared scratch with the CPU cull's
  // bounds, the tracker's adjacency) keys on its address AND this, so loading another level into
  // the same World object, or assigning it another finalized World, is noticed. 0: never finalized.
  uint64_t revision = 0;
  // Grows by one with every DynamicInstances::move (dynamic_instances.h), which edits instances in
  // place without a new revision. A cache of instance bounds or reach that was not handed the
  // moved instances (DynamicInstances::take_moved) sees it change and re-derives them.
  uint64_t instance_moves = 0;
  std::vector<Mesh> meshes;
  std::vector<Texture> textures;  // one per glTF image used as a drawn mesh's base colour texture
  std::vector<Cell> cells;
  std::vector<Portal> portals;
  std::vector<Instance> instances;
  std::vector<DrawGroup> groups;
  std::vector<Light> lights;
  std::vector<Timeline> timelines;
  // Linear radiance of a uniform sky around the scene (every direction that leaves the geometry),
  // in the lights' units: extras.lintel.environment color x intensity; a file without it gets
  // kDefaultEnvironmentRadiance when it has no light sources (has_light_sources: so it is not
  // black) and 0 otherwise.
  // The renderer and the path tracer both read this one value.
  glm::vec3 environment{0.0f};

  // Index of the cell with this name, or -1.
  int find_cell(std::string_view name) const;
  // Index of the timeline with this name, or -1.
  int find_timeline(std::string_view name) const;
  // Independent cycles of the undirected portal multigraph: portals - cells + components. A tree
  // of rooms has 0; every extra door or window that closes a loop adds 1.
  size_t portal_graph_cycles() const;

  // Door state (Portal::open_from_to / open_to_from). Preconditions: portal < portals.size().
  bool portal_open(uint32_t portal, PortalDirection direction) const;
  void set_portal_open(uint32_t portal, PortalDirection direction, bool open);
  void set_portal_open(uint32_t portal, bool open);  // both directions
  // Index of the portal with this name, or -1.
  int find_portal(std::string_view name) const;
  // Whether anything in the scene gives off light: a light, or a mesh with Mesh::emissive > 0
  // (which decides whether a scene without a sky gets kDefaultEnvironmentRadiance).
  bool has_light_sources() const;
};

// The one place that derives and validates World's derived fields, for loaders, generators,
// tests and games after they fill or edit the primary ones: Cell::links (portal order; `from`
// looks into `to`, and `to` into `from` when two-way), Cell::instances and Cell::lights
// (ascending), DrawGroup::instances (ascending, from Instance::group) and Instance::bounds_world
// (Mesh::bounds_mesh through mesh_to_world), Cell::linked_portals. Validates every index, each
// portal polygon's size and each link (validate_portal_link, portal_link.h). Gives World::revision a new value (see there), also on error (the world is then unusable:
// fix and call again). Allocates. Thread-safe for distinct Worlds.
Status finalize_world(World& world);

}  // namespace lintel

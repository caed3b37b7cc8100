// Things -> instances (one box mesh per thing type, so one draw group per type; lamps, candles,
// torches and burning barrels glow: Mesh::emissive) and bright sectors -> point lights. A thing's box is shrunk to stay inside its sector's lines, so an
// instance never reaches into a neighbouring cell, nor across the cut to the next cell of a split
// sector (the ray-cast truth counts a thing's cell as seen wherever the thing is hit); the sizes
// are Doom's thing radii and heights by category.
#include "doom/doom_level.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace lintel::doom {
namespace {

constexpr uint16_t kMultiplayerOnly = 0x10;
constexpr int kBrightLight = 192;          // sector light level (0..255) that gets a lamp
constexpr size_t kMaxLights = 32;          // the largest bright sectors first
constexpr float kAmbientRadiance = 0.05f;  // the imported scene's sky (SceneDesc::environment)
constexpr double kBoxShrink = 0.7;         // box half-width <= this x distance to the nearest line

constexpr float kLampRadiance = 4.0f;  // emission of a lamp's box (lights' units; a lit wall is about 0.5)

struct ThingShape {
  double radius = 16, height = 16;
  glm::vec4 colour{0.9f, 0.8f, 0.2f, 1.0f};
  glm::vec3 emissive{0.0f};  // light sources (lamps, candles, torches, burning barrels) glow
};

// Doom's decorations that are light sources (drawn full-bright in Doom), with their light's colour.
bool lamp_colour(uint16_t type, glm::vec3& colour) {
  static constexpr glm::vec3 kWarm{1.0f, 0.92f, 0.8f}, kFlame{1.0f, 0.75f, 0.4f}, kFire{1.0f, 0.5f, 0.2f},
      kBlue{0.35f, 0.5f, 1.0f}, kGreen{0.4f, 1.0f, 0.4f}, kRed{1.0f, 0.35f, 0.2f};
  static constexpr std::pair<uint16_t, glm::vec3> kLamps[] = {
      {2028, kWarm}, {85, kWarm},  {86, kWarm},  // floor lamp, tall and short techno floor lamps
      {34, kFlame},  {35, kFlame},               // candle, candelabra
      {70, kFire},                               // burning barrel
      {44, kBlue},   {55, kBlue},                // tall and short torches, by colour
      {45, kGreen},  {56, kGreen}, {46, kRed},  {57, kRed}};
  for (const auto& [t, c] : kLamps)
    if (t == type) {
      colour = c;
      return true;
    }
  return false;
}

bool is_monster(uint16_t t) {
  static constexpr uint16_t kMonsters[] = {7,  9,  16, 58,   64,   65,   66,   67,   68,
                                           69, 71, 84, 3001, 3002, 3003, 3004, 3005, 3006};
  return std::find(std::begin(kMonsters), std::end(kMonsters), t) != std::end(kMonsters);
}

// Doom's sizes by category (the renderer draws boxes, so categories are enough).
ThingShape shape_of(uint16_t type) {
  if (is_monster(type)) {
    const bool big = type == 7 || type == 16 || type == 67 || type == 68;
    return {big ? 48.0 : 20.0, big ? 96.0 : 56.0, {0.75f, 0.2f, 0.15f, 1.0f}};
  }
  // Before the pickups' range: the floor lamp is 2028.
  if (glm::vec3 light; lamp_colour(type, light)) return {16, 48, glm::vec4(light, 1.0f), kLampRadiance * light};
  if (type >= 2001 && type <= 2049) return {16, 24, {0.3f, 0.7f, 0.3f, 1.0f}};  // weapons, ammo, health, barrels...
  if ((type >= 5 && type <= 6) || (type >= 38 && type <= 40) || type == 13)
    return {12, 16, {0.2f, 0.4f, 0.9f, 1.0f}};  // keys
  return {16, 48, {0.55f, 0.55f, 0.6f, 1.0f}};  // other decorations: columns, trees, bodies
}

bool is_player_or_marker(uint16_t type) { return (type >= 1 && type <= 4) || type == 11 || type == 14; }

MeshDesc box_mesh(const std::string& name, const ThingShape& shape) {
  const double radius = shape.radius, height = shape.height;
  MeshDesc mesh;
  mesh.name = name;
  mesh.base_color = shape.colour;
  mesh.emissive = shape.emissive;
  const float r = float(radius * kDoomMetersPerUnit), h = float(height * kDoomMetersPerUnit);
  for (int i = 0; i < 8; ++i) mesh.positions.emplace_back((i & 1) ? r : -r, (i & 2) ? h : 0.0f, (i & 4) ? r : -r);
  // Outward-facing quads (x-, x+, y-, y+, z-, z+).
  static constexpr uint32_t kQuads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                            {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : kQuads) mesh.indices.insert(mesh.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  return mesh;
}

bool drawn_kind(const Thing& thing) { return !is_player_or_marker(thing.type) && !(thing.flags & kMultiplayerOnly); }

uint16_t sector_under(const Map& m, const glm::dvec2& p) {
  return m.seg_sector(m.segs[m.subsectors[subsector_at(m, p)].first_seg]);
}

double nearest_line(const Map& m, const glm::dvec2& p) {
  double nearest = INFINITY;
  for (const Linedef& line : m.linedefs)
    nearest = std::min(nearest, distance_to_segment(p, m.vertices[line.v1], m.vertices[line.v2]));
  return nearest;
}

}  // namespace

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

std::vector<std::vector<ThingClearance>> thing_clearances(const Map& m) {
  std::vector<std::vector<ThingClearance>> out(m.sectors.size());
  for (const Thing& thing : m.things) {
    if (!drawn_kind(thing)) continue;
    const double half = std::min(shape_of(thing.type).radius, kBoxShrink * nearest_line(m, thing.position));
    // A cut may shrink a box to half its width (and 1 unit), no more: a thing is never dropped
    // for a cut, and cuts near things stay where they pay.
    out[sector_under(m, thing.position)].push_back({thing.position, std::max(1.0, 0.5 * half) / kBoxShrink});
  }
  return out;
}

void add_things_and_lights(const Level& level, SceneDesc& scene, DoomImportStats& stats) {
  const Map& m = level.map;
  std::map<uint16_t, int> mesh_of_type;
  for (size_t i = 0; i < m.things.size(); ++i) {
    const Thing& thing = m.things[i];
    if (!drawn_kind(thing)) continue;
    const uint16_t sector = sector_under(m, thing.position);
    if (level.cell_node[sector] < 0) continue;
    const int cell = cell_node_at(level, sector, thing.position);  // of a split sector: the cell under the thing
    // A cut counts as a line: the box stays in its cell. Cuts keep a thing's clearance
    // (thing_clearances), so they shrink a box to half its width at most.
    double nearest = nearest_line(m, thing.position);
    for (const auto& [a, b] : level.cuts) nearest = std::min(nearest, distance_to_segment(thing.position, a, b));
    const ThingShape shape = shape_of(thing.type);
    const double half = std::min(shape.radius, kBoxShrink * nearest);
    const double room = level.ceiling[sector] - level.floor[sector] - 1.0;
    const double height = std::min(shape.height, room);
    if (half < 1.0 || height < 1.0) continue;
    auto [it, added] = mesh_of_type.try_emplace(thing.type, int(scene.meshes.size()));
    if (added) scene.meshes.push_back(box_mesh("thing_type_" + std::to_string(thing.type), shape));
    NodeDesc node;
    node.name = "thing_" + std::to_string(i);
    node.parent = cell;
    node.mesh = it->second;
    node.translation = to_world(thing.position, level.floor[sector]);
    node.rotation = glm::angleAxis(float(thing.angle_deg * M_PI / 180.0), glm::vec3(0, 1, 0));
    node.scale = glm::vec3(float(half / shape.radius), float(height / shape.height), float(half / shape.radius));
    scene.nodes.push_back(node);
    ++stats.instances;
  }

  // Lamps: the largest bright sectors, at the centroid of their largest piece, 3/4 up.
  std::vector<std::pair<double, size_t>> bright;
  for (size_t s = 0; s < m.sectors.size(); ++s) {
    if (level.cell_node[s] < 0 || m.sectors[s].light < kBrightLight) continue;
    double area = 0.0;
    for (size_t p : level.pieces_of_sector[s]) area += polygon_area(level.pieces[p].polygon);
    bright.emplace_back(-area, s);
  }
  std::sort(bright.begin(), bright.end());
  // Doom lights every sector by its light level, not by lamps: the level is in each sector's
  // albedo (sector_colour), and a dim uniform sky stands for that light everywhere, so that a
  // sector far from every lamp is dim, as in Doom, not black (the renderer adds the sky as ambient
  // light times AO; docs/rendering.md, "The sky").
  scene.environment = glm::vec3(kAmbientRadiance);
  for (size_t k = 0; k < bright.size() && k < kMaxLights; ++k) {
    const size_t s = bright[k].second;
    size_t largest = level.pieces_of_sector[s][0];
    for (size_t p : level.pieces_of_sector[s])
      if (polygon_area(level.pieces[p].polygon) > polygon_area(level.pieces[largest].polygon)) largest = p;
    LightDesc light;
    light.name = "lamp_sector_" + std::to_string(s);
    light.color = {1.0f, 0.92f, 0.8f};
    light.intensity = 20.0f * float(m.sectors[s].light) / 255.0f;
    light.range = 12.0f;
    NodeDesc node;
    node.name = light.name;
    node.parent = cell_node_at(level, s, polygon_centroid(level.pieces[largest].polygon));
    node.light = int(scene.lights.size());
    node.translation = to_world(polygon_centroid(level.pieces[largest].polygon),
                                level.floor[s] + 0.75 * (level.ceiling[s] - level.floor[s]));
    scene.lights.push_back(light);
    scene.nodes.push_back(node);
    ++stats.lights;
  }
}

}  // namespace lintel::doom

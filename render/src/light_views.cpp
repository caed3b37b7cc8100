// Light visibility: the camera's portal traversal run from each light, through open portals only.
#include "light_views.h"

#include "clip_volume.h"

#include <lintel/visibility_builder.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace lintel::render {
namespace {

constexpr float kWideSpotRad = 80.0f * 3.14159265f / 180.0f;

void mark(LightViews& lv, uint32_t light, uint32_t cell) {
  lv.cell_mask[size_t(light) * lv.words_per_light + cell / 32] |= 1u << (cell % 32);
}

// One perspective view from the light: its visibility query gives the lit cells and the casters.
Status perspective_view(const RenderScene& scene, uint32_t light_index, const View& view, uint32_t resolution,
                        VisibilityBuilder& builder, VisibleSet& visible, LightViews& out) {
  const World& world = scene.drawables;
  const Light& light = world.lights[light_index];
  VisibilityOptions options;
  options.cull_instances = true;
  if (Status s = builder.build(world, view, light.cell, options, visible); !s)
    return Status::error("light '" + light.name + "': " + s.message());
  ShadowView sv;
  sv.light = light_index;
  sv.world_to_clip = view_projection(view);
  sv.casters = visible.instances;
  sv.texel_scale = 2.0f * std::tan(glm::radians(view.fov_y_deg) * 0.5f) / float(resolution);
  for (const VisibleCell& c : visible.cells) mark(out, light_index, c.cell);
  out.views.push_back(std::move(sv));
  return {};
}

// Cells that sunlight travelling along `dir` can reach from `start` through portals.
std::vector<uint32_t> directional_flood(const World& world, uint32_t start, const glm::vec3& dir) {
  std::vector<uint8_t> seen(world.cells.size(), 0);
  std::vector<uint32_t> order{start};
  seen[start] = 1;
  for (size_t i = 0; i < order.size(); ++i) {
    const uint32_t c = order[i];
    for (const PortalLink& link : world.cells[c].links) {
      const Portal& p = world.portals[link.portal];
      const glm::vec3 into = p.from == c ? p.normal_world : -p.normal_world;
      if (glm::dot(dir, into) <= 0.0f || seen[link.neighbour]) continue;
      // A closed door is a wall for light (this cell's side of it, as for sight).
      if (!world.portal_open(link.portal, p.from == c ? PortalDirection::FromTo : PortalDirection::ToFrom)) continue;
      seen[link.neighbour] = 1;
      order.push_back(link.neighbour);
    }
  }
  return order;
}

// An orthographic view along `dir` over the sphere (centre, radius), deep enough (from `depth_centre`
// +- `depth_radius` along the light) to hold every caster of the scene.
ShadowView ortho_view(uint32_t light, const glm::vec3& dir, const glm::vec3& centre, float radius,
                      const glm::vec3& depth_centre, float depth_radius) {
  const glm::vec3 up = std::abs(dir.y) > 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  const float reach = depth_radius + glm::length(centre - depth_centre);
  const glm::vec3 eye = centre - dir * reach;
  ShadowView sv;
  sv.light = light;
  sv.world_to_clip =
      glm::orthoRH_ZO(-radius, radius, -radius, radius, 0.0f, 2.0f * reach) * glm::lookAtRH(eye, centre, up);
  return sv;
}

// Two views: a fine one over the sunlit cells other than the light's own (the interiors, where a
// coarse texel would be as wide as a wall and let light through it), then a coarse one over the
// whole scene for everything else. The lighting uses the first that holds the point.
Status directional_view(const RenderScene& scene, uint32_t light_index, LightViews& out) {
  const World& world = scene.drawables;
  const Light& light = world.lights[light_index];
  const glm::vec3 centre = scene.bounds_world.center();
  const float radius = 0.5f * glm::length(scene.bounds_world.extent()) + 1.0f;
  const glm::vec3 dir = glm::normalize(light.direction_world);
  const std::vector<uint32_t> lit = directional_flood(world, light.cell, dir);
  Aabb inner;
  for (uint32_t c : lit) {
    mark(out, light_index, c);
    if (c == light.cell) continue;
    for (uint32_t i : world.cells[c].instances) inner.extend(world.instances[i].bounds_world);
  }
  std::vector<ShadowView> views;
  const float inner_radius = inner.empty() ? radius : 0.5f * glm::length(inner.extent()) + 0.5f;
  if (inner_radius < 0.5f * radius)
    views.push_back(ortho_view(light_index, dir, inner.center(), inner_radius, centre, radius));
  views.push_back(ortho_view(light_index, dir, centre, radius, centre, radius));
  for (ShadowView& sv : views) {
    for (uint32_t c : lit)
      for (uint32_t i : world.cells[c].instances)
        if (box_may_meet_clip_volume(glm::dmat4(sv.world_to_clip), world.instances[i].bounds_world))
          sv.casters.push_back(i);
    std::sort(sv.casters.begin(), sv.casters.end());
    out.views.push_back(std::move(sv));
  }
  return {};
}

}  // namespace

uint32_t max_shadow_views(const Light& light) {
  if (light.type == Light::Type::Directional) return 2;
  if (light.type == Light::Type::Spot && light.outer_cone_rad <= kWideSpotRad) return 1;
  return 6;
}

Status build_light_views(const RenderScene& scene, const LightViewOptions& options, LightViews& out) {
  const World& world = scene.drawables;
  out = LightViews{};
  out.words_per_light = uint32_t((world.cells.size() + 31) / 32);
  out.cell_mask.assign(world.lights.size() * out.words_per_light, 0u);
  VisibilityBuilder builder;
  VisibleSet visible;
  const float far_default = glm::length(scene.bounds_world.extent()) + 1.0f;
  // Cube faces a little wider than 90 degrees, so the PCF footprint at a face's edge still reads
  // texels of that face.
  const float margin = 1.0f + 4.0f / float(std::max(options.shadow_resolution, 8u));
  const float cube_fov_deg = glm::degrees(2.0f * std::atan(margin));
  for (uint32_t l = 0; l < world.lights.size(); ++l) {
    const Light& light = world.lights[l];
    out.first_view.push_back(uint32_t(out.views.size()));
    if (light.type == Light::Type::Directional) {
      if (Status s = directional_view(scene, l, out); !s) return s;
    } else {
      View v;
      v.eye_world = light.position_world;
      v.near_m = 0.05f;
      v.far_m = light.range > 0.0f ? std::max(light.range, 0.1f) : far_default;
      v.aspect = 1.0f;
      if (light.type == Light::Type::Spot && light.outer_cone_rad <= kWideSpotRad) {
        const glm::vec3 dir = glm::normalize(light.direction_world);
        v.target_world = v.eye_world + dir;
        v.up_world = std::abs(dir.y) > 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
        v.fov_y_deg = std::min(glm::degrees(2.0f * std::atan(std::tan(light.outer_cone_rad) * margin)), 170.0f);
        if (Status s = perspective_view(scene, l, v, options.shadow_resolution, builder, visible, out); !s) return s;
      } else {
        static const glm::vec3 kDirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (int f = 0; f < 6; ++f) {
          v.target_world = v.eye_world + kDirs[f];
          v.up_world = f == 2 || f == 3 ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
          v.fov_y_deg = cube_fov_deg;
          if (Status s = perspective_view(scene, l, v, options.shadow_resolution, builder, visible, out); !s) return s;
        }
      }
    }
    out.view_count.push_back(uint32_t(out.views.size()) - out.first_view.back());
  }
  return {};
}

}  // namespace lintel::render

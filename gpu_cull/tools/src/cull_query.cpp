// `lintel cull` as a library call: locate the viewer cell, build the visible set, cull the
// instances on the GPU (pack, run, read back) or take the reference's, and lay both out as the
// per-group indirect commands a renderer would draw.
#include <lintel/cell_locate.h>
#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_pass.h>
#include <lintel/tools/cull_query.h>

#include <algorithm>

namespace lintel::gpu {

Status cull_query(const World& world, const CullQueryOptions& options, CullQueryResult& out) {
  out = CullQueryResult{};
  if (Status s = validate_view(options.view); !s) return s;
  if (world.cells.empty()) return Status::error(world.source + ": the scene has no cells");
  CullScene scene;
  if (Status s = pack_scene(world, {}, scene); !s) return s;
  VisibilityOptions vis = options.visibility;
  vis.cull_instances = true;
  vis.cull_linked_instances = true;
  out.start_cell = locate_cell(world, glm::dvec3(options.view.eye_world)).cell;
  VisibilityBuilder builder;
  VisibleSet visible;
  if (Status s = builder.build(world, options.view, out.start_cell, vis, visible); !s) return s;
  out.stats = visible.stats;
  for (const VisibleCell& c : visible.cells) out.visible_cells.push_back(c.cell);
  for (uint32_t t = 1; t < visible.transforms.size(); ++t) {
    LinkedViewDraw v;
    v.transform = t;
    v.portal = visible.transforms[t].portal;
    v.depth = visible.transforms[t].depth;
    v.mirrored = visible.transforms[t].mirrored;
    for (const VisibleCell& c : visible.linked_cells)
      if (c.transform == t) v.cells.push_back(c.cell);
    for (const LinkedInstance& i : visible.linked_instances)
      if (i.transform == t) v.instances.push_back(i.instance);
    if (!v.cells.empty()) out.linked_views.push_back(std::move(v));
  }
  out.unresolved_links = uint32_t(visible.unresolved.size());

  out.groups.resize(world.groups.size());
  for (uint32_t g = 0; g < world.groups.size(); ++g) {
    GroupDraw& d = out.groups[g];
    d.group = g;
    d.mesh = world.groups[g].mesh;
    d.mesh_name = d.mesh < world.meshes.size() ? world.meshes[d.mesh].name : std::string();
    const GpuDrawGroup& pg = scene.groups[g];
    d.command = {pg.index_count, 0, pg.first_index, pg.vertex_offset, pg.base};
  }
  if (!options.use_gpu) {
    out.method = "cpu";
    for (uint32_t id : visible.instances) out.groups[world.instances[id].group].instances.push_back(id);
  } else {
    out.method = "gpu";
    ContextOptions ctx_options;
    ctx_options.device = options.device;
    ctx_options.validation = options.validation;
    std::unique_ptr<Context> ctx;
    if (Status s = Context::create(ctx_options, ctx); !s) return s;
    out.device = ctx->info().name;
    std::unique_ptr<CullPass> pass;
    if (Status s = CullPass::create(*ctx, {}, pass); !s) return s;
    CullFrame frame;
    pack_visible_set(visible, options.view, uint32_t(world.cells.size()), frame);
    CullReadback rb;
    Status s = pass->set_scene(scene);
    if (s) s = pass->set_frame(frame);
    if (s) s = pass->run(&rb);
    if (!s) return s;
    for (uint32_t g = 0; g < rb.commands.size(); ++g) {
      std::span<const uint32_t> ids = rb.group_ids(g);
      out.groups[g].instances.assign(ids.begin(), ids.end());
    }
    if (options.validation) {
      std::vector<std::string> messages = ctx->take_validation_messages();
      if (!messages.empty()) return Status::internal("GPU cull: validation: " + messages.front());
    }
  }
  for (GroupDraw& d : out.groups) {
    std::sort(d.instances.begin(), d.instances.end());
    d.command.instance_count = uint32_t(d.instances.size());
    out.visible_instances += d.command.instance_count;
  }
  return {};
}

}  // namespace lintel::gpu

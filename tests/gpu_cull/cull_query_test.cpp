// The library calls behind `lintel cull` and `lintel bench cull`: GPU and CPU answers agree on a
// generated building, bad cameras are statuses, and the benchmark runs clean under validation.
#include <lintel/tools/cull_bench.h>
#include <lintel/tools/cull_query.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

namespace lintel::gpu {
namespace {

World cottage() {
  World world;
  Status s = build_world(generate_cottage({}), "cottage", world);
  EXPECT_TRUE(s.ok()) << s.message();
  return world;
}

CullQueryOptions looking_from_first_timeline(const World& world) {
  CullQueryOptions options;
  const TimelineKey& key = world.timelines.at(0).keys.at(0);
  options.view.eye_world = key.eye_world;
  options.view.target_world = key.target_world;
  options.validation = true;
  return options;
}

TEST(CullQuery, GpuAndCpuAgreePerGroup) {
  const World world = cottage();
  ASSERT_FALSE(world.timelines.empty());
  CullQueryOptions options = looking_from_first_timeline(world);
  CullQueryResult gpu, cpu;
  Status s = cull_query(world, options, gpu);
  ASSERT_TRUE(s.ok()) << s.message();
  options.use_gpu = false;
  ASSERT_TRUE(cull_query(world, options, cpu).ok());
  EXPECT_EQ(gpu.method, "gpu");
  EXPECT_EQ(cpu.method, "cpu");
  EXPECT_FALSE(gpu.device.empty());
  EXPECT_EQ(gpu.visible_cells, cpu.visible_cells);
  EXPECT_GT(cpu.visible_instances, 0u);
  ASSERT_EQ(gpu.groups.size(), world.groups.size());
  uint32_t base = 0;
  for (size_t g = 0; g < gpu.groups.size(); ++g) {
    EXPECT_EQ(gpu.groups[g].instances, cpu.groups[g].instances) << "group " << g;
    EXPECT_EQ(gpu.groups[g].command.first_instance, base);
    EXPECT_EQ(gpu.groups[g].command.instance_count, gpu.groups[g].instances.size());
    EXPECT_EQ(gpu.groups[g].command.index_count, world.meshes[world.groups[g].mesh].indices.size());
    base += uint32_t(world.groups[g].instances.size());
  }
}

TEST(CullQuery, BadCameraIsAStatus) {
  const World world = cottage();
  CullQueryOptions options = looking_from_first_timeline(world);
  options.view.target_world = options.view.eye_world;
  CullQueryResult out;
  Status s = cull_query(world, options, out);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("view"), std::string::npos) << s.message();
}

TEST(CullBench, SmallRunUnderValidation) {
  CullBenchOptions options;
  options.instance_counts = {1000, 3000};
  options.repetitions = 2;
  options.validation = true;
  CullBenchResult result;
  Status s = run_cull_benchmark(options, result);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(result.rows.size(), 6u);  // gpu, cpu x1, cpu x2 per size
  for (const CullBenchRow& row : result.rows) {
    EXPECT_GT(row.instances_per_second, 0.0);
    EXPECT_GT(row.visible, 0u);
  }
  const std::string json = result.to_json();
  EXPECT_NE(json.find("\"method\": \"gpu\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"threads\": 2"), std::string::npos) << json;
}

}  // namespace
}  // namespace lintel::gpu

// PLACEHOLDER: replaced by the generators.
#include <lintel/scene_gen.h>
namespace lintel {
SceneDesc generate_cottage(const CottageOptions&) { return {}; }
SceneDesc generate_grid(const GridOptions&) { return {}; }
SceneDesc generate_ring(const RingOptions&) { return {}; }
SceneDesc generate_random(const RandomOptions&) { return {}; }
}  // namespace lintel

// VisibleSet housekeeping: clearing without giving memory back, so reuse does not allocate.
#include <lintel/visible_set.h>

namespace lintel {

void VisibleSet::clear() {
  start_cell = 0;
  cells.clear();
  polygons.clear();
  vertices_ndc.clear();
  slot_of_cell.clear();
  instances.clear();
  transforms.clear();
  linked_cells.clear();
  linked_instances.clear();
  unresolved.clear();
  stats = VisibilityStats{};
}

}  // namespace lintel

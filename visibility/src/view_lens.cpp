// ViewLens: the lens's terms, recomputed only when the lens changes (view_lens.h).
#include <lintel/view_lens.h>

#include <lintel/doorway_rule.h>

namespace lintel {

void ViewLens::update(const View& view) {
  if (view.fov_y_deg == fov_y_deg && view.aspect == aspect && view.near_m == near_m && view.far_m == far_m) return;
  fov_y_deg = view.fov_y_deg;
  aspect = view.aspect;
  near_m = view.near_m;
  far_m = view.far_m;
  view_to_clip = view_to_clip_d(view);
  near_extent = near_half_extent(view);
  clip_depth = portal_clip_depth(view);
}

}  // namespace lintel

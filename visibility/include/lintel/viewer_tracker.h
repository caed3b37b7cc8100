// Follows the viewer's cell from frame to frame by portal crossings, so that the flood is rooted
// in the cell the eye actually walked into, not in "whichever volume contains the eye" (which
// flaps when a third-person camera drifts across a doorway).
//
// Rules (docs/visibility.md):
//  * Sides: a portal splits space by its own plane; signed distance (normal_world from `from` to
//    `to`) > 0 is `to`'s side, <= 0 is `from`'s side. A move crosses portal P out of the tracked
//    cell when the segment old eye -> new eye passes from the tracked cell's side to the other and
//    the crossing point lies in P's polygon (closed). Every portal whose from or to is the tracked
//    cell counts, one-way ones too (the opening is physical; one-way only limits what is seen).
//  * Several crossings in one move are followed in order along the segment, at most
//    TrackerOptions::max_crossings_per_move. No crossing: the cell stays (sticky).
//  * Jump: a move longer than jump_distance_m re-locates by containment (cell_locate.h).
//  * Lost: after following crossings, an eye outside the tracked cell's volume by more than
//    lost_tolerance_m re-locates by containment; nearest cell when no volume contains it.
//  * Every change of cell is reported with its reason.
// No flap by construction: the cell changes exactly when the eye changes side within a portal.
#pragma once

#include <lintel/status.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace lintel {

inline constexpr uint32_t kMaxTrackerCrossings = 64;
inline constexpr uint32_t kNoCell = std::numeric_limits<uint32_t>::max();

struct TrackerOptions {
  float jump_distance_m = 2.0f;          // a longer move is a teleport: re-locate by containment
  float lost_tolerance_m = 0.25f;        // outside the tracked volume by more: re-locate
  uint32_t max_crossings_per_move = 16;  // 1..kMaxTrackerCrossings; more crossings are ignored
};

enum class TransitionReason : uint8_t { PortalCrossing, Containment, Nearest };
const char* transition_reason_name(TransitionReason reason);

struct CellTransition {
  uint32_t from = kNoCell;  // kNoCell for the first placement by reset()
  uint32_t to = 0;
  TransitionReason reason = TransitionReason::PortalCrossing;
  uint32_t portal = kNoCell;  // the portal crossed (PortalCrossing only)
  friend bool operator==(const CellTransition&, const CellTransition&) = default;
};

class ViewerTracker {
 public:
  ViewerTracker() = default;
  explicit ViewerTracker(const TrackerOptions& options) : options_(options) {}

  // Binds to `world` (which must outlive the tracker's use) and places the eye by containment /
  // nearest cell. Allocates (per-world adjacency and volumes). Errors: non-finite eye, world
  // without cells, bad options.
  Status reset(const World& world, const glm::vec3& eye_world);
  // Follows the eye to its new position. Does not allocate. Errors: non-finite eye (the state is
  // unchanged), update before reset or with a different world.
  Status update(const World& world, const glm::vec3& eye_world);

  bool placed() const { return cell_ != kNoCell; }
  uint32_t cell() const { return cell_; }
  const glm::vec3& eye_world() const { return eye_; }
  // The transitions of the last reset() or update(), in order.
  std::span<const CellTransition> transitions() const { return {transitions_.data(), transition_count_}; }

 private:
  void relocate(const World& world, const glm::dvec3& eye);
  void record(const CellTransition& t);

  TrackerOptions options_;
  const World* world_ = nullptr;
  uint32_t cell_ = kNoCell;
  glm::vec3 eye_{0.0f};
  std::vector<uint32_t> incident_begin_;  // portals touching each cell (from or to), CSR
  std::vector<uint32_t> incident_;
  std::vector<double> volumes_m3_;
  std::array<CellTransition, kMaxTrackerCrossings + 1> transitions_{};
  uint32_t transition_count_ = 0;
};

}  // namespace lintel

// Follows the viewer's cell from frame to frame by portal crossings, so that the flood is rooted
// in the cell the eye actually walked into, not in "whichever volume contains the eye" (which
// flaps when a third-person camera drifts across a doorway).
//
// Rules (docs/visibility.md):
//  * Sides: a portal splits space by its own plane. Seen from the tracked cell C, a portal P's
//    signed distance s (portal_signed_distance(P, C, eye)) is > 0 on the other cell's side. The
//    plane and a band of hysteresis_band_m(P) beyond it belong to C, whichever cell C is: a move
//    crosses P out of C when the segment old eye -> new eye passes from s <= band to s > band and
//    the crossing point (band off the plane) lies in P's polygon (closed). Because the rule is
//    the same from both sides, containment placing an eye that lies on the plane in either cell
//    agrees with it: walking on into the other cell is a crossing once the eye is band past.
//    Every portal whose from or to is C counts, one-way and closed ones too (the opening is
//    physical; one-way and closed only limit what is seen).
//  * Hysteresis: an eye resting within the band of a plane never switches (oscillation with
//    amplitude <= band: zero switches); a real walk through switches exactly once. Meanwhile the
//    eye is at most band outside C's volume and within band (<= kMaxHysteresisBand_m <= the near
//    distance) of P's plane inside its polygon, so the doorway rule passes C's whole region to
//    the other cell: the visible set stays a superset of both cells' views.
//  * Several crossings in one move are followed in order along the segment, at most
//    TrackerOptions::max_crossings_per_move. No crossing: the cell stays (sticky).
//  * Jump: a move longer than jump_distance_m re-locates by containment (cell_locate.h).
//  * Lost: after following crossings, an eye outside the tracked cell's volume by more than
//    lost_tolerance_m, or by more than found_elsewhere_m while another cell's volume contains it
//    (it walked through a wall into a room), re-locates by containment; nearest cell when no
//    volume contains it.
//  * Linked portals (docs/visibility.md, "Linked portals"): a teleport is crossed from its `from`
//    cell only, by the same rule; the eye (and the rest of the move) is carried by its link into
//    `to`, reported as TransitionReason::Teleport, and teleport() returns the transform the caller
//    must apply to its camera (eye, target, up) before the next update(). A caller that does not
//    apply it moves the eye far from where the tracker put it: the jump / lost rules re-locate by
//    containment. Mirrors are walls for the tracker (never crossed).
//  * Every change of cell is reported with its reason.
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

// Hysteresis band of a portal (meters): max(kMinHysteresisBand_m, 8 float ulps of the portal's
// largest world coordinate), capped at min(kMaxHysteresisBand_m, 1 % of the portal's inradius
// about its centroid). The floor absorbs the micrometre jitter physics and animation put on a
// resting eye; the ulp term absorbs float rounding far from the origin (10 um at 10 m, 0.95 mm at
// 1 km); the cap keeps the band inside any sane near plane (the doorway rule needs band <= near_m;
// View's default near is 50 mm) and tiny next to the opening.
inline constexpr double kMinHysteresisBand_m = 1e-5;
inline constexpr double kMaxHysteresisBand_m = 1e-3;
double hysteresis_band_m(const Portal& portal);

struct TrackerOptions {
  float jump_distance_m = 2.0f;          // a longer move is a teleport: re-locate by containment
  float lost_tolerance_m = 0.25f;        // outside the tracked volume by more: re-locate
  uint32_t max_crossings_per_move = 16;  // 1..kMaxTrackerCrossings; more crossings are ignored
  // Outside the tracked volume by more than this (or the largest hysteresis band, if larger)
  // while another cell's volume contains the eye: re-locate (it walked through a wall into a
  // room). Above the float error of far-from-origin geometry (about 1 mm at 1e4 m), so cracks
  // between volumes do not flap.
  float found_elsewhere_m = 0.01f;
};

enum class TransitionReason : uint8_t { PortalCrossing, Containment, Nearest, Teleport };
const char* transition_reason_name(TransitionReason reason);

struct CellTransition {
  uint32_t from = kNoCell;  // kNoCell for the first placement by reset()
  uint32_t to = 0;
  TransitionReason reason = TransitionReason::PortalCrossing;
  uint32_t portal = kNoCell;  // the portal crossed (PortalCrossing and Teleport only)
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
  // Follows the eye to its new position. Does not allocate, except once after World::revision
  // changed (a reload or an edit finalized into the same World): then it re-derives its per-world
  // data and re-locates the eye by containment. Errors: non-finite eye (the state is unchanged),
  // update before reset or with a different world.
  Status update(const World& world, const glm::vec3& eye_world);

  bool placed() const { return cell_ != kNoCell; }
  uint32_t cell() const { return cell_; }
  // The eye as the tracker holds it: the last eye passed in, carried by any teleport it crossed.
  const glm::vec3& eye_world() const { return eye_; }
  // The product of the link transforms of the teleports crossed by the last update() (identity
  // when none): apply it to the camera (points: m * (p, 1); directions: m * (d, 0)).
  const glm::dmat4& teleport() const { return teleport_; }
  bool teleported() const { return teleport_ != glm::dmat4(1.0); }
  // The transitions of the last reset() or update(), in order.
  std::span<const CellTransition> transitions() const { return {transitions_.data(), transition_count_}; }

 private:
  void bind(const World& world);
  void relocate(const World& world, const glm::dvec3& eye);
  void record(const CellTransition& t);

  TrackerOptions options_;
  const World* world_ = nullptr;
  uint64_t revision_ = 0;
  uint32_t cell_ = kNoCell;
  glm::vec3 eye_{0.0f};
  glm::dmat4 teleport_{1.0};
  std::vector<uint32_t> incident_begin_;  // portals touching each cell (from or to), CSR
  std::vector<uint32_t> incident_;
  std::vector<double> volumes_m3_;
  std::vector<double> band_m_;  // hysteresis_band_m of each portal
  double max_band_m_ = 0.0;
  std::array<CellTransition, kMaxTrackerCrossings + 1> transitions_{};
  uint32_t transition_count_ = 0;
};

}  // namespace lintel

// Shells of axis-aligned rooms and of the exterior around an axis-aligned house. All six faces
// share three global split lists (X, Y, Z), so walls, floor, ceiling and reveals meet vertex to
// vertex; every coordinate is built by permuting split values, never by arithmetic, so shared
// corners are bit-identical.
#include "generate/room_shell.h"

#include <cassert>
#include <cmath>

namespace lintel::gen {
namespace {

enum Face { kXMin, kXMax, kZMin, kZMax, kFloor, kCeiling, kFaceCount };

struct FaceHole {
  Face face;
  PanelHole hole;
};

struct MidBox {
  double x0, x1, z0, z1, y0, y1;
};

MidBox mid_box(const RoomPlan& r) {
  return {r.footprint[0].x, r.footprint[2].x, r.footprint[0].y, r.footprint[2].y, r.floor_mid, r.ceiling_mid};
}

// Which face of the mid box the opening lies on, and its rectangle in that face's (a, b):
// walls facing X use (z, y), walls facing Z use (x, y), floor and ceiling use (x, z).
FaceHole classify(const OpeningPlan& o, const MidBox& box, PanelHole::Kind kind) {
  FaceHole fh{kXMin, {o.u0, o.u1, o.v0, o.v1, kind}};
  if (o.in_slab) {
    assert(o.u_axis == glm::dvec3(1, 0, 0) && o.v_axis == glm::dvec3(0, 0, 1));
    assert(o.origin.y == box.y0 || o.origin.y == box.y1);
    fh.face = o.origin.y == box.y0 ? kFloor : kCeiling;
  } else if (o.u_axis == glm::dvec3(0, 0, 1)) {
    assert(o.origin.x == box.x0 || o.origin.x == box.x1);
    fh.face = o.origin.x == box.x0 ? kXMin : kXMax;
  } else {
    assert(o.u_axis == glm::dvec3(1, 0, 0) && (o.origin.z == box.z0 || o.origin.z == box.z1));
    fh.face = o.origin.z == box.z0 ? kZMin : kZMax;
  }
  return fh;
}

std::vector<FaceHole> face_holes(const BuildingPlan& plan, int room, const MidBox& box) {
  std::vector<FaceHole> out;
  for (const OpeningPlan& o : plan.openings)
    if ((o.from == room || o.to == room) && !o.linked()) out.push_back(classify(o, box, hole_kind(o, room)));
  return out;
}

// Plans compute a door's sill as floor_mid + half a slab in their own way; a last-bit difference
// from the face's own value would leave a sliver row, so bounds that close snap to the face.
void snap_to_faces(std::vector<FaceHole>& holes, const double fx[2], const double fy[2], const double fz[2]) {
  auto snap = [](double& v, const double face[2]) {
    for (int i = 0; i < 2; ++i)
      if (std::fabs(v - face[i]) < 1e-9) v = face[i];
  };
  for (FaceHole& fh : holes) {
    const bool x_wall = fh.face == kXMin || fh.face == kXMax, z_wall = fh.face == kZMin || fh.face == kZMax;
    const double* a_face = x_wall ? fz : fx;
    const double* b_face = (x_wall || z_wall) ? fy : fz;
    snap(fh.hole.a0, a_face), snap(fh.hole.a1, a_face), snap(fh.hole.b0, b_face), snap(fh.hole.b1, b_face);
  }
}

struct Splits {
  std::vector<double> x, y, z;
};

// Collects hole bounds into the split lists of the axes they run along.
void add_hole_splits(const std::vector<FaceHole>& holes, Splits& s) {
  for (const FaceHole& fh : holes) {
    const PanelHole& h = fh.hole;
    switch (fh.face) {
      case kXMin:
      case kXMax:
        s.z.insert(s.z.end(), {h.a0, h.a1});
        s.y.insert(s.y.end(), {h.b0, h.b1});
        break;
      case kZMin:
      case kZMax:
        s.x.insert(s.x.end(), {h.a0, h.a1});
        s.y.insert(s.y.end(), {h.b0, h.b1});
        break;
      default:
        s.x.insert(s.x.end(), {h.a0, h.a1});
        s.z.insert(s.z.end(), {h.b0, h.b1});
        break;
    }
  }
}

std::vector<PanelHole> holes_on(const std::vector<FaceHole>& holes, Face face) {
  std::vector<PanelHole> out;
  for (const FaceHole& fh : holes)
    if (fh.face == face) out.push_back(fh.hole);
  return out;
}

// The six panels of a box whose air-side faces are at x = fx[0|1], y = fy[0|1], z = fz[0|1] and
// whose mid-planes are at mx, my, mz; `inward` says whether the air is inside the box.
void emit_box_faces(const double fx[2], const double fy[2], const double fz[2], const double mx[2], const double my[2],
                    const double mz[2], bool inward, const Splits& s, const std::vector<FaceHole>& holes,
                    bool with_floor_and_ceiling, ShellMesh& out) {
  const double in = inward ? 1.0 : -1.0;
  for (int side = 0; side < 2; ++side) {
    const double sign = (side == 0 ? 1.0 : -1.0) * in;  // the min face looks +axis from inside
    WallPanel wx;
    wx.a_splits = splits_within(s.z, fz[0], fz[1]);
    wx.b_splits = splits_within(s.y, fy[0], fy[1]);
    wx.holes = holes_on(holes, side == 0 ? kXMin : kXMax);
    wx.normal = {sign, 0, 0};
    wx.axis_a = {0, 0, 1};
    wx.axis_b = {0, 1, 0};
    const double face_x = fx[side], mid_x = mx[side];
    wx.point = [=](double a, double b, bool mid) { return glm::dvec3(mid ? mid_x : face_x, b, a); };
    emit_panel(wx, out);

    WallPanel wz = wx;
    wz.a_splits = splits_within(s.x, fx[0], fx[1]);
    wz.holes = holes_on(holes, side == 0 ? kZMin : kZMax);
    wz.normal = {0, 0, sign};
    wz.axis_a = {1, 0, 0};
    const double face_z = fz[side], mid_z = mz[side];
    wz.point = [=](double a, double b, bool mid) { return glm::dvec3(a, b, mid ? mid_z : face_z); };
    emit_panel(wz, out);

    if (!with_floor_and_ceiling) continue;
    WallPanel h;
    h.a_splits = splits_within(s.x, fx[0], fx[1]);
    h.b_splits = splits_within(s.z, fz[0], fz[1]);
    h.holes = holes_on(holes, side == 0 ? kFloor : kCeiling);
    h.normal = {0, sign, 0};
    h.axis_a = {1, 0, 0};
    h.axis_b = {0, 0, 1};
    const double face_y = fy[side], mid_y = my[side];
    h.point = [=](double a, double b, bool mid) { return glm::dvec3(a, mid ? mid_y : face_y, b); };
    emit_panel(h, out);
  }
}

}  // namespace

ShellMesh build_box_shell(const BuildingPlan& plan, int room) {
  const RoomPlan& r = plan.rooms[size_t(room)];
  const MidBox m = mid_box(r);
  const double hw = 0.5 * kWallThickness, hs = 0.5 * kSlabThickness;
  const double fx[2] = {m.x0 + hw, m.x1 - hw}, fy[2] = {m.y0 + hs, m.y1 - hs}, fz[2] = {m.z0 + hw, m.z1 - hw};
  const double mx[2] = {m.x0, m.x1}, my[2] = {m.y0, m.y1}, mz[2] = {m.z0, m.z1};
  std::vector<FaceHole> holes = face_holes(plan, room, m);
  snap_to_faces(holes, fx, fy, fz);
  Splits s{{fx[0], fx[1]}, {fy[0], fy[1]}, {fz[0], fz[1]}};
  add_hole_splits(holes, s);
  ShellMesh out;
  emit_box_faces(fx, fy, fz, mx, my, mz, true, s, holes, true, out);
  return out;
}

ShellMesh build_exterior_shell(const BuildingPlan& plan, int room) {
  const RoomPlan& r = plan.rooms[size_t(room)];
  assert(is_axis_aligned_box(r));
  const MidBox m = mid_box(r);
  const double hw = 0.5 * kWallThickness;
  const double ground = m.y0, roof = m.y1 + 0.5 * kSlabThickness;
  const double fx[2] = {m.x0 - hw, m.x1 + hw}, fy[2] = {ground, roof}, fz[2] = {m.z0 - hw, m.z1 + hw};
  const double mx[2] = {m.x0, m.x1}, my[2] = {ground, roof}, mz[2] = {m.z0, m.z1};
  std::vector<FaceHole> holes = face_holes(plan, room, m);
  snap_to_faces(holes, fx, fy, fz);
  for ([[maybe_unused]] const FaceHole& fh : holes) assert(fh.face != kFloor && fh.face != kCeiling);
  Splits s{{fx[0], fx[1]}, {fy[0], fy[1]}, {fz[0], fz[1]}};
  add_hole_splits(holes, s);
  ShellMesh out;
  emit_box_faces(fx, fy, fz, mx, my, mz, false, s, holes, false, out);

  // Roof over the facade's outline, then the ground around it with the footprint cut out; both
  // use the facade's splits, so their edges meet the facade's vertex for vertex.
  WallPanel roof_panel;
  roof_panel.a_splits = splits_within(s.x, fx[0], fx[1]);
  roof_panel.b_splits = splits_within(s.z, fz[0], fz[1]);
  roof_panel.normal = {0, 1, 0};
  roof_panel.axis_a = {1, 0, 0};
  roof_panel.axis_b = {0, 0, 1};
  roof_panel.point = [=](double a, double b, bool) { return glm::dvec3(a, roof, b); };
  emit_panel(roof_panel, out);

  WallPanel ground_panel = roof_panel;
  const double g = r.ground_margin;
  std::vector<double> gx = s.x, gz = s.z;
  gx.insert(gx.end(), {fx[0] - g, fx[1] + g});
  gz.insert(gz.end(), {fz[0] - g, fz[1] + g});
  ground_panel.a_splits = splits_within(gx, fx[0] - g, fx[1] + g);
  ground_panel.b_splits = splits_within(gz, fz[0] - g, fz[1] + g);
  ground_panel.holes = {{fx[0], fx[1], fz[0], fz[1], PanelHole::Kind::Cutout}};
  ground_panel.point = [=](double a, double b, bool) { return glm::dvec3(a, ground, b); };
  emit_panel(ground_panel, out);
  return out;
}

}  // namespace lintel::gen

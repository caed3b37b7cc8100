// The exact convex partition of a Doom sector (scene/src/doom/doom_sector_partition.h) and the
// convex cells built on it (doom_convex_cells.h), on maps made in the test: random polyominoes
// (unions of grid squares: holes, disjoint parts, parts touching at one corner, collinear line
// ends), and outlines that must be refused.
#include "doom/doom_convex_cells.h"
#include "doom/doom_sector_partition.h"
#include "doom/polygon_triangulate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace lintel::doom {
namespace {

constexpr double kSquare = 64.0;  // map units per grid square

// A map whose sector 0 is the union of the grid squares with inside[j * n + i] == 1; squares with
// 2 are sector 1 (lines between the two sectors are two-sided), 0 is void (one-sided walls).
Map polyomino_map(const std::vector<int>& cells, int n) {
  Map map;
  map.sectors.resize(2);
  map.sidedefs.push_back({0});
  map.sidedefs.push_back({1});
  auto at = [&](int i, int j) { return i < 0 || j < 0 || i >= n || j >= n ? 0 : cells[size_t(j * n + i)]; };
  auto add_line = [&](glm::dvec2 a, glm::dvec2 b, int other) {
    // Sector 0 lies to the right of a -> b (its front side).
    Linedef line;
    line.v1 = uint16_t(map.vertices.size());
    map.vertices.push_back(a * kSquare);
    line.v2 = uint16_t(map.vertices.size());
    map.vertices.push_back(b * kSquare);
    line.front = 0;
    line.back = other == 1 ? 1 : kNoSide;
    map.linedefs.push_back(line);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (at(i, j) != 1) continue;
      const double x = i, y = j;
      // Each side walked clockwise round the square, so that the square is on its right.
      if (at(i, j - 1) != 1) add_line({x + 1, y}, {x, y}, at(i, j - 1));
      if (at(i - 1, j) != 1) add_line({x, y}, {x, y + 1}, at(i - 1, j));
      if (at(i, j + 1) != 1) add_line({x, y + 1}, {x + 1, y + 1}, at(i, j + 1));
      if (at(i + 1, j) != 1) add_line({x + 1, y + 1}, {x + 1, y}, at(i + 1, j));
    }
  return map;
}

bool strictly_inside(const SectorPartition& part, const SectorPartition::Piece& piece, const glm::dvec2& p) {
  for (size_t i = 0; i < piece.polygon.size(); ++i)
    if (!(orient2(part.corners[piece.polygon[i]], part.corners[piece.polygon[(i + 1) % piece.polygon.size()]], p) >
          0.0))
      return false;
  return true;
}

// Corner index of `to` follows `from` in the piece's polygon.
bool has_edge(const SectorPartition::Piece& piece, uint32_t from, uint32_t to) {
  for (size_t i = 0; i < piece.polygon.size(); ++i)
    if (piece.polygon[i] == from && piece.polygon[(i + 1) % piece.polygon.size()] == to) return true;
  return false;
}

// Property: for any union of grid squares (random, with holes, disjoint parts, parts touching at a
// corner and long straight walls of many lines), the partition succeeds and tiles the sector
// exactly: every piece is convex (exact orientation tests), the pieces' areas add up to the
// squares' area exactly, a point inside any square of the sector lies inside exactly one piece and
// a point of any other square in none; every side of the sector's lines is an edge of the piece
// it names, and every diagonal is an edge of both of its pieces, one each way. The convex groups
// over it (no hull excess) are convex and their cuts run between corners of the sector; a pair
// of pieces that must be joined ends in one group.
TEST(SectorPartition, RandomPolyominoesAreTiledExactlyByConvexPieces) {
  std::mt19937 rng(1234);
  const int n = 9;
  size_t touching_corners = 0;
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    std::vector<int> cells(size_t(n * n));
    std::uniform_int_distribution<int> kind(0, 9);
    int squares = 0;
    for (int& c : cells) {
      const int k = kind(rng);
      c = k < 6 ? 1 : (k < 8 ? 2 : 0);
      squares += c == 1;
    }
    if (squares == 0) continue;
    const Map map = polyomino_map(cells, n);
    SectorPartition part;
    ASSERT_EQ(partition_sector(map, 0, part), "");
    ASSERT_FALSE(part.pieces.empty());
    touching_corners += part.corners.size() > [&] {
      std::vector<std::pair<double, double>> unique;
      for (const glm::dvec2& c : part.corners) unique.emplace_back(c.x, c.y);
      std::sort(unique.begin(), unique.end());
      return size_t(std::unique(unique.begin(), unique.end()) - unique.begin());
    }();
    double area2 = 0.0;
    for (const SectorPartition::Piece& piece : part.pieces) {
      const size_t m = piece.polygon.size();
      ASSERT_GE(m, 3u);
      double piece2 = 0.0;
      for (size_t i = 0; i < m; ++i) {
        const glm::dvec2 a = part.corners[piece.polygon[i]], b = part.corners[piece.polygon[(i + 1) % m]];
        EXPECT_GE(orient2(part.corners[piece.polygon[(i + m - 1) % m]], a, b), 0.0) << "a reflex corner";
        piece2 += a.x * b.y - b.x * a.y;
      }
      EXPECT_GT(piece2, 0.0);
      area2 += piece2;
    }
    EXPECT_EQ(area2, 2.0 * squares * kSquare * kSquare);
    EXPECT_EQ(part.area, squares * kSquare * kSquare);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const glm::dvec2 p = (glm::dvec2(i, j) + glm::dvec2(0.3183098861837907, 0.7071067811865476)) * kSquare;
        int count = 0;
        for (const SectorPartition::Piece& piece : part.pieces) count += strictly_inside(part, piece, p);
        EXPECT_EQ(count, cells[size_t(j * n + i)] == 1 ? 1 : 0) << "square " << i << "," << j;
      }
    // Every line side: lines of sector 0 were added with their front on it.
    ASSERT_EQ(part.side_piece.size(), map.linedefs.size());
    for (const auto& [side, piece] : part.side_piece) {
      ASSERT_EQ(side % 2, 0u);
      const Linedef& line = map.linedefs[side / 2];
      // The sector lies to the left of v2 -> v1: find the corners there.
      bool found = false;
      for (size_t i = 0; i < part.pieces[piece].polygon.size() && !found; ++i) {
        const auto& poly = part.pieces[piece].polygon;
        found = part.corners[poly[i]] == map.vertices[line.v2] &&
                part.corners[poly[(i + 1) % poly.size()]] == map.vertices[line.v1];
      }
      EXPECT_TRUE(found) << "line " << side / 2 << " is no edge of its piece";
    }
    for (const SectorPartition::Diagonal& d : part.diagonals) {
      EXPECT_NE(d.left, d.right);
      EXPECT_TRUE(has_edge(part.pieces[d.left], d.a, d.b));
      EXPECT_TRUE(has_edge(part.pieces[d.right], d.b, d.a));
    }
    size_t group_count = 0;
    const std::vector<size_t> group = convex_piece_groups(part, 0.0, {}, group_count);
    std::vector<std::vector<glm::dvec2>> group_corners(group_count);
    std::vector<double> group_area(group_count, 0.0);
    for (size_t p = 0; p < part.pieces.size(); ++p) {
      for (uint32_t c : part.pieces[p].polygon) group_corners[group[p]].push_back(part.corners[c]);
      for (const auto& t : part.pieces[p].triangles)
        group_area[group[p]] += 0.5 * orient2(part.corners[t[0]], part.corners[t[1]], part.corners[t[2]]);
    }
    for (size_t g = 0; g < group_count; ++g) EXPECT_EQ(convex_hull_area(group_corners[g]), group_area[g]);
    // A pair that must be joined (a thing stands across its diagonal) ends in one group.
    if (!part.diagonals.empty()) {
      const SectorPartition::Diagonal& d = part.diagonals[size_t(trial) % part.diagonals.size()];
      size_t forced_count = 0;
      const std::vector<size_t> forced = convex_piece_groups(part, 0.0, {{d.left, d.right}}, forced_count);
      EXPECT_EQ(forced[d.left], forced[d.right]);
    }
    for (const GroupBoundary& cut : group_boundaries(part, group)) {
      EXPECT_NE(cut.left, cut.right);
      EXPECT_EQ(cut.a, glm::floor(cut.a));
      EXPECT_EQ(cut.b, glm::floor(cut.b));
    }
  }
  EXPECT_GT(touching_corners, 50u);  // the generator does make parts that touch at a corner
}

// A square with a square hole and a second square touching the first at one corner: one outer
// loop with a hole, one outer loop that shares a position with it; 4 lines meet at the shared
// corner, and the result tiles 9 * 9 - 3 * 3 + 2 * 2 units^2 with convex pieces.
TEST(SectorPartition, HoleAndTouchingCorner) {
  // 0: void, 1: sector 0.
  std::vector<int> cells = {
      1, 1, 1, 0, 0,  //
      1, 0, 1, 0, 0,  //
      1, 1, 1, 0, 0,  //
      0, 0, 0, 1, 0,  //
      0, 0, 0, 0, 0,
  };
  const Map map = polyomino_map(cells, 5);
  SectorPartition part;
  ASSERT_EQ(partition_sector(map, 0, part), "");
  EXPECT_EQ(part.area, 9 * kSquare * kSquare);
  // The corner (3, 3) * 64 carries two corners (one per loop).
  size_t at_touch = 0;
  for (const glm::dvec2& c : part.corners) at_touch += c == glm::dvec2(3, 3) * kSquare;
  EXPECT_EQ(at_touch, 2u);
  size_t group_count = 0;
  const std::vector<size_t> group = convex_piece_groups(part, 0.0, {}, group_count);
  EXPECT_GE(group_count, 5u);  // a ring needs at least 4 convex parts, plus the touching square
  EXPECT_FALSE(group_boundaries(part, group).empty());
}

// Outlines that are no polygon with holes are refused with the reason (the importer then keeps
// the sector as one cell): a missing line, two lines that cross, a line doubled, a line end off
// the integer grid, two lines back to back.
TEST(SectorPartition, BrokenOutlinesAreRefused) {
  std::vector<int> square = {1};
  SectorPartition part;
  {
    Map map = polyomino_map(square, 1);
    map.linedefs.pop_back();
    EXPECT_NE(partition_sector(map, 0, part).find("odd number"), std::string::npos);
  }
  {
    // A bow tie: A -> B -> C -> D -> A where B -> C and D -> A cross.
    Map map;
    map.sectors.resize(1);
    map.sidedefs.push_back({0});
    map.vertices = {{0, 0}, {128, 0}, {0, 128}, {128, 128}};
    for (uint16_t i = 0; i < 4; ++i) {
      Linedef line;
      line.v1 = uint16_t((i + 1) % 4);  // the sector on the right of v1 -> v2, i.e. left of v2 -> v1
      line.v2 = i;
      line.front = 0;
      map.linedefs.push_back(line);
    }
    EXPECT_EQ(partition_sector(map, 0, part), "two of its lines cross or touch");
  }
  {
    Map map = polyomino_map(square, 1);
    map.linedefs.push_back(map.linedefs[0]);
    EXPECT_NE(partition_sector(map, 0, part), "");
  }
  {
    Map map = polyomino_map(square, 1);
    map.vertices[map.linedefs[0].v1].x += 0.5;
    map.vertices[map.linedefs[3].v2].x += 0.5;
    EXPECT_EQ(partition_sector(map, 0, part), "a line end is not an integer point");
  }
  {
    // A thin wall inside an otherwise good room: two one-sided lines of the sector, back to back.
    std::vector<int> room = {1, 1, 1, 1};
    Map map = polyomino_map(room, 2);
    Linedef across;
    across.front = 0;
    across.v1 = uint16_t(map.vertices.size());
    map.vertices.push_back(glm::dvec2(0.5, 1.5) * kSquare);
    across.v2 = uint16_t(map.vertices.size());
    map.vertices.push_back(glm::dvec2(1.5, 0.5) * kSquare);
    Linedef back = across;
    std::swap(back.v1, back.v2);
    map.linedefs.push_back(across);
    map.linedefs.push_back(back);
    EXPECT_EQ(partition_sector(map, 0, part), "two of its lines overlap");
  }
}

// Triangulation certificate: the exact check accepts a correct triangulation of a square and
// refuses one with a triangle flipped, one missing, and one covering the square twice.
TEST(SectorPartition, TriangulationCertificateRefusesBadTilings) {
  const std::vector<glm::dvec2> pts = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const std::vector<std::vector<uint32_t>> loop = {{0, 1, 2, 3}};
  std::vector<std::array<uint32_t, 3>> tris;
  ASSERT_TRUE(triangulate_polygon(pts, loop[0], {}, tris));
  EXPECT_TRUE(triangulation_covers_outline(pts, loop, tris));
  EXPECT_TRUE(triangulation_covers_outline(pts, loop, {{0, 1, 2}, {0, 2, 3}}));
  EXPECT_FALSE(triangulation_covers_outline(pts, loop, {{0, 2, 1}, {0, 2, 3}}));
  EXPECT_FALSE(triangulation_covers_outline(pts, loop, {{0, 1, 2}}));
  EXPECT_FALSE(triangulation_covers_outline(pts, loop, {{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {1, 2, 3}}));
}

}  // namespace
}  // namespace lintel::doom

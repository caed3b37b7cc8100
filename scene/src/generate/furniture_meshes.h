// Furniture for the generated scenes, built from boxes in the mesh's own space: origin at the
// centre of the footprint on the floor, +Y up, the front along +Z. Small (tens of triangles) so
// that grids of thousands of rooms stay light; shared by many instances to form draw groups.
#pragma once

#include <lintel/scene_desc.h>

namespace lintel::gen {

MeshDesc make_table(glm::vec4 color);  // 1.2 x 0.75 x 0.8 m
MeshDesc make_chair(glm::vec4 color);  // 0.45 x 0.95 x 0.45 m, backrest at -Z
MeshDesc make_bed(glm::vec4 color);    // 1.4 x 1.0 x 2.0 m (headboard at -Z)
MeshDesc make_shelf(glm::vec4 color);  // 0.9 x 1.8 x 0.35 m, open towards +Z
MeshDesc make_sofa(glm::vec4 color);   // 1.8 x 0.8 x 0.8 m, backrest at -Z
MeshDesc make_crate(glm::vec4 color);  // 0.6 m cube
// A door leaf 0.04 m thick filling a door opening (kDoorWidth x kDoorHeight): the hinge edge on
// the Y axis, the leaf along -Z, its thickness along +X (placed against a wall's face with the
// hinge at one jamb it closes the opening; turned about Y it swings open).
MeshDesc make_door_leaf(glm::vec4 color);
MeshDesc make_tree(glm::vec4 color);  // trunk and crown, 2.0 x 4.0 x 2.0 m
// A straight flight of `steps` steps rising `height` over `run` along +X from the origin, `width`
// wide across Z (centred); solid down to y = 0.
MeshDesc make_stair(glm::vec4 color, int steps, double run, double height, double width);

// Half extents of a mesh's footprint (x, z) and its height, from its positions.
glm::dvec3 mesh_extent(const MeshDesc& mesh);

}  // namespace lintel::gen

#pragma once
// The local faces of quad4 and hex8 elements in outward node order: quad edges counter-clockwise,
// hex faces as their outward normals turn. One table for the mesh (detach_parts.cpp) and the
// couplings (coupling/element_faces.hpp).
namespace camouflet::element_face_tables {

inline constexpr int quad[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
inline constexpr int hex[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                  {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

}  // namespace camouflet::element_face_tables

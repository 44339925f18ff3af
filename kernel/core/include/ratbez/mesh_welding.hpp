#pragma once
// A mesh welded: vertices at the same coordinates made one, the triangles that then collapse (two corners on one
// vertex) dropped, and the vertices no triangle names any more. It is what a reader of a format without a vertex
// table (binary STL) makes of a mesh whose float32 rounding brought vertices together. With OppositePairs::dropped,
// pairs that bound no volume (the same three corners once each way round) go too: how two faces that both took the
// same sliver along an edge they share are reconciled (tessellate.cpp); no file reader does that, so an exporter
// keeps them. Triangles keep their order and orientation; the vertices kept keep theirs.

#include <cstdint>
#include <vector>

#include "ratbez/mesh.hpp"

namespace ratbez {

enum class OppositePairs { kept, dropped };

Mesh welded(const Mesh& mesh, OppositePairs pairs = OppositePairs::kept);

// For each vertex, the index of the first vertex at exactly its coordinates (itself where it is the first): the
// vertices welded makes one. Equality is exact: only what rounding made equal.
std::vector<std::uint32_t> first_at_same_place(const std::vector<Vec3>& vertices);

}  // namespace ratbez

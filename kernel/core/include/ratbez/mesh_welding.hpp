#pragma once
// A mesh welded: vertices at the same coordinates made one, then the triangles that collapse (two corners on one
// vertex) and the pairs that bound no volume (the same three corners once each way round) dropped, and the
// vertices no triangle names any more. It is what a reader of a format without a vertex table (binary STL) makes
// of a mesh whose float32 rounding brought vertices together, and how two faces that both took the same sliver
// along an edge they share are reconciled (tessellate.cpp). Triangles keep their order and orientation; the
// vertices kept keep theirs.

#include "ratbez/mesh.hpp"

namespace ratbez {

Mesh welded(const Mesh& mesh);

}  // namespace ratbez

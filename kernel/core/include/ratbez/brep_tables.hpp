#pragma once
// Faces as plain indexed tables: vertices by index, edges naming their vertices by index, faces naming
// their edges by index. This is the form a B-rep takes to be stored or sent elsewhere (pickling in the
// Python module) or assembled from another system's topology (the OpenCASCADE reader): shared edges and
// vertices are shared objects in a Solid, and indices are how they stay shared outside it.
//
// faces_of rebuilds through the validating constructors (Face::from_surface, Face::planar, Face::trimmed), so tables
// from anywhere are checked as any user input is; tables_of followed by faces_of gives back the same
// faces exactly (the same numbers, the same sharing).

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "ratbez/brep.hpp"

namespace ratbez {

struct BrepTables {
    struct EdgeRecord {
        NurbsCurve curve;
        std::size_t start = 0, end = 0;  // indices into vertices
        bool degenerate = false;
    };
    struct CoedgeRecord {
        std::size_t edge = 0;  // index into edges
        bool reversed = false;
        std::optional<NurbsCurve> pcurve;  // trimmed faces
    };
    struct FaceRecord {
        Face::Kind kind = Face::Kind::surface;
        std::optional<NurbsSurface> surface;             // surface and trimmed faces (a planar face's patch is derived)
        std::array<CoedgeRecord, 4> sides{};             // surface faces, in Side order
        Plane plane{};                                   // planar faces
        std::vector<std::vector<CoedgeRecord>> loops;    // planar and trimmed faces
        double tolerance = 0;                            // planar and trimmed faces (Face::tolerance)
    };
    std::vector<Vec3> vertices;
    std::vector<EdgeRecord> edges;
    std::vector<FaceRecord> faces;
};

// Every distinct vertex and edge of the faces once, in order of first use.
BrepTables tables_of(std::span<const Face> faces);
// The faces of the tables, edges and vertices shared as the indices say. Throws Error naming
// "faces[i]..." for an index out of range, and whatever the face constructors find wrong.
std::vector<Face> faces_of(const BrepTables& tables);

}  // namespace ratbez

#pragma once
// Where a mesh vertex shared by several faces goes: each face wishes the vertex moved along its own
// outward normal by its own offset within the range its cells accept (tessellate_plan.hpp's offset field;
// a planar face, and one inscribed in its surface, wish exactly 0), and the vertex takes the shortest
// move that grants every wish: the move o with o . n_i = offset_i for each distinct normal n_i. Along a
// smooth edge (one normal) between two different faces (a G1 joint), nothing: the samples of both faces'
// lines meet there, and the strips that zip them together are checked by neither face (a ring's outer
// wall and its rounded top, at a tolerance of 1% of its size); along a seam (one face on both sides) the
// face's wishes are one offset: the middle of the ranges they all accept (a fixed wish wins), or when they
// accept nothing
// in common what the face with the most cells accepts (the others, cheaper to refine, are refined); along a crease (two normals) the solution in the plane
// of the two normals, which for a crease with a planar face lies in the plane (a cylinder's cap circle
// moves out radially, the cap stays flat); at a corner of three or more faces, nothing. A move longer
// than `max_offset` is shortened to it, except at a crease of less than 0.1 radians (where the faces'
// wishes nearly contradict each other), which takes the mean offset along the mean normal. Not
// installed, not part of the public API.

#include <span>

#include "ratbez/vec.hpp"

namespace ratbez::detail {

struct OffsetWish {
    Vec3 normal;            // unit, outward
    double offset;          // along it: the centre of the face's errors there
    double lowest, highest; // the offsets the face's cells accept there
    bool fixed = false;     // exactly `offset` (0): a planar face, which stays planar, or one inscribed in
                            // its surface, which keeps its vertices on it (its grid was checked so)
    double weight = 0;      // the face's cells: where the faces accept nothing in common, the heaviest wins
    const void* face = nullptr;  // whose wish: along a smooth joint of two faces the vertex stays put
};

// A crease edge's own wish for its samples: its polyline's chords sag by s from the curve, towards the
// centre of curvature, so the samples are best moved s / 2 away from it (`outward`, unit), which centres
// the curve on the polyline. At a crease the faces' offsets move within the ranges they accept towards it.
struct EdgeBend {
    Vec3 outward;
    double wanted;
};

Vec3 shared_offset(std::span<const OffsetWish> wishes, double max_offset, const EdgeBend* bend = nullptr);

}  // namespace ratbez::detail

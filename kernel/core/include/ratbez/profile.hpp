#pragma once
// A profile: Bézier and NURBS pieces joined end to end, the input of revolve and extrude.
//
// Pieces must meet within tolerance() = 1e-9 times the diagonal of the profile's control-point box.
// The constructor then makes every joint exact (the start control point of piece k is moved onto the
// end of piece k-1, and for a closed profile the last end onto the first start), so the faces built
// from neighbouring pieces share their boundary curves exactly. Unclamped pieces are first rewritten
// on clamped knot vectors (same curve, same parameterisation), so that their ends are control points.
// A rational piece with a Bézier span whose end weights differ by more than 4x is put in normal form
// (NurbsCurve::normal_form: same curve and domain, each span's parameter spread evenly between its ends,
// C0 at its knots); every other piece keeps its parameterisation.

#include <vector>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/nurbs_curve.hpp"

namespace ratbez {

class Profile {
public:
    // Throws Error naming "profile" when empty, when a piece is a point (degree 0 or all control points
    // equal), or when piece k does not start where piece k-1 ends (within tolerance()).
    explicit Profile(std::vector<NurbsCurve> pieces);
    static Profile from_beziers(const std::vector<BezierCurve>& pieces);

    const std::vector<NurbsCurve>& pieces() const { return pieces_; }
    bool is_closed() const { return closed_; }  // the last piece ends where the first starts
    Vec3 start_point() const;
    Vec3 end_point() const;
    // The absolute tolerance used for joints (and by revolve/extrude for "on the axis", "planar").
    double tolerance() const { return tolerance_; }
    // The diagonal of the axis-aligned box of all control points.
    double size() const { return size_; }
    // The same profile traversed backwards (pieces in reverse order, each reversed).
    Profile reversed() const;

private:
    std::vector<NurbsCurve> pieces_;
    bool closed_ = false;
    double tolerance_ = 0;
    double size_ = 0;
};

}  // namespace ratbez

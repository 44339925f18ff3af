#pragma once
// A profile: Bézier and NURBS pieces joined end to end, the input of revolve and extrude.

#include <vector>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/nurbs_curve.hpp"

namespace ratbez {

class Profile {
public:
    // Throws Error naming "profile" when empty, or when piece k does not start where piece k-1 ends
    // (within a tolerance relative to the profile's size).
    explicit Profile(std::vector<NurbsCurve> pieces);
    static Profile from_beziers(const std::vector<BezierCurve>& pieces);

    const std::vector<NurbsCurve>& pieces() const { return pieces_; }
    bool is_closed() const;  // the last piece ends where the first starts
    Vec3 start_point() const;
    Vec3 end_point() const;

private:
    std::vector<NurbsCurve> pieces_;
};

}  // namespace ratbez

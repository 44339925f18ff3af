#pragma once
// Cubature: integrals over the rational Bézier pieces of NURBS surfaces and plane curves, by a globally
// adaptive Gauss–Legendre engine (QUADPACK's QAG strategy in 2D) on pieces that first pass the weight
// certificate (geometry/subdivision.hpp). The engine knows integrands, surfaces and curves, not faces:
// brep/face_integrals.hpp walks a shell's faces onto it (volume and area of solids, a Solid's orientation
// check). Not installed, not part of the public API.

#include <cmath>
#include <functional>
#include <memory>
#include <string_view>

#include "geometry/surface_evaluator.hpp"
#include "ratbez/box.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/progress.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The frame every piece is measured in: coordinates relative to `reference` (the centre of the part's box),
// in units of 2^exponent (the power of two nearest the box's size). Where the part lies and how large it is
// then change nothing but that frame: a unit sphere at 1e8 is integrated with the accuracy it has at the
// origin (its points are differences of about 1, not numbers of 1e8 whose last bits are the shape; and
// (S - c) . (S_u x S_v) is no longer a difference of large terms), and a sphere of radius 1e80 or 1e-80 as
// one of radius 1 (|S_u x S_v| neither overflows, 1e160 squared, nor underflows, 1e-160 squared); the
// result is scaled back by 2^(power x exponent) exactly. Homogeneous points are moved with one rounding
// each (w x - w c_x by a fused multiply-add), so the local net is the stored one to rounding of its own
// size, not of its distance from the origin.
struct LocalFrame {
    Vec3 reference;
    int exponent = 0;

    static LocalFrame of(const Box& box);
    Vec3 to_local(const Vec3& world) const;
    Vec4 to_local(const Vec4& homogeneous) const;
    double to_local(double length) const { return std::ldexp(length, -exponent); }
};

// One integral, the sum of integrands over surfaces (in (u, v)) and curves (in u, S_v = 0). The integrands
// see the pieces in the problem's LocalFrame (frame()): a caller's points and lengths go through its to_local.
class Cubature {
public:
    using Integrand = std::function<double(const SurfaceFirstDerivatives&)>;

    // An integral of something that scales as size^power (2: an area, 3: a volume) over a part that lies in
    // `box`, computed in the box's LocalFrame to about 1e-14 size^power (size: the box diagonal). `quick`
    // takes a fixed low-order rule instead of the adaptive one: enough for a sign (the orientation check of
    // a new Solid).
    Cubature(const Box& box, int power, bool quick = false);
    const LocalFrame& frame() const;
    Cubature(Cubature&&) noexcept;
    Cubature& operator=(Cubature&&) noexcept;
    ~Cubature();

    // The integrand over every Bézier patch of `surface` (A5.7). `polynomial_factor` k > 0 says that on a
    // non-rational surface the integrand is a polynomial of degree k·p - 1 along a direction of degree p
    // (3 for the volume flux (S - c) · (S_u x S_v)); 0 that it is not.
    void add_surface(const NurbsSurface& surface, Integrand integrand, int polynomial_factor);
    // |S_u x S_v| over `surface`.
    void add_surface_area(const NurbsSurface& surface);
    // `factor` times Green's area integral (1/2) ∮ (x dy - y dx) along `curve`, x = (C - origin)·x_axis,
    // y = (C - origin)·y_axis, in the curve's own direction (the frame is copied).
    void add_green(const NurbsCurve& curve, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis, double factor);

    // One closed boundary curve of a trimmed region in a surface's (u, v): a 2D curve (z = 0), run forward
    // (sign 1) or backward (sign -1).
    struct TrimmingCurve {
        const NurbsCurve* pcurve;
        double sign;
    };
    // The integrand over the region of `surface`'s (u, v) that the trimming curves bound (counterclockwise
    // outside, clockwise around holes), by Green's theorem: the double integral of g over the region is the
    // line integral of G dv along its boundary, G(u, v) = the integral of g(s, v) ds from the domain's u_min
    // to u (or, along v, minus that of H du with H the integral in v, whichever direction has fewer spans).
    // The inner integral is Gauss–Legendre on every knot span of the surface it crosses; the outer one runs
    // through the engine's adaptive cells on the curves' Bézier segments. The curves must stay inside the
    // surface's domain (Face::trimmed validates it); the caller keeps them alive until integrate().
    void add_trimmed_surface(const NurbsSurface& surface, const std::vector<TrimmingCurve>& boundary, Integrand integrand);

    // The integral, in world units (scaled back from the frame's). Throws Error naming `argument` when the
    // accuracy cannot be reached within the cell budget; `progress` (may be null or empty) is polled with 0 every few thousand cells, so that it can
    // cancel (progress.hpp). Consumes the problem.
    double integrate(std::string_view argument, const Progress* progress = nullptr);

    struct Problem;  // the pieces and integrands: cubature.cpp's alone

private:
    std::unique_ptr<Problem> problem_;
};

// The area of an untrimmed surface, to about 1e-14 of its control box's diagonal squared; errors as above.
double surface_area(const NurbsSurface& surface, std::string_view argument);

// (1/2) ∮ (x dy - y dx) of a curve in a plane frame (x = (C - origin)·x_axis, y = (C - origin)·y_axis):
// the signed area contribution of one loop piece (Green's theorem), to within `absolute_tolerance`.
// By the adaptive engine (weight certificate, then refinement), so extreme rational weights cannot hide
// part of the curve from the rule. Throws Error naming `argument` if a hostile curve exhausts the cell budget.
double green_area(const NurbsCurve& curve, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis,
                  double absolute_tolerance, std::string_view argument);

}  // namespace ratbez::detail

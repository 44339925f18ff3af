#pragma once
// Adaptive, watertight tessellation of exact solids to an absolute chordal tolerance (004 §1.3 meshes).
// Every shared edge is sampled once and both faces use those samples, so the mesh is closed by
// construction; degenerate edges (poles, apexes) become fans; planar faces are triangulated from
// their boundary loops.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "ratbez/brep.hpp"
#include "ratbez/error.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/progress.hpp"

namespace ratbez {

struct TessellationOptions {
    double tolerance = 0;                 // largest distance from any point of a triangle to the surface, > 0
    std::optional<double> angle_deg;      // optional, in (0, 180): the exact surface normals at the two ends
                                          // of any mesh edge inside a curved face differ by at most this
    std::size_t max_triangles = 20'000'000;  // budget: a finer request throws TooFine
    Progress progress;                    // optional: called with the fraction done as faces are planned and
                                          // meshed; may throw to cancel (progress.hpp)
};

// A tolerance that needs more than max_triangles: an Error naming "tolerance", with the estimated count
// (from a coarser tessellation that fits, scaled by the tolerance ratio: curved faces need triangles in
// proportion to 1 / tolerance) and, where known, a tolerance whose mesh fits, so that callers can word the
// message after their own options (reworded). Thrown from the plan, before the mesh is built, and only
// when the plan's count is one the mesh cannot fall below: a mesh within max_triangles is never refused.
// Defined here whole: the planner throws it, the driver refines its estimate and callers catch it.
class TooFine : public Error {
public:
    // `fitting_tolerance`: a tolerance that fits (0: not known); `budget`: the words for the limit (default
    // "max_triangles = N"); `tolerance_words`: how the fitting tolerance is introduced ("a tolerance of").
    TooFine(double estimated_triangles, std::size_t max_triangles, double fitting_tolerance = 0, std::string budget = {},
            std::string tolerance_words = "a tolerance of")
        : Error("tolerance", message(estimated_triangles, max_triangles, fitting_tolerance, budget, tolerance_words)),
          estimated_(estimated_triangles),
          max_triangles_(max_triangles),
          fitting_tolerance_(fitting_tolerance),
          budget_(budget.empty() ? "max_triangles = " + std::to_string(max_triangles) : std::move(budget)) {}
    double estimated_triangles() const noexcept { return estimated_; }
    std::size_t max_triangles() const noexcept { return max_triangles_; }
    double fitting_tolerance() const noexcept { return fitting_tolerance_; }
    const std::string& budget() const noexcept { return budget_; }
    // The same refusal with the limit and the tolerance named as the caller knows them ("--max-triangles
    // 1000", "--tolerance").
    TooFine reworded(std::string budget, std::string tolerance_words) const {
        return TooFine(estimated_, max_triangles_, fitting_tolerance_, std::move(budget), std::move(tolerance_words));
    }

    // Rounded up to two significant digits: an estimate, not a count (and a tolerance on the safe side).
    static double two_digits_up(double value) {
        if (!(value > 0) || !std::isfinite(value)) return value;
        const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1);
        return std::ceil(value / unit * (1 - 1e-12)) * unit;
    }

private:
    static std::string about(double count) {
        const double rounded = count < 100 ? std::ceil(count) : two_digits_up(count);
        if (rounded < 1e15) return std::to_string(static_cast<long long>(rounded));
        char text[32];  // "1.2e+25", not a wall of digits (nor 9e18 for everything past it)
        std::snprintf(text, sizeof text, "%.2g", rounded);
        return text;
    }
    static std::string message(double estimated, std::size_t max_triangles, double fitting_tolerance,
                               const std::string& budget, const std::string& tolerance_words) {
        std::string text = "too fine: the mesh would need about " + about(estimated) + " triangles, more than " +
                           (budget.empty() ? "max_triangles = " + std::to_string(max_triangles) : budget) + " allows";
        if (fitting_tolerance > 0 && std::isfinite(fitting_tolerance)) {
            char number[32];
            std::snprintf(number, sizeof number, "%.2g", two_digits_up(fitting_tolerance));
            text += "; " + tolerance_words + " " + number + " or coarser fits";
        }
        return text;
    }

    double estimated_;
    std::size_t max_triangles_;
    double fitting_tolerance_;
    std::string budget_;
};

Mesh tessellate(const Solid& solid, const TessellationOptions& options);
// An open mesh of one face on its own, with the same tolerance and angle semantics: the face's boundary
// edges are sampled as in a solid (a face of a solid meets its neighbours' meshes along them), sides
// that the face itself shares (a seam) are closed. Triangles follow the face's outward normal.
Mesh tessellate(const Face& face, const TessellationOptions& options);
// A bare surface as the face Face::from_surface(surface) makes of it.
Mesh tessellate(const NurbsSurface& surface, const TessellationOptions& options);
// The tolerance used when the caller gives none: 1e-3 of the solid's bounding-box diagonal, or the largest
// tolerance a face of it was read with (Face::tolerance) if that is more: no mesh follows that face closer.
double default_tolerance(const Solid& solid);
inline Mesh tessellate(const Solid& solid, double tolerance, std::optional<double> angle_deg = std::nullopt) {
    TessellationOptions options;
    options.tolerance = tolerance;
    options.angle_deg = angle_deg;
    return tessellate(solid, options);
}

}  // namespace ratbez

// Skinning (The NURBS Book §10.3) and lofted solids; see loft.hpp.
#include "ratbez/loft.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/interpolation.hpp"
#include "math/numeric_internal.hpp"
#include "modelling/embedding_check.hpp"
#include "modelling/planar_profile.hpp"
#include "modelling/section_alignment.hpp"
#include "modelling/tube_shell.hpp"
#include "ratbez/compatible_curves.hpp"
#include "ratbez/error.hpp"
#include "ratbez/join.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {

namespace {

using detail::to_size;

// Averaged chord-length parameters across the sections (Eq. 9.5 per column, averaged as Eq. 10.8). Columns
// whose points do not move (a point shared by every section) carry no information and are left out.
std::vector<double> section_parameters(const std::vector<NurbsCurve>& sections, const std::string& argument) {
    const std::size_t count = sections.size(), columns = sections.front().homogeneous_points().size();
    std::vector<double> v(count, 0.0);
    std::vector<double> chord(count);
    std::vector<double> largest_step(count, 0.0);
    int used = 0;
    double size = 0;
    for (const NurbsCurve& c : sections) size = std::max(size, c.control_box().diagonal());
    for (std::size_t i = 0; i < columns; ++i) {
        double total = 0;
        chord[0] = 0;
        for (std::size_t k = 1; k < count; ++k) {
            const double step = distance(project(sections[k].homogeneous_points()[i]),
                                         project(sections[k - 1].homogeneous_points()[i]));
            largest_step[k] = std::max(largest_step[k], step);
            total += step;
            chord[k] = total;
        }
        if (total <= 0) continue;
        ++used;
        for (std::size_t k = 1; k < count; ++k) v[k] += chord[k] / total;
    }
    for (std::size_t k = 1; k < count; ++k)
        require(largest_step[k] > 1e-12 * size, argument, [&] {
            return "section " + std::to_string(k) + " coincides with section " + std::to_string(k - 1) +
                   " (a loft needs distinct consecutive sections)";
        });
    for (std::size_t k = 1; k + 1 < count; ++k) v[k] /= used;
    v.back() = 1.0;
    // Averaging keeps the v_k increasing (each column's are non-decreasing and one moves at every step);
    // make sure rounding did not merge two.
    for (std::size_t k = 1; k < count; ++k)
        require(v[k] > v[k - 1], argument, [&] {
            return "sections " + std::to_string(k - 1) + " and " + std::to_string(k) + " are too close to loft between";
        });
    return v;
}

Vec3 control_centre(const Profile& profile) {
    Vec3 sum{};
    double count = 0;
    for (const NurbsCurve& piece : profile.pieces())
        for (const Vec4& pw : piece.homogeneous_points()) {
            sum += project(pw);
            count += 1;
        }
    return sum / count;
}

// Before the sections are made compatible (each refined to the union of all their knots): the net that gives,
// sections x (union of the interior knots on [0, 1] + degree + 1), within limits::max_surface_points, so that
// sections with many different knots are refused by their count instead of after the refinement.
void require_compatible_net(const std::vector<NurbsCurve>& curves, const std::string& argument) {
    int degree = 0;
    for (const NurbsCurve& c : curves) degree = std::max(degree, c.degree());
    std::vector<double> knots;
    for (const NurbsCurve& c : curves) {
        const Interval d = c.domain();
        for (const double u : c.knots())
            if (u > d.min && u < d.max) knots.push_back((u - d.min) / d.width());
    }
    std::sort(knots.begin(), knots.end());
    // Distinct values, each at most `degree` times (a knot's multiplicity never exceeds the degree inside).
    std::size_t columns = static_cast<std::size_t>(degree) + 1, run = 0;
    for (std::size_t k = 0; k < knots.size(); ++k) {
        run = k > 0 && knots[k] - knots[k - 1] <= 1e-12 ? run + 1 : 1;
        if (run <= static_cast<std::size_t>(degree)) ++columns;
    }
    limits::require_surface_points(curves.size(), columns, argument);
}

// The surface cut along u at knots of multiplicity >= p (creases, where its control rows meet): the pieces
// side by side, each with the rows between its ends and the knots between them (no change to the surface).
std::vector<NurbsSurface> split_along_u(const NurbsSurface& surface, const std::vector<double>& at) {
    const int p = surface.degree_u();
    const std::vector<double>& knots = surface.knots_u();
    const Interval d = surface.domain_u();
    std::vector<std::pair<double, int>> cuts{{d.min, 0}};  // (knot, the control row at it)
    for (const double c : at) {
        const auto first = std::lower_bound(knots.begin(), knots.end(), c);
        const auto count = std::count(knots.begin(), knots.end(), c);
        if (c <= d.min || c >= d.max || count < p) continue;
        cuts.emplace_back(c, static_cast<int>(first - knots.begin()) - 1);
    }
    cuts.emplace_back(d.max, surface.rows() - 1);
    if (cuts.size() == 2) return {surface};
    std::vector<NurbsSurface> pieces;
    const std::vector<Vec4>& pw = surface.homogeneous_points();
    const auto columns = static_cast<std::size_t>(surface.columns());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const auto [a, row_a] = cuts[k];
        const auto [b, row_b] = cuts[k + 1];
        std::vector<double> piece_knots(to_size(p + 1), a);
        for (const double u : knots)
            if (u > a && u < b) piece_knots.push_back(u);
        piece_knots.insert(piece_knots.end(), to_size(p + 1), b);
        std::vector<Vec4> net(pw.begin() + static_cast<std::ptrdiff_t>(to_size(row_a) * columns),
                              pw.begin() + static_cast<std::ptrdiff_t>(to_size(row_b + 1) * columns));
        pieces.push_back(NurbsSurface::from_homogeneous(p, surface.degree_v(), std::move(piece_knots), surface.knots_v(),
                                                        std::move(net), surface.is_rational()));
    }
    return pieces;
}

}  // namespace

Skin skin(const std::vector<NurbsCurve>& curves, int degree, bool align) {
    require(curves.size() >= 2, "curves", [&] { return "a loft needs at least 2 sections, got " + std::to_string(curves.size()); });
    limits::require_loft_sections(curves.size(), "curves");
    require(degree >= 1, "degree", [&] { return "must be >= 1, got " + std::to_string(degree); });
    require_compatible_net(curves, "curves");
    std::vector<NurbsCurve> sections = make_compatible(align ? detail::align_sections(curves, "curves").curves : curves, "curves");
    // Each section's weights scaled so that its first is 1: the loft then does not depend on the
    // arbitrary common factor of a curve's weights.
    bool rational = false;
    for (NurbsCurve& c : sections) {
        rational = rational || c.is_rational();
        if (!c.is_rational()) continue;
        std::vector<Vec4> pw = c.homogeneous_points();
        const double scale = 1.0 / pw.front().w;
        for (Vec4& q : pw) q *= scale;
        c = NurbsCurve::from_homogeneous(c.degree(), c.knots(), std::move(pw), true);
    }
    const std::vector<double> v = section_parameters(sections, "curves");
    const int q = std::min(degree, static_cast<int>(sections.size()) - 1);
    const std::vector<double> knots_v = detail::averaged_knots(v, q);

    const std::size_t rows = sections.front().homogeneous_points().size(), columns = sections.size();
    std::vector<Vec4> net(rows * columns);
    std::vector<Vec4> column(columns);
    for (std::size_t i = 0; i < rows; ++i) {
        for (std::size_t k = 0; k < columns; ++k) column[k] = sections[k].homogeneous_points()[i];
        const std::vector<Vec4> solved = detail::interpolate(q, knots_v, v, column);
        for (std::size_t j = 0; j < columns; ++j) {
            Vec4 point = solved[j];
            if (!rational) point.w = 1.0;  // interpolating weights 1 gives 1 up to rounding
            require(point.w > 0 && std::isfinite(point.w), "curves", [&] {
                return "the sections' weights differ too much between neighbours: interpolating them gives the weight " +
                       detail::number(point.w) + " (weights must stay > 0); use sections with similar weights or a lower degree across (1 always works)";
            });
            net[i * columns + j] = point;
        }
    }
    NurbsSurface surface = NurbsSurface::from_homogeneous(sections.front().degree(), q, sections.front().knots(),
                                                          knots_v, std::move(net), rational);
    // Never a surface that meets itself (twisted or crossing sections): certified (self_intersection.hpp).
    const double size = surface.control_box().diagonal();
    const bool closed = std::all_of(sections.begin(), sections.end(), [&](const NurbsCurve& c) {
        return distance(c.start_point(), c.end_point()) <= 1e-9 * size;
    });
    detail::require_embedded(
        {{surface}, closed, false}, "curves", "lofted surface",
        [&](const detail::SelfIntersection& at) {
            const std::size_t k = static_cast<std::size_t>(std::upper_bound(v.begin(), v.end(), at.v) - v.begin());
            const std::size_t after = std::clamp<std::size_t>(k, 1, v.size() - 1);
            return " (between sections " + std::to_string(after - 1) + " and " + std::to_string(after) + ")";
        },
        align ? "sections that twist or cross give no valid surface"
              : "sections that twist or cross give no valid surface; align=True matches them by arc length from the start "
                "points of least twist");
    return Skin{std::move(surface), v};
}

Solid loft(const std::vector<Profile>& profiles, int degree, bool ruled, bool align) {
    const std::size_t count = profiles.size();
    require(count >= 2, "profiles", [&] { return "a loft needs at least 2 profiles, got " + std::to_string(count); });
    limits::require_loft_sections(count, "profiles");  // before every profile is analysed
    require(degree >= 1, "degree", [&] { return "must be >= 1, got " + std::to_string(degree); });
    auto name = [](std::size_t k) { return "profiles[" + std::to_string(k) + "]"; };

    std::vector<detail::PlanarProfile> planes;
    std::vector<Vec3> centres;
    for (std::size_t k = 0; k < count; ++k) {
        planes.push_back(detail::analyse_planar_profile(profiles[k], name(k)));
        centres.push_back(control_centre(profiles[k]));
    }
    // Orient every profile counterclockwise about the direction the loft travels through it.
    std::vector<Profile> oriented;
    std::vector<Vec3> normals;
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3 travel = k + 1 < count ? centres[k + 1] - centres[k] : centres[k] - centres[k - 1];
        const double along = dot(planes[k].normal, travel);
        const bool forward = along > 0;
        oriented.push_back(forward ? profiles[k] : profiles[k].reversed());
        normals.push_back(forward ? planes[k].normal : -planes[k].normal);
    }
    // Consecutive sections strictly separated by each other's planes, so they cannot cut through each other.
    for (std::size_t k = 0; k + 1 < count; ++k) {
        const double tol = std::max(profiles[k].tolerance(), profiles[k + 1].tolerance());
        for (const NurbsCurve& piece : oriented[k + 1].pieces())
            for (const Vec4& pw : piece.homogeneous_points())
                require(dot(project(pw) - planes[k].reference, normals[k]) > tol, name(k + 1), [&] {
                    return "must lie entirely in front of the plane of " + name(k) +
                           " (the side the loft travels to); sections that cross each other's planes give no solid";
                });
        for (const NurbsCurve& piece : oriented[k].pieces())
            for (const Vec4& pw : piece.homogeneous_points())
                require(dot(project(pw) - planes[k + 1].reference, normals[k + 1]) < -tol, name(k), [&] {
                    return "must lie entirely behind the plane of " + name(k + 1) +
                           "; sections that cross each other's planes give no solid";
                });
    }
    std::vector<NurbsCurve> sections;
    for (const Profile& p : oriented) sections.push_back(join(p.pieces()));
    if (align) {
        // Oriented by the travel above; matched by arc length from the starts of least twist. When every
        // profile has a corner at matching places, the seam goes to the first such crease, so that the side
        // faces below are exactly the smooth runs.
        sections = detail::align_sections(sections, "profiles", true).curves;
        const std::vector<double> creases = detail::full_creases(sections, true);
        if (!creases.empty() && creases.front() > 0) sections = detail::restarted_at(sections, creases.front());
    }
    const Skin lofted = [&] {
        try {
            return skin(sections, ruled ? 1 : degree, false);
        } catch (const Error& e) {
            // skin() names its sections "curves"; here they are the profiles.
            throw e.renamed("curves", "profiles");
        }
    }();
    // One side face per smooth run: cut along the creases every section has (after make_compatible, the
    // sections' common knots are the surface's u knots).
    std::vector<NurbsCurve> compatible;
    for (const double v : lofted.section_parameters) compatible.push_back(lofted.surface.isocurve_v(v));
    const std::vector<NurbsSurface> sides = split_along_u(lofted.surface, detail::full_creases(compatible, true));
    return detail::tube_solid({sides}, detail::CapNormals{-normals.front(), normals.back()});
}

}  // namespace ratbez

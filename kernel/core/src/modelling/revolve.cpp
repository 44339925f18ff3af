// Surfaces and solids of revolution (004 §1.5 rotational sweeps; Ex1.15's cylindrical patch and the
// sphere are special cases). The surface is the NURBS book's A8.1 construction: every profile control
// point Q_j is carried around the axis as the control polygon of the arc of A7.1 (see
// detail::arc_layout), and the weights multiply, w_ij = a_i w_j. Because the arc is exact (000 §1.4,
// Ex1.13) and the rotation of a point depends linearly on it, every isocurve v = const is an exact
// circular arc and every isocurve u = const is the profile rotated by the exact angle: the surface is
// exact for any rational profile.
#include "ratbez/revolve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "analysis/cubature.hpp"
#include "brep/brep_build.hpp"
#include "brep/consistency.hpp"
#include "geometry/arcs.hpp"
#include "geometry/clamping.hpp"
#include "geometry/subdivision.hpp"
#include "math/degrees.hpp"
#include "math/numeric_internal.hpp"
#include "math/solid_scale.hpp"
#include "modelling/profile_crossings.hpp"
#include "modelling/revolve_internal.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez {

namespace {

void validate_angle(double angle_deg) {
    require_finite(angle_deg, "angle_deg");
    require(angle_deg > 0 && angle_deg <= 360, "angle_deg", "must be in (0, 360] degrees");
}

// The rule for "the profile stays off the axis", on one Bézier segment of a profile piece, in terms of
// the signed radial coordinate s (distance from the axis within the profile's half-plane, negative on
// the far side) of its control points and their positive weights. The convex hull property certifies
// it: s(t) = Σ B_i w_i s_i / Σ B_i w_i, so if every control value is >= 0 (values within tol count as
// 0), at least one is > 0, and every end that is not allowed on the axis is > 0, then s > 0 on the open
// segment and at its disallowed ends. Where the hull cannot decide, the segment is halved (deCasteljau
// on (w s, w)) up to `depth` times; false if even then it cannot: the curve passes within the tolerance
// of the axis.
bool certified_off_axis(const std::vector<double>& ws, const std::vector<double>& w, bool allow_start,
                        bool allow_end, double tol, int depth) {
    const std::size_t n = ws.size();
    bool nonnegative = true, any_positive = false;
    std::vector<double> z(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double s = ws[i] / w[i];
        z[i] = std::abs(s) <= tol ? 0.0 : s;
        nonnegative = nonnegative && z[i] >= 0;
        any_positive = any_positive || z[i] > 0;
    }
    const bool ends_ok = (allow_start || z.front() > 0) && (allow_end || z.back() > 0);
    if (nonnegative && any_positive && ends_ok) return true;
    if (depth == 0) return false;
    // Halve the homogeneous function (w s, w) at 1/2.
    const auto [lws, rws] = detail::halve_bezier(ws);
    const auto [lw, rw] = detail::halve_bezier(w);
    return certified_off_axis(lws, lw, allow_start, false, tol, depth - 1) &&
           certified_off_axis(rws, rw, false, allow_end, tol, depth - 1);
}

// Certifies the segment first (cheap: one hull test for a segment well off the axis, so a profile of
// 10^5 segments costs 10^5 tests); only a segment that fails is sampled densely (64 points) to say
// which way it fails: a sample with s < -tol crosses the axis, otherwise it touches it.
void check_segment_off_axis(const BezierCurve& segment, const Vec3& axis_point, const Vec3& radial, bool allow_start,
                            bool allow_end, double tol, int piece) {
    std::vector<double> ws, w;
    for (const Vec4& p : segment.homogeneous_points()) {
        ws.push_back(p.w * dot(project(p) - axis_point, radial));
        w.push_back(p.w);
    }
    if (certified_off_axis(ws, w, allow_start, allow_end, tol, 20)) return;
    const std::string where = "piece " + std::to_string(piece);
    constexpr int samples = 64;
    for (int k = 0; k <= samples; ++k) {
        const double s = dot(segment.point(static_cast<double>(k) / samples) - axis_point, radial);
        if (s < -tol) fail("profile", where + " crosses the axis (it reaches the other side of it)");
    }
    fail("profile", where + " touches the axis (comes within the tolerance of it) away from the profile's ends");
}

// The largest coordinate magnitude of the solid: the profile's control box, widened by the circle of the
// farthest point about the axis (a box of the axis point +- radius bounds every circle).
double reach_of_revolution(const Profile& profile, const Vec3& axis_point, double radius) {
    Box box;
    for (const NurbsCurve& piece : profile.pieces()) box.add(piece.control_box());
    const Vec3 r{radius, radius, radius};
    box.add(axis_point - r);
    box.add(axis_point + r);
    return detail::reach_of(box);
}

// A partial turn must move the profile's farthest point (at `radius` from the axis) by a visible amount:
// at least kMinRelativeThickness of the profile's size. Below it the two end faces lie on each other (an
// angle of 1e-12 degrees gave a valid-looking solid of zero thickness and a STEP file of it).
constexpr double kMinRelativeThickness = 1e-6;

void require_thickness(double angle_deg, double radius, double size) {
    const double thickness = angle_deg * std::numbers::pi / 180.0 * radius;
    require(thickness >= kMinRelativeThickness * size, "angle_deg", [&] {
        return "a turn of " + detail::number(angle_deg) + " degrees moves the profile by at most " +
               detail::number(thickness) + ", less than " + detail::number(kMinRelativeThickness) +
               " of its size: the solid would have no thickness";
    });
}

// The radial direction e is that of the farthest control point, so when the profile crosses the axis
// the piece found on the far side of e may be an innocent one lying wholly on the other side. The piece
// to blame is the one with points on both sides: sampled, it reaches beyond tol either way.
void blame_the_crossing_piece(const Profile& profile, const Vec3& axis_point, const Vec3& radial, double tol) {
    constexpr int samples = 64;
    for (std::size_t k = 0; k < profile.pieces().size(); ++k) {
        double low = 0, high = 0;
        for (const BezierCurve& segment : profile.pieces()[k].bezier_segments())
            for (int i = 0; i <= samples; ++i) {
                const double s = dot(segment.point(static_cast<double>(i) / samples) - axis_point, radial);
                low = std::min(low, s);
                high = std::max(high, s);
            }
        if (low < -tol && high > tol)
            fail("profile", "piece " + std::to_string(k) + " crosses the axis (it reaches the other side of it)");
    }
}

// A closed profile with exactly one piece lying on the axis (OpenSCAD's rotate_extrude habit: a polygon
// with a side on the axis) stands for the open profile of its other pieces, which starts and ends there.
std::optional<Profile> without_side_on_axis(const Profile& profile, const Vec3& axis_point, const Vec3& d) {
    const std::vector<NurbsCurve>& pieces = profile.pieces();
    const double tol = profile.tolerance();
    const auto on_axis = [&](const NurbsCurve& piece) {
        for (const Vec4& pw : piece.homogeneous_points()) {
            const Vec3 r = project(pw) - axis_point;
            if (norm(r - d * dot(r, d)) > tol) return false;
        }
        return true;  // the convex hull lies within tol of the axis line: the piece is on it, straight
    };
    std::optional<std::size_t> side;
    for (std::size_t k = 0; k < pieces.size(); ++k)
        if (on_axis(pieces[k])) {
            if (side) return std::nullopt;  // two: the other pieces would not be one profile
            side = k;
        }
    if (!side || pieces.size() < 2) return std::nullopt;
    std::vector<NurbsCurve> open;
    for (std::size_t i = 1; i < pieces.size(); ++i) open.push_back(pieces[(*side + i) % pieces.size()]);
    return Profile(std::move(open));
}

}  // namespace

NurbsSurface revolve_surface(const NurbsCurve& profile, const Vec3& axis_point, const Vec3& axis_dir,
                             double angle_deg) {
    require(is_finite(axis_point), "axis_point", "must have finite coordinates");
    const Vec3 d = frame_from_axis(axis_point, axis_dir, "axis_dir").z_axis;
    validate_angle(angle_deg);

    const detail::ArcLayout arc = detail::arc_layout(0.0, angle_deg);
    const std::vector<Vec4>& profile_points = profile.homogeneous_points();
    const double size = profile.control_box().diagonal();
    Box extent = profile.control_box();
    extent.add(axis_point);
    const double far_rounding = detail::coordinate_rounding(detail::reach_of(extent));
    const std::size_t rows = arc.weights.size(), columns = profile_points.size();
    std::vector<Vec4> net(rows * columns);
    for (std::size_t j = 0; j < columns; ++j) {
        const Vec3 q = project(profile_points[j]);
        const double weight = profile_points[j].w;
        const Vec3 relative = q - axis_point;
        Vec3 foot = axis_point + d * dot(relative, d);  // O_j, the foot of Q_j on the axis
        Vec3 x = q - foot;                              // radial part; y = d x x is x turned by 90°
        // A control point within rounding of the axis is put on it, so that a profile ending on the axis
        // gives an exactly collapsed row (a pole) rather than a circle of radius 1e-17. Rounding of the
        // profile's size, or of coordinates as far out as the point (a sphere r = 0.01 at (100, 0, 0): its
        // pole's control point is 1.4e-14 off the axis, one ulp of 100, which is 1.4e-12 of the radius).
        if (norm(x) <= 1e-13 * std::max(norm(relative), size) + far_rounding) x = {};
        const Vec3 y = cross(d, x);
        for (std::size_t i = 0; i < rows; ++i) {
            const Vec3 p = foot + x * arc.cos_coefficient[i] + y * arc.sin_coefficient[i];
            net[i * columns + j] = homogenize(p, weight * arc.weights[i]);
        }
    }
    return NurbsSurface::from_homogeneous(2, profile.degree(), arc.knots, profile.knots(), std::move(net), true);
}

detail::RevolutionShell detail::build_revolution(const std::vector<NurbsCurve>& pieces, bool closed,
                                                 const Vec3& axis_point, const Vec3& unit_axis, double angle_deg) {
    const std::size_t m = pieces.size();
    const bool full = angle_deg == 360.0;
    std::vector<NurbsSurface> surfaces;
    surfaces.reserve(m);
    for (const NurbsCurve& piece : pieces) surfaces.push_back(revolve_surface(piece, axis_point, unit_axis, angle_deg));

    // Joint j (0..m) is the start of piece j, or the end of the last piece for j = m. Its circle is a
    // column of control points of a surface: the first column of surface j or the last of surface m-1.
    auto joint_surface = [&](std::size_t j) -> const NurbsSurface& { return surfaces[j < m ? j : m - 1]; };
    auto joint_column = [&](std::size_t j) { return j < m ? 0 : surfaces[m - 1].columns() - 1; };
    auto joint_v = [&](std::size_t j) {
        return j < m ? surfaces[j].domain_v().min : surfaces[m - 1].domain_v().max;
    };

    RevolutionShell shell;
    const std::size_t joints = m + 1;
    shell.start_vertices.resize(joints);
    shell.end_vertices.resize(joints);
    shell.joint_edges.resize(joints);
    std::vector<bool> on_axis(joints, false);
    for (std::size_t j = 0; j < joints; ++j) {
        if (closed && j == m) {
            shell.start_vertices[j] = shell.start_vertices[0];
            shell.end_vertices[j] = shell.end_vertices[0];
            shell.joint_edges[j] = shell.joint_edges[0];
            on_axis[j] = on_axis[0];
            continue;
        }
        const NurbsSurface& s = joint_surface(j);
        const int column = joint_column(j);
        const Vec3 first = project(s.homogeneous_point(0, column));
        const Vec3 last = project(s.homogeneous_point(s.rows() - 1, column));
        // revolve_surface puts a control point on the axis exactly (its whole row is the foot point), but
        // H{w P} = (w P) / w may round differently for each arc weight: compare to rounding (of the size and
        // of coordinates as far out, as Face::from_surface judges a collapsed side), not exactly.
        const Box box = s.control_box();
        const double rounding = 1e-13 * box.diagonal() + detail::coordinate_rounding(detail::reach_of(box));
        bool collapsed = true;
        for (int i = 0; i < s.rows(); ++i)
            collapsed = collapsed && distance(project(s.homogeneous_point(i, column)), first) <= rounding;
        on_axis[j] = collapsed;
        shell.start_vertices[j] = make_vertex(first);
        shell.end_vertices[j] = (full || collapsed) ? shell.start_vertices[j] : make_vertex(last);
        shell.joint_edges[j] =
            make_edge(s.isocurve_v(joint_v(j)), shell.start_vertices[j], shell.end_vertices[j], collapsed);
    }
    for (std::size_t k = 0; k < m; ++k) {
        const NurbsSurface& s = surfaces[k];
        shell.start_profile_edges.push_back(
            make_edge(s.isocurve_u(s.domain_u().min), shell.start_vertices[k], shell.start_vertices[k + 1]));
        shell.end_profile_edges.push_back(
            full ? shell.start_profile_edges.back()
                 : make_edge(s.isocurve_u(s.domain_u().max), shell.end_vertices[k], shell.end_vertices[k + 1]));
    }
    // Face k: v_min = the joint circle at its start (with u), u_max = the profile at the end angle (with v),
    // v_max = the joint circle at its end (against u), u_min = the profile at angle 0 (against v).
    for (std::size_t k = 0; k < m; ++k)
        shell.faces.push_back(Face::from_surface(
            surfaces[k], {Coedge{shell.joint_edges[k], false}, Coedge{shell.end_profile_edges[k], false},
                          Coedge{shell.joint_edges[k + 1], true}, Coedge{shell.start_profile_edges[k], true}}));
    return shell;
}

namespace {

// The usual mistake behind a profile off the axis's plane: a 2D profile (drawn in z = 0) revolved about
// the default z axis, so the profile lies across the axis instead of along it. Empty unless the whole
// profile lies in one plane perpendicular to the unit axis d.
std::string perpendicular_hint(const Profile& profile, const Vec3& axis_point, const Vec3& d) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const NurbsCurve& piece : profile.pieces())
        for (const Vec4& pw : piece.homogeneous_points()) {
            const double height = dot(project(pw) - axis_point, d);
            low = std::min(low, height);
            high = std::max(high, height);
        }
    if (high - low > profile.tolerance()) return "";
    // Along a coordinate axis, name the plane and an axis lying in it.
    const std::array<std::pair<Vec3, const char*>, 3> axes{
        {{{1, 0, 0}, "x"}, {{0, 1, 0}, "y"}, {{0, 0, 1}, "z"}}};
    for (std::size_t k = 0; k < 3; ++k)
        if (std::abs(std::abs(dot(d, axes[k].first)) - 1) <= 1e-12) {
            const Vec3 in_plane = axes[(k + 2) % 3].first;  // z -> y: a 2D sketch's x is the radius, y the height
            const Vec3 point = project(profile.pieces().front().homogeneous_points().front());
            const double level = k == 0 ? point.x : k == 1 ? point.y : point.z;
            std::ostringstream text;
            text << "; it lies in the " << axes[k].second << " = " << level
                 << " plane, perpendicular to the axis: revolve about an axis in its plane, such as axis_dir=("
                 << in_plane.x << ", " << in_plane.y << ", " << in_plane.z << ")";
            return text.str();
        }
    return "; it lies in a plane perpendicular to the axis: revolve about an axis in its plane";
}

}  // namespace

Solid revolve(const Profile& profile, const Vec3& axis_point, const Vec3& axis_dir, double angle_deg) {
    require(is_finite(axis_point), "axis_point", "must have finite coordinates");
    const Vec3 d = frame_from_axis(axis_point, axis_dir, "axis_dir").z_axis;
    validate_angle(angle_deg);
    if (profile.is_closed())
        if (const auto open = without_side_on_axis(profile, axis_point, d)) return revolve(*open, axis_point, axis_dir, angle_deg);
    const double tol = profile.tolerance();
    const bool closed = profile.is_closed();
    const std::size_t m = profile.pieces().size();

    // The meridian half-plane: spanned by the axis and the radial direction e of the control point
    // farthest from the axis. By the convex hull property the profile lies in that plane when all
    // its control points do.
    Vec3 farthest{};
    for (const NurbsCurve& piece : profile.pieces())
        for (const Vec4& pw : piece.homogeneous_points()) {
            const Vec3 r = project(pw) - axis_point;
            const Vec3 radial = r - d * dot(r, d);
            if (norm(radial) > norm(farthest)) farthest = radial;
        }
    require(norm(farthest) > tol, "profile", "lies on the axis");
    detail::require_solid_scale(profile.size(), reach_of_revolution(profile, axis_point, norm(farthest)), "profile",
                                "profile", detail::largest_box_diagonal);
    require_thickness(angle_deg, norm(farthest), profile.size());
    const Vec3 e = farthest / norm(farthest);
    const Vec3 plane_normal = cross(d, e);
    for (const NurbsCurve& piece : profile.pieces())
        for (const Vec4& pw : piece.homogeneous_points())
            require(std::abs(dot(project(pw) - axis_point, plane_normal)) <= tol, "profile", [&] {
                return "must lie in a plane containing the axis (a control point is " +
                       std::to_string(std::abs(dot(project(pw) - axis_point, plane_normal))) + " off it)" +
                       perpendicular_hint(profile, axis_point, d);
            });

    if (!closed) {
        const double start_off = std::abs(dot(profile.start_point() - axis_point, e));
        const double end_off = std::abs(dot(profile.end_point() - axis_point, e));
        require(start_off <= tol && end_off <= tol, "profile",
                "an open profile must start and end on the axis (its start is " + std::to_string(start_off) +
                    " and its end " + std::to_string(end_off) + " away from it); otherwise close it");
    }
    for (std::size_t k = 0; k < m; ++k) {
        const std::vector<BezierCurve> segments = profile.pieces()[k].bezier_segments();
        for (std::size_t b = 0; b < segments.size(); ++b) {
            const bool allow_start = !closed && k == 0 && b == 0;
            const bool allow_end = !closed && k + 1 == m && b + 1 == segments.size();
            try {
                check_segment_off_axis(segments[b], axis_point, e, allow_start, allow_end, tol, static_cast<int>(k));
            } catch (const Error&) {
                blame_the_crossing_piece(profile, axis_point, e, tol);
                throw;
            }
        }
    }
    detail::require_no_crossings(profile, axis_point, e, d);

    // Orientation: S_u x S_v points out of the solid when the profile runs counterclockwise in the
    // (radial, axial) coordinates of its half-plane (at angle 0, S_u = |x| d x e and the normal is the
    // profile's tangent turned clockwise). Its signed area there, (1/2) ∮ (ρ dh - h dρ), decides; the
    // closing segment of an open profile lies on the axis (ρ = 0, dρ = 0) and adds nothing.
    double signed_area = 0;
    for (const NurbsCurve& piece : profile.pieces())
        signed_area += detail::green_area(piece, axis_point, e, d, 1e-15 * profile.size() * profile.size(), "profile");
    require(std::abs(signed_area) > 1e-12 * profile.size() * profile.size(), "profile",
            "encloses no area with the axis (nothing to revolve)");
    const Profile oriented = signed_area > 0 ? profile : profile.reversed();

    std::vector<NurbsCurve> pieces = oriented.pieces();
    if (!closed) {
        // Put the ends exactly on the axis (they are within tol of it): the poles become exact points.
        auto foot = [&](const Vec3& p) { return axis_point + d * dot(p - axis_point, d); };
        pieces.front() = detail::with_end_point(pieces.front(), false, foot(pieces.front().start_point()));
        pieces.back() = detail::with_end_point(pieces.back(), true, foot(pieces.back().end_point()));
    }

    detail::RevolutionShell shell = detail::build_revolution(pieces, closed, axis_point, d, angle_deg);
    std::vector<Face> faces = std::move(shell.faces);
    if (angle_deg < 360.0) {
        // Two planar end faces bounded by the profile at angle 0 and at the end angle (plus, for an open
        // profile, the segment of the axis between its ends, shared by both end faces).
        std::vector<Coedge> start_loop, end_loop;
        for (const EdgePtr& edge : shell.start_profile_edges) start_loop.push_back(Coedge{edge, false});
        for (auto it = shell.end_profile_edges.rbegin(); it != shell.end_profile_edges.rend(); ++it)
            end_loop.push_back(Coedge{*it, true});
        if (!closed) {
            const VertexPtr top = shell.start_vertices[m], bottom = shell.start_vertices[0];
            const EdgePtr axis_edge = detail::make_edge(line_segment(top->point, bottom->point), top, bottom);
            start_loop.push_back(Coedge{axis_edge, false});
            end_loop.push_back(Coedge{axis_edge, true});
        }
        // At angle 0 the solid lies on the d x e side, so the outward normal is e x d; the plane frame
        // (e, d) makes the counterclockwise (ρ, h) profile counterclockwise seen from that normal.
        faces.push_back(Face::planar(Plane{axis_point, e, d, cross(e, d)}, {start_loop}));
        const Vec3 e_end = e * detail::cos_deg(angle_deg) + cross(d, e) * detail::sin_deg(angle_deg);
        faces.push_back(Face::planar(Plane{axis_point, d, e_end, cross(d, e_end)}, {end_loop}));
    }
    return Solid(std::move(faces), Construction::Revolution{axis_point, d, angle_deg});
}

}  // namespace ratbez

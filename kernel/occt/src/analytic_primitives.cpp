// Cylinders, cones, spheres and tori as OpenCASCADE's own primitives (see analytic_primitives.hpp).

#include "analytic_primitives.hpp"

#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <gp_Ax3.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pln.hxx>

#include <cmath>

#include "ratbez/bspline_basis.hpp"
#include "ratbez/construction.hpp"
#include "ratbez/occt/geometry.hpp"
#include "smooth_arcs.hpp"
#include "swept_solids.hpp"

namespace ratbez::occt::detail {
namespace {

// Relative to the solid's size: how far a control row may be from the arc, axis or meridian it is taken for
// (find_arc's own fit), and how far the surface may be from the recognised sphere or torus at 81 samples.
constexpr double kFit = 1e-11;
constexpr double kOnSurface = 1e-10;

gp_Ax2 axes(const Vec3& origin, const Vec3& axis) { return gp_Ax2(to_occt_point(origin), to_occt_direction(axis)); }
gp_Ax2 axes(const Vec3& origin, const Vec3& axis, const Vec3& x) {
    return gp_Ax2(to_occt_point(origin), to_occt_direction(axis), to_occt_direction(x));
}

// A surface of revolution OCCT has a surface of its own for: centre (on the axis; a cylinder's and a cone's at
// their first row), axis, the direction its parameter starts from, radii (a cone's at the centre) and a cone's
// semi-angle (its radius grows by tan(semi_angle) per unit along the axis).
struct Round {
    enum class Kind { sphere, torus, cylinder, cone };
    Vec3 centre, axis, x;
    double major = 0, minor = 0, semi_angle = 0;
    Kind kind = Kind::sphere;
};

// The meridian (height along the axis, radius) of a surface's rows as a straight line, not square to the axis:
// a cylinder or a cone. Control points within `tolerance` of the line through the first and last (the curve
// then lies on it: the convex hull).
std::optional<Round> straight_meridian(const std::vector<Vec3>& meridian, const Vec3& base, const Vec3& axis,
                                       const Vec3& x, double tolerance) {
    const Vec3 a = meridian.front(), d = meridian.back() - a;
    const double length = norm(d);
    if (!(std::abs(d.x) > tolerance)) return std::nullopt;  // square to the axis: a plane
    for (const Vec3& p : meridian)
        if (norm(cross(p - a, d)) > tolerance * length) return std::nullopt;
    // Centred at an end of positive radius (OCCT's cone is both nappes, its reference radius not negative).
    const Vec3 centre = a.y >= 0 ? a : meridian.back();
    if (!(centre.y >= 0)) return std::nullopt;
    Round round{base + centre.x * axis, axis, x, centre.y, 0, std::atan(d.y / d.x), Round::Kind::cone};
    if (std::abs(d.y) <= tolerance) round.kind = Round::Kind::cylinder, round.semi_angle = 0;
    return round;
}

// The surface as a revolution about one axis of a meridian arc: a sphere when the arc's centre is on the
// axis, a torus when it is off it; or of a meridian line: a cylinder or a cone.
std::optional<Round> round_surface(const NurbsSurface& surface, double tolerance) {
    for (const bool along_u : {true, false}) {
        const std::optional<ArcDirection> arc = find_arc(surface, along_u, tolerance, true);
        if (!arc || arc->origin.empty()) continue;
        std::size_t widest = 0;
        for (std::size_t j = 0; j < arc->origin.size(); ++j)
            if (norm(arc->u_axis[j]) > norm(arc->u_axis[widest])) widest = j;
        const double r_widest = norm(arc->u_axis[widest]);
        if (!(r_widest > tolerance)) continue;
        const Vec3 x = arc->u_axis[widest] / r_widest;
        Vec3 axis = cross(arc->u_axis[widest], arc->v_axis[widest]);
        axis = axis / norm(axis);
        const Vec3 base = arc->origin[widest];
        // Every row a circle about the axis, starting towards x or, turning the same way, away from it (a row beyond
        // a cone's apex: a drill point's cone in a file runs a little past it): its height along the axis and its
        // signed radius.
        std::vector<Vec3> meridian;
        bool revolution = true;
        for (std::size_t j = 0; j < arc->origin.size() && revolution; ++j) {
            const Vec3 &u = arc->u_axis[j], &v = arc->v_axis[j];
            const double r = norm(u);
            const Vec3 offset = arc->origin[j] - base;
            const double h = dot(offset, axis);
            const bool towards = norm(u - r * x) <= tolerance, away = norm(u + r * x) <= tolerance;
            revolution = std::abs(norm(v) - r) <= tolerance && std::abs(dot(u, v)) <= tolerance * std::max(r, 1.0) &&
                         norm(offset - h * axis) <= tolerance &&
                         (r <= tolerance || ((towards || away) && norm(cross(u, v) / r - r * axis) <= tolerance));
            meridian.push_back({h, towards || r <= tolerance ? r : -r, 0});
        }
        if (!revolution) continue;
        if (const std::optional<Round> straight = straight_meridian(meridian, base, axis, x, tolerance)) return straight;
        const int degree = along_u ? surface.degree_v() : surface.degree_u();
        const std::vector<double>& knots = along_u ? surface.knots_v() : surface.knots_u();
        const std::optional<ArcDirection> bend = find_arc(NurbsCurve(degree, knots, meridian, arc->omega), tolerance, true);
        if (!bend) continue;
        const Vec3 centre = bend->origin.front();
        const double radius = norm(bend->u_axis.front());
        if (std::abs(norm(bend->v_axis.front()) - radius) > tolerance) continue;  // an ellipse
        if (std::abs(centre.y) <= tolerance) return Round{base + centre.x * axis, axis, x, radius, 0, 0, Round::Kind::sphere};
        // Off the axis: a torus, a spindle one too (the meridian circle crosses the axis: a fillet in a file read by
        // OpenCASCADE as its torus of minor radius above the major; distance_from then holds the face to the outer part).
        if (centre.y > tolerance) return Round{base + centre.x * axis, axis, x, centre.y, radius, 0, Round::Kind::torus};
    }
    return std::nullopt;
}

double distance_from(const Round& round, const Vec3& p) {
    const Vec3 d = p - round.centre;
    const double h = dot(d, round.axis), r = norm(d - h * round.axis);
    switch (round.kind) {
        case Round::Kind::sphere: return std::abs(norm(d) - round.major);
        case Round::Kind::torus: return std::abs(std::hypot(h, r - round.major) - round.minor);
        case Round::Kind::cylinder: return std::abs(r - round.major);
        case Round::Kind::cone:  // both nappes: beyond the apex the signed radius is negative
            return std::abs(r - std::abs(round.major + h * std::tan(round.semi_angle))) * std::cos(round.semi_angle);
    }
    return HUGE_VAL;
}

// The sphere, torus, cylinder or cone the surface is, recognised on its control net and checked at 8 points a span
// each way. A surface running several turns round its axis (a face read from a file round a cylinder 15 times:
// elementary_bspline in shape_import.cpp) is recognised on its first patch, which turns less than half a turn.
std::optional<Round> exact_round(const NurbsSurface& surface, double size) {
    const std::vector<double> us = breakpoints(surface.degree_u(), surface.knots_u()), vs = breakpoints(surface.degree_v(), surface.knots_v());
    std::optional<Round> round = round_surface(surface, kFit * size);
    if (!round && surface.is_rational() && us.size() + vs.size() > 4)  // (the many turns are rational arcs)
        round = round_surface(NurbsSurface::from_bezier(surface.bezier_patches().front().front()), kFit * size);
    if (!round) return std::nullopt;
    for (std::size_t a = 0; a + 1 < us.size(); ++a)
        for (int i = 0; i <= 8; ++i)
            for (std::size_t b = 0; b + 1 < vs.size(); ++b)
                for (int j = 0; j <= 8; ++j) {
                    const Vec3 p = surface.point(i == 8 ? us[a + 1] : us[a] + (us[a + 1] - us[a]) * i / 8,
                                                 j == 8 ? vs[b + 1] : vs[b] + (vs[b + 1] - vs[b]) * j / 8);
                    if (distance_from(*round, p) > kOnSurface * size) return std::nullopt;
                }
    return round;
}

// A solid of one face that is a whole sphere or ring torus.
std::optional<Round> one_round_face(const Solid& solid) {
    if (solid.faces().size() != 1 || solid.faces().front().kind() != Face::Kind::surface) return std::nullopt;
    const std::optional<Round> round = exact_round(solid.faces().front().surface(), std::max(1.0, solid.bounding_box().diagonal()));
    if (!round || (round->kind != Round::Kind::sphere && round->kind != Round::Kind::torus)) return std::nullopt;
    if (round->kind == Round::Kind::torus && !(round->major > round->minor)) return std::nullopt;
    return round;
}

std::optional<TopoDS_Solid> made(const Solid& solid) {
    const Construction& record = solid.construction();
    if (const auto* c = record.get<Construction::Cylinder>())
        return BRepPrimAPI_MakeCylinder(axes(c->center, c->axis), c->radius, c->height).Solid();
    if (const auto* c = record.get<Construction::Cone>())
        return BRepPrimAPI_MakeCone(axes(c->center, c->axis), c->radius1, c->radius2, c->height).Solid();
    if (const auto* s = record.get<Construction::Sphere>())
        return BRepPrimAPI_MakeSphere(to_occt_point(s->center), s->radius).Solid();
    if (const auto* t = record.get<Construction::Torus>())
        return BRepPrimAPI_MakeTorus(axes(t->center, t->axis), t->major_radius, t->minor_radius).Solid();
    if (const std::optional<Round> round = one_round_face(solid)) {
        const gp_Ax2 frame = axes(round->centre, round->axis, round->x);
        return round->kind == Round::Kind::sphere ? BRepPrimAPI_MakeSphere(frame, round->major).Solid()
                             : BRepPrimAPI_MakeTorus(frame, round->major, round->minor).Solid();
    }
    return std::nullopt;
}

// Which face of ours an OCCT face of the primitive is: the one surface face for a curved face; for a planar
// one, the planar face of ours whose outward normal it shares.
std::optional<std::size_t> face_of(const Solid& solid, const TopoDS_Face& face) {
    const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(face));
    Vec3 normal{};
    if (!plane.IsNull()) {
        const gp_Dir n = plane->Pln().Axis().Direction();
        normal = face.Orientation() == TopAbs_REVERSED ? Vec3{-n.X(), -n.Y(), -n.Z()} : Vec3{n.X(), n.Y(), n.Z()};
    }
    for (std::size_t i = 0; i < solid.faces().size(); ++i) {
        const Face& ours = solid.faces()[i];
        if (plane.IsNull() ? ours.kind() == Face::Kind::surface
                           : ours.kind() == Face::Kind::planar && dot(ours.plane().normal, normal) > 0.999)
            return i;
    }
    return std::nullopt;
}

// The primitive's faces in the order of ours, by face_of.
std::optional<FacesInOrder> primitive_in_order(const Solid& solid) {
    const std::optional<TopoDS_Solid> primitive = made(solid);
    if (!primitive) return std::nullopt;
    FacesInOrder result{*primitive, std::vector<TopoDS_Face>(solid.faces().size())};
    int faces = 0;
    for (TopExp_Explorer it(*primitive, TopAbs_FACE); it.More(); it.Next(), ++faces) {
        const TopoDS_Face face = TopoDS::Face(it.Current());
        const std::optional<std::size_t> ours = face_of(solid, face);
        if (!ours || !result.faces[*ours].IsNull()) return std::nullopt;
        result.faces[*ours] = face;
    }
    if (faces != static_cast<int>(solid.faces().size())) return std::nullopt;
    return result;
}

// Whether the face of ours lies on the OCCT face (its surface), at 9 x 9 points of its parameter box (a planar
// face: its plane's origin), to kOnSurface of the size: a record that does not describe the faces (a wrong
// claim) must not be handed out.
bool lies_on(const Face& ours, const TopoDS_Face& face, double size) {
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    const auto off = [&](const Vec3& p) {
        GeomAPI_ProjectPointOnSurf foot(to_occt_point(p), surface);
        return foot.NbPoints() > 0 ? foot.LowerDistance() : HUGE_VAL;
    };
    if (ours.kind() == Face::Kind::planar) return off(ours.plane().origin) <= kOnSurface * size;
    const Interval du = ours.surface().domain_u(), dv = ours.surface().domain_v();
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j)
            if (off(ours.surface().point(std::min(du.max, du.min + du.width() * i / 8),
                                         std::min(dv.max, dv.min + dv.width() * j / 8))) > kOnSurface * size)
                return false;
    return true;
}

}  // namespace

std::optional<TopoDS_Solid> analytic_primitive(const Solid& solid) {
    try {
        std::optional<FacesInOrder> occt = primitive_in_order(solid);
        if (!occt) occt = swept_solid(solid);
        if (!occt) return std::nullopt;
        // Each face checked on ours, then the shell assembled in the order of ours (face i is face i of the shape).
        const double size = std::max(1.0, solid.bounding_box().diagonal());
        BRep_Builder builder;
        TopoDS_Shell shell;
        builder.MakeShell(shell);
        for (std::size_t i = 0; i < solid.faces().size(); ++i) {
            if (!lies_on(solid.faces()[i], occt->faces[i], size)) return std::nullopt;
            builder.Add(shell, occt->faces[i]);
        }
        shell.Closed(Standard_True);
        TopoDS_Solid result;
        builder.MakeSolid(result);
        builder.Add(result, shell);
        return result;
    } catch (const Standard_Failure&) {
        return std::nullopt;
    }
}

Handle(Geom_ElementarySurface) exact_elementary(const NurbsSurface& surface, double size) {
    const std::optional<Round> round = exact_round(surface, size);
    if (!round) return {};
    const gp_Ax3 frame(axes(round->centre, round->axis, round->x));
    switch (round->kind) {
        case Round::Kind::sphere: return new Geom_SphericalSurface(frame, round->major);
        case Round::Kind::torus: return new Geom_ToroidalSurface(frame, round->major, round->minor);
        case Round::Kind::cylinder: return new Geom_CylindricalSurface(frame, round->major);
        case Round::Kind::cone: return new Geom_ConicalSurface(frame, round->semi_angle, round->major);
    }
    return {};
}

}  // namespace ratbez::occt::detail

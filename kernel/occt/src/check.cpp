// Checking a solid against OpenCASCADE (check.hpp): BRepCheck validity and closedness of the converted
// B-rep, our evaluation against OCCT's evaluation of the converted geometry, our points against OCCT's
// analytic surface of the solid's construction, and volumes and areas (ours, OCCT's BRepGProp, closed form).

#include "ratbez/occt/check.hpp"

#include <BOPAlgo_ArgumentAnalyzer.hxx>
#include <BOPAlgo_CheckResult.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_Shell.hxx>
#include <BRepGProp.hxx>
#include <BRepGProp_Domain.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp_Sinert.hxx>
#include <BRepGProp_Vinert.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax3.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "handout.hpp"
#include "polled_progress.hpp"
#include "ratbez/error.hpp"
#include "ratbez/occt/geometry.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/properties.hpp"
#include "swept_solids.hpp"

namespace ratbez::occt {
namespace {

// The BOP analysis's memory (bop_analysis; its time is CheckOptions::bop_seconds).
constexpr std::size_t kBopMemoryBytes = std::size_t{4} << 30;
constexpr double kPropertiesEps = 1e-9;  // BRepGProp's default is 4e-4 relative on B-spline faces (SETUP-NOTES)

std::string number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

int count_edges(const TopoDS_Shape& shape) {
    int n = 0;
    for (TopExp_Explorer it(shape, TopAbs_EDGE); it.More(); it.Next()) ++n;
    return n;
}

// Closed: BRepCheck_Shell finds no free edge in any shell, and ShapeAnalysis_FreeBounds finds no free boundary.
bool is_closed(const TopoDS_Solid& solid) {
    for (TopExp_Explorer shells(solid, TopAbs_SHELL); shells.More(); shells.Next())
        if (BRepCheck_Shell(TopoDS::Shell(shells.Current())).Closed() != BRepCheck_NoError) return false;
    ShapeAnalysis_FreeBounds free_bounds(solid);
    return count_edges(free_bounds.GetClosedWires()) == 0 && count_edges(free_bounds.GetOpenWires()) == 0;
}

// Samples t_0 .. t_{n-1} over [a, b], both ends included.
double sample(double a, double b, int i, int n) { return i == n - 1 ? b : a + (b - a) * i / (n - 1); }

// Largest |ours - OCCT D0| over the grid of every face and the samples of every edge.
// `progress` (optional) gets the share of the faces done before each grid row.
double evaluation_deviation(const Solid& solid, const ConvertedSolid& converted, int grid, const Progress& progress) {
    double worst = 0;
    for (std::size_t f = 0; f < solid.faces().size(); ++f) {
        const Face& face = solid.faces()[f];
        const NurbsSurface& surface = face.surface();
        // Each OCCT face of ours (one, or its Bézier patches) on its own part of our parameter rectangle.
        for (std::size_t k = converted.first_face[f]; k < converted.first_face[f + 1]; ++k) {
            const Handle(Geom_Surface) occt_surface = BRep_Tool::Surface(converted.faces[k]);
            const GeomAdaptor_Surface adaptor(occt_surface);
            const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(occt_surface);
            const auto& [u0, u1, v0, v1] = converted.face_domains[k];
            // OCCT's parameter ranges along our u and our v (exchanged on a face rough in u, where OCCT's u runs
            // along our v backwards: topology.hpp).
            const bool exchanged = converted.face_exchanged[k];
            double occt_u0 = u0, occt_u1 = u1, occt_v0 = v0, occt_v1 = v1;
            if (plane.IsNull()) {
                occt_surface->Bounds(occt_u0, occt_u1, occt_v0, occt_v1);
                if (exchanged) std::swap(occt_u0, occt_v0), std::swap(occt_u1, occt_v1);
            }
            // Our parameters of OCCT's sample: the affine map of the domains, or the arc's map (topology.hpp).
            const auto& [to_u, to_v] = converted.face_parameters[k];
            for (int i = 0; i < grid; ++i) {
                if (progress) progress((static_cast<double>(f) + static_cast<double>(i) / grid) / static_cast<double>(solid.faces().size()));
                const double u = to_u ? to_u(sample(occt_u0, occt_u1, i, grid)) : sample(u0, u1, i, grid);
                for (int j = 0; j < grid; ++j) {
                    const Vec3 ours = surface.point(u, to_v ? to_v(sample(occt_v0, occt_v1, j, grid)) : sample(v0, v1, j, grid));
                    if (!plane.IsNull()) {
                        // Our plane patch (or flat patch) against OCCT's plane: the distance from it (the
                        // patch's own (u, v) are not the plane's).
                        worst = std::max(worst, plane->Pln().Distance(to_occt_point(ours)));
                    } else {
                        const double a = sample(occt_u0, occt_u1, i, grid), b = sample(occt_v0, occt_v1, j, grid);
                        const gp_Pnt theirs = exchanged ? adaptor.Value(occt_v0 + occt_v1 - b, a) : adaptor.Value(a, b);
                        worst = std::max(worst, distance(ours, from_occt(theirs)));
                    }
                }
            }
        }
    }
    for (const auto& [edge, pieces] : converted.edges)
        for (const TopoDS_Edge& occt_edge : pieces) {
            double first = 0, last = 0;
            const Handle(Geom_Curve) curve = BRep_Tool::Curve(occt_edge, first, last);
            const GeomAdaptor_Curve adaptor(curve, first, last);
            const auto map = converted.edge_parameters.find(edge);
            const Interval domain = edge->curve.domain();
            for (int i = 0; i < grid; ++i) {
                const double t = sample(first, last, i, grid);
                // Clamped: OCCT's range of an edge read from a file can end a rounding beyond the kernel curve's
                // domain (2020_extrusion_support_x4.step of VoronDesign was refused the check so: -40 against
                // [-40, -31]); a real difference of the ranges shows as a distance.
                const double ours = std::clamp(map == converted.edge_parameters.end() ? t : map->second(t), domain.min, domain.max);
                worst = std::max(worst, distance(edge->curve.point(ours), from_occt(adaptor.Value(t))));
            }
        }
    return worst;
}

// The distance from a point of a face to OCCT's analytic surface of what the solid was built as. Closed
// forms in the surface's own gp_Ax3 for the quadrics and the torus (exact). For a revolution, OCCT's
// Geom_SurfaceOfRevolution of the face's own profile about the recorded axis, evaluated at the point's
// angle about the axis and its profile parameter v (S(u, v) is the profile point C(v) turned about the
// axis, 004 §1.5; u in a mirror image, whose faces have their parameters swapped): the distance to that
// surface point bounds the distance to the surface. No projection search: GeomAPI_ProjectPointOnSurf /
// OnCurve missed the nearest point by up to 1e-2 of the size on profiles with extreme weights. An extrusion
// (and a Solid of kind none) has no analytic surface here.
class AnalyticDistance {
public:
    explicit AnalyticDistance(const Construction& construction) {
        const auto frame = [](const Vec3& center, const Vec3& axis) {
            return gp_Ax3(to_occt_point(center), to_occt_direction(axis));
        };
        if (const auto* c = construction.get<Construction::Cylinder>()) {
            surface_ = new Geom_CylindricalSurface(frame(c->center, c->axis), c->radius);
        } else if (const auto* c = construction.get<Construction::Cone>()) {
            const double semi_angle = std::atan2(c->radius2 - c->radius1, c->height);
            if (c->radius1 == c->radius2)
                surface_ = new Geom_CylindricalSurface(frame(c->center, c->axis), c->radius1);
            else
                surface_ = new Geom_ConicalSurface(frame(c->center, c->axis), semi_angle, c->radius1);
        } else if (const auto* s = construction.get<Construction::Sphere>()) {
            surface_ = new Geom_SphericalSurface(frame(s->center, {0, 0, 1}), s->radius);
        } else if (const auto* t = construction.get<Construction::Torus>()) {
            surface_ = new Geom_ToroidalSurface(frame(t->center, t->axis), t->major_radius, t->minor_radius);
        } else if (const auto* r = construction.get<Construction::Revolution>()) {
            revolution_ = *r;
        }
        if (!surface_.IsNull()) {
            const Handle(Geom_ElementarySurface) elementary = Handle(Geom_ElementarySurface)::DownCast(surface_);
            to_local_.SetTransformation(elementary->Position());  // global -> the surface's frame
        }
    }

    bool exists() const { return !surface_.IsNull() || revolution_.has_value(); }

    // For a revolution: the surface of revolution of the face's own profile (its isocurve at the start of
    // the rotation, converted to OCCT), and the radial direction of the half-plane that profile lies in.
    void set_face(const Face& face) {
        if (!revolution_) return;
        const NurbsSurface& surface = face.surface();
        turns_along_u_ = detail::turns_along_u(surface, revolution_->axis_point, revolution_->axis_dir);
        const NurbsCurve profile = turns_along_u_ ? surface.isocurve_u(surface.domain_u().min)
                                                  : surface.isocurve_v(surface.domain_v().min);
        Vec3 farthest{};  // the control point farthest from the axis: the profile's half-plane, in which they all lie
        for (const Vec4& pw : profile.homogeneous_points()) {
            const Vec3 radial = radial_part(project(pw));
            if (norm(radial) > norm(farthest)) farthest = radial;
        }
        start_radial_ = farthest / norm(farthest);
        surface_ = new Geom_SurfaceOfRevolution(
            to_occt(profile), gp_Ax1(to_occt_point(revolution_->axis_point), to_occt_direction(revolution_->axis_dir)));
    }

    // Distance of the face's point p = S(u, v) to the analytic surface.
    double operator()(const Vec3& p, double u, double v) const {
        if (revolution_) {
            const double along_profile = turns_along_u_ ? v : u;
            // Geom_SurfaceOfRevolution's U is the angle about the axis (right-handed, as revolve turns).
            const Vec3 radial = radial_part(p);
            const Vec3 quarter_turn = cross(revolution_->axis_dir, start_radial_);
            const double angle = std::atan2(dot(radial, quarter_turn), dot(radial, start_radial_));
            return distance(p, from_occt(surface_->Value(angle < 0 ? angle + 2 * std::numbers::pi : angle, along_profile)));
        }
        const gp_Pnt local = to_occt_point(p).Transformed(to_local_);
        const double rho = std::hypot(local.X(), local.Y()), z = local.Z();
        if (const auto cylinder = Handle(Geom_CylindricalSurface)::DownCast(surface_); !cylinder.IsNull())
            return std::abs(rho - cylinder->Radius());
        if (const auto cone = Handle(Geom_ConicalSurface)::DownCast(surface_); !cone.IsNull()) {
            // In the meridian half-plane the cone is the line through (RefRadius, 0) along (sin a, cos a).
            const double a = cone->SemiAngle();
            return std::abs((rho - cone->RefRadius()) * std::cos(a) - z * std::sin(a));
        }
        if (const auto sphere = Handle(Geom_SphericalSurface)::DownCast(surface_); !sphere.IsNull())
            return std::abs(std::hypot(rho, z) - sphere->Radius());
        const auto torus = Handle(Geom_ToroidalSurface)::DownCast(surface_);
        return std::abs(std::hypot(rho - torus->MajorRadius(), z) - torus->MinorRadius());
    }

private:
    // p's component normal to the revolution's axis, from the axis.
    Vec3 radial_part(const Vec3& p) const {
        const Vec3 r = p - revolution_->axis_point;
        return r - revolution_->axis_dir * dot(r, revolution_->axis_dir);
    }

    Handle(Geom_Surface) surface_;
    gp_Trsf to_local_;
    std::optional<Construction::Revolution> revolution_;
    bool turns_along_u_ = true;  // revolve's layout; a mirror image turns along v
    Vec3 start_radial_{};
};

void validate(const CheckOptions& options) {
    // grid^2 evaluations per face: an absurd grid would run for hours, so it is an Error instead.
    require(options.grid >= 2 && options.grid <= 2000, "options.grid",
            "must be from 2 to 2000, got " + std::to_string(options.grid));
    require(std::isfinite(options.deviation_limit) && options.deviation_limit > 0, "options.deviation_limit",
            "must be a finite number greater than 0");
    require(std::isfinite(options.volume_limit) && options.volume_limit > 0, "options.volume_limit",
            "must be a finite number greater than 0");
    require(std::isfinite(options.bop_seconds) && options.bop_seconds > 0, "options.bop_seconds",
            "must be a finite number greater than 0");
}

double relative_difference(double a, double b) { return std::abs(a - b) / std::max(std::abs(a), std::abs(b)); }

// How far two honest measures of a solid recorded to a tolerance t may disagree (a file's t, on the faces read
// from it, brep/consistency.hpp): each face's boundary is known to t, which moves the volume by up to
// area x t and the area by up to (length of the edges, each bounding two faces) x t. Ratbez's own solids
// carry a t of rounding size, and so no slack to speak of.
struct Slack {
    double volume = 0, area = 0;
};

Slack tolerance_slack(const Solid& solid, double area) {
    double tolerance = 0;
    for (const Face& face : solid.faces()) tolerance = std::max(tolerance, face.tolerance());
    if (tolerance == 0) return {};
    // The edges' control polygons bound their lengths from above (de Casteljau and knot insertion put every new
    // projected point on a segment of the old polygon, so its length never grows as it converges to the
    // curve), without an integration that creeps near a point where a file's edge curve stands still.
    double edge_length = 0;
    for (const EdgePtr& edge : solid.edges()) {
        if (edge->degenerate) continue;
        const std::vector<Vec3> points = edge->curve.points();
        for (std::size_t k = 1; k < points.size(); ++k) edge_length += distance(points[k - 1], points[k]);
    }
    return {area * tolerance, 2 * edge_length * tolerance};
}

bool agree(double ours, double occt, double relative_limit, double slack) {
    return std::abs(ours - occt) <= std::max(relative_limit * std::max(std::abs(ours), std::abs(occt)), slack);
}

// OCCT's volume or area of the shape (Inertia: BRepGProp_Vinert or BRepGProp_Sinert) to the relative `eps`, as
// BRepGProp::VolumeProperties and SurfaceProperties compute it (BRepGProp.cxx: the same faces, about the same point,
// the mean of the vertices), face by face here so that `progress` is polled between faces: on a large part the
// adaptive rule ran 14 s with no poll, and a Ctrl-C waited that long. (BRepGProp on each face alone takes the volume
// about that face's own vertices, and the sum is no volume.)
template <class Inertia>
double occt_mass(const TopoDS_Shape& shape, double eps, const Progress& progress) {
    gp_XYZ mean(0, 0, 0);
    int vertices = 0;
    for (TopExp_Explorer it(shape, TopAbs_VERTEX); it.More(); it.Next(), ++vertices)
        mean += BRep_Tool::Pnt(TopoDS::Vertex(it.Current())).XYZ();
    if (vertices > 0) mean /= vertices;
    std::vector<TopoDS_Face> faces;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) faces.push_back(TopoDS::Face(it.Current()));
    Inertia inertia;
    inertia.SetLocation(gp_Pnt(mean));
    GProp_GProps sum(gp_Pnt(0, 0, 0).Transformed(shape.Location().Transformation()));
    BRepGProp_Face face;
    BRepGProp_Domain domain;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        if (progress) progress(static_cast<double>(f) / static_cast<double>(faces.size()));
        face.Load(faces[f]);
        domain.Init(faces[f]);
        inertia.Perform(face, domain, eps);
        sum.Add(inertia);
    }
    return sum.Mass();
}

// OpenCASCADE's volume or area of the converted solid (occt_mass). Its adaptive Gauss integration converges slowly
// on rational B-spline faces: a torus face converted exactly is 2e-6 off at eps 1e-9 and 2e-7 at 1e-11, where the
// analytic torus is exact at 1e-15. Where the first answer disagrees with ours it is asked again at 1e-11 and 1e-13
// before the disagreement is reported.
template <class Inertia>
double occt_measure(const TopoDS_Shape& shape, double ours, double relative_limit, double slack, const Progress& progress) {
    constexpr double kEps[] = {kPropertiesEps, 1e-11, 1e-13};
    constexpr double kPasses = static_cast<double>(std::size(kEps));
    double value = 0;
    for (std::size_t pass = 0; pass < std::size(kEps); ++pass) {
        value = occt_mass<Inertia>(shape, kEps[pass], progress_part(progress, pass / kPasses, (pass + 1) / kPasses));
        if (agree(ours, value, relative_limit, slack)) break;
    }
    return value;
}

// The words FreeCAD's BOP check report uses for a status ("BOPAlgo SelfIntersect"), so that a finding reads the
// same in both.
const char* status_name(BOPAlgo_CheckStatus status) {
    switch (status) {
        case BOPAlgo_BadType: return "BOPAlgo BadType";
        case BOPAlgo_SelfIntersect: return "BOPAlgo SelfIntersect";
        case BOPAlgo_TooSmallEdge: return "BOPAlgo TooSmallEdge";
        case BOPAlgo_NonRecoverableFace: return "BOPAlgo NonRecoverableFace";
        case BOPAlgo_IncompatibilityOfVertex: return "BOPAlgo IncompatibilityOfVertex";
        case BOPAlgo_IncompatibilityOfEdge: return "BOPAlgo IncompatibilityOfEdge";
        case BOPAlgo_IncompatibilityOfFace: return "BOPAlgo IncompatibilityOfFace";
        case BOPAlgo_OperationAborted: return "BOPAlgo OperationAborted";
        case BOPAlgo_GeomAbs_C0: return "BOPAlgo GeomAbs_C0";
        case BOPAlgo_InvalidCurveOnSurface: return "BOPAlgo InvalidCurveOnSurface";
        case BOPAlgo_NotValid: return "BOPAlgo NotValid";
        default: return "BOPAlgo CheckUnknown";
    }
}

const char* shape_kind(TopAbs_ShapeEnum type) {
    switch (type) {
        case TopAbs_VERTEX: return "vertex";
        case TopAbs_EDGE: return "edge";
        case TopAbs_WIRE: return "wire";
        case TopAbs_FACE: return "face";
        case TopAbs_SHELL: return "shell";
        case TopAbs_SOLID: return "solid";
        default: return "shape";
    }
}

// BOPAlgo_ArgumentAnalyzer set up as FreeCAD's "Run BOP check" sets it up (TopoShape::isValid / TaskCheckGeometry:
// every mode on), on a copy of the shape as FreeCAD does: the analysis intersects the shape with itself and may
// raise the tolerances of what it runs on, which would change the measurements taken after it. Each finding
// names its status, the kinds of its shapes and, for faces, which face of ours (face i of the Solid). It runs on
// the solid as handed out (`handed`: split at C0 knots where to_occt splits it), its faces traced back to ours,
// and as FreeCAD gets it: through the .brep text (brep_string, write_brep), read back, then copied. The text
// round trip matters: on a trimmed sphere read from a file (corpus sphere_minus_box) the search flags a face of
// the read-back shape and not of the one in memory.
// `progress` follows the analysis (its self-intersection search takes most of a large part's check), and a
// callback that throws stops it: the exception comes out once OpenCASCADE has wound down.
// The BOP analysis in this process: its findings in order, each "<status>[: kinds][ (face ...)]", and the counts.
struct BopFindings {
    std::vector<std::string> findings;
    int self_intersections = 0, small_edges = 0;
    bool faulty = false;
};

BopFindings analyse_here(const ConvertedSolid& converted, const detail::SplitSolid& handed, const Progress& progress) {
    BopFindings found;
    std::stringstream text;
    BRepTools::Write(handed.solid, text);
    TopoDS_Shape read;
    BRep_Builder builder;
    BRepTools::Read(read, text, builder);
    TopTools_IndexedMapOfShape handed_faces, read_faces;
    TopExp::MapShapes(handed.solid, TopAbs_FACE, handed_faces);
    TopExp::MapShapes(read, TopAbs_FACE, read_faces);
    if (read.IsNull() || read_faces.Extent() != handed_faces.Extent()) {
        found.findings.push_back("the .brep text of the solid does not read back");
        return found;
    }
    BRepBuilderAPI_Copy copier(read);
    BOPAlgo_ArgumentAnalyzer analyzer;
    // One thread: this runs in a forked child (bop_analysis), which has none of the parent's threads, and OCCT's
    // thread pool, started in the parent by an earlier parallel boolean (FreeCAD runs its BOP check so), waited
    // there for workers that do not exist: the check of a cylinder stopped at the time limit.
    BOPAlgo_Options::SetParallelMode(false);
    analyzer.SetRunParallel(false);
    analyzer.SetShape1(copier.Shape());
    analyzer.ArgumentTypeMode() = true;
    analyzer.SelfInterMode() = true;
    analyzer.SmallEdgeMode() = true;
    analyzer.RebuildFaceMode() = true;
    analyzer.ContinuityMode() = true;
    analyzer.TangentMode() = true;
    analyzer.MergeVertexMode() = true;
    analyzer.CurveOnSurfaceMode() = true;
    analyzer.MergeEdgeMode() = true;
    detail::CapturedProgress captured(progress);
    const Handle(detail::PolledIndicator) indicator = new detail::PolledIndicator(captured, 0, 1);
    try {
        analyzer.Perform(indicator->Start());
    } catch (const Standard_Failure&) {
        captured.rethrow_if_stopped();  // the caller's stop, not OpenCASCADE's reaction to it
        throw;
    }
    captured.rethrow_if_stopped();
    const auto our_face = [&](const TopoDS_Shape& shape) -> std::optional<std::size_t> {
        for (int k = 1; k <= read_faces.Extent(); ++k) {
            const TopoDS_Shape& piece = handed_faces(k);  // the same place in the text's order
            if (!copier.ModifiedShape(read_faces(k)).IsSame(shape) || !handed.original_face.IsBound(piece)) continue;
            const TopoDS_Shape& original = handed.original_face.Find(piece);
            for (std::size_t c = 0; c < converted.faces.size(); ++c)
                if (converted.faces[c].IsSame(original)) {
                    const auto after = std::upper_bound(converted.first_face.begin(), converted.first_face.end(), c);
                    return static_cast<std::size_t>(after - converted.first_face.begin()) - 1;
                }
        }
        return std::nullopt;
    };
    for (const BOPAlgo_CheckResult& result : analyzer.GetCheckResult()) {
        const BOPAlgo_CheckStatus status = result.GetCheckStatus();
        if (status == BOPAlgo_SelfIntersect) ++found.self_intersections;
        if (status == BOPAlgo_TooSmallEdge) ++found.small_edges;
        std::string kinds, faces;
        for (const TopoDS_Shape& shape : result.GetFaultyShapes1()) {
            kinds += (kinds.empty() ? "" : ", ") + std::string(shape_kind(shape.ShapeType()));
            if (shape.ShapeType() == TopAbs_FACE)
                if (const auto f = our_face(shape)) faces += (faces.empty() ? "" : ", ") + std::to_string(*f);
        }
        found.findings.push_back(std::string(status_name(status)) + (kinds.empty() ? "" : ": " + kinds) +
                                 (faces.empty() ? "" : " (face " + faces + ")"));
    }
    found.faulty = analyzer.HasFaulty();
    return found;
}

// The BOP analysis of the solid as handed out, in a child process (child_process.hpp) under a limit of time and
// memory: OpenCASCADE's face self-intersection search can run on for minutes and gigabytes on a real part (a
// 480 kB STEP bracket: 14 GB after 8 minutes, its loops deaf to Ctrl-C), where FreeCAD's own check of the same
// part takes seconds. Then the check says so (not completed), and the caller's Progress (Ctrl-C) kills the
// child within a poll interval.
void bop_analysis(const ConvertedSolid& converted, const detail::SplitSolid& handed, CheckReport& report,
                  double seconds, const Progress& progress) {
    detail::ChildWords words;
    words.argument = "solid";
    words.doing = "the BOP analysis";
    words.limit = "the check's limit";
    words.seconds_setting = words.memory_setting = "";
    words.crashed = "OpenCASCADE's BOP analysis crashed on it";
    words.crash_reason = "the solid is handed out all the same";
    const detail::ChildLimits limits{seconds, kBopMemoryBytes};
    std::string packed;
    try {
        packed = detail::run_in_child("the solid", limits, progress, [&](const detail::ChildProgress& report_fraction) {
            BopFindings found;
            try {
                found = analyse_here(converted, handed, [&](double f) { report_fraction(f); });
            } catch (const Standard_Failure& failure) {
                const char* message = failure.GetMessageString();
                throw Error("solid", std::string("OpenCASCADE raised ") + failure.DynamicType()->Name() +
                                         (message && *message ? std::string(": ") + message : std::string()));
            }
            // Lines: the counts and whether OCCT saw a fault, then one finding per line (none holds a newline).
            std::string bytes = std::to_string(found.self_intersections) + " " + std::to_string(found.small_edges) + " " +
                                (found.faulty ? "1" : "0") + "\n";
            for (const std::string& finding : found.findings) bytes += finding + "\n";
            return bytes;
        }, words);
    } catch (const Error& error) {
        if (error.argument() != "solid") throw;  // a stop's exception, or the child's own refusal
        report.bop_findings.push_back("not completed: " + std::string(error.reason()));
        report.bop_clean = false;
        return;
    }
    std::istringstream lines(packed);
    int faulty = 0;
    lines >> report.self_intersections >> report.small_edges >> faulty;
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line)) report.bop_findings.push_back(line);
    report.bop_clean = faulty == 0 && report.bop_findings.empty();
}

}  // namespace

CheckReport check(const Solid& solid, const CheckOptions& options) {
    validate(options);
    CheckReport report;
    report.size = solid.bounding_box().diagonal();
    // The progress reported: the steps below in these shares of the work (the grids take most of it).
    const auto report_progress = [&](double fraction) {
        if (options.progress) options.progress(fraction);
    };
    // Polled face by face from here on (a Ctrl-C on a large part waited 14 s for the conversion and the split).
    const ConvertedSolid converted = convert(solid, options.convert, progress_part(options.progress, 0, 0.04));
    // Validity, closure, OCCT's measures and the BOP analysis are of the solid as files and brep_string hand it
    // out (handout.hpp: faces still C0 inside split, or OCCT's own primitive); the evaluation deviation goes
    // through convert's maps (the split only segments surfaces, exactly; a primitive's analytic surface is
    // measured against ours by the analytic row).
    const detail::SplitSolid handed =
        detail::handed_out(solid, converted, options.convert, progress_part(options.progress, 0.04, 0.08));
    // Our own measures (the slack depends on the area), taken once, before OpenCASCADE may raise.
    report.volume = enclosed_volume(solid, progress_part(options.progress, 0.08, 0.09));
    report.area = surface_area(solid, progress_part(options.progress, 0.09, 0.1));
    const Slack slack = tolerance_slack(solid, report.area);
    report_progress(0.1);

    try {
        report.valid = BRepCheck_Analyzer(handed.solid).IsValid();
        report.closed = is_closed(handed.solid);
        report.max_deviation = evaluation_deviation(solid, converted, options.grid, progress_part(options.progress, 0.2, 0.5));

        if (AnalyticDistance analytic(solid.construction()); analytic.exists()) {
            double worst = 0;
            const Progress faces_done = progress_part(options.progress, 0.5, 0.8);
            for (std::size_t f = 0; f < solid.faces().size(); ++f) {
                const Face& face = solid.faces()[f];
                if (face.kind() != Face::Kind::surface) continue;  // caps and end faces are planes
                analytic.set_face(face);
                const Interval du = face.surface().domain_u(), dv = face.surface().domain_v();
                for (int i = 0; i < options.grid; ++i) {
                    if (faces_done)
                        faces_done((static_cast<double>(f) + static_cast<double>(i) / options.grid) /
                                   static_cast<double>(solid.faces().size()));
                    for (int j = 0; j < options.grid; ++j) {
                        const double u = sample(du.min, du.max, i, options.grid), v = sample(dv.min, dv.max, j, options.grid);
                        worst = std::max(worst, analytic(face.point(u, v), u, v));
                    }
                }
            }
            report.max_analytic_deviation = worst;
        }

        report_progress(0.8);
        report.occt_volume = occt_measure<BRepGProp_Vinert>(handed.solid, report.volume, options.volume_limit, slack.volume,
                                                            progress_part(options.progress, 0.8, 0.825));
        report.occt_area = occt_measure<BRepGProp_Sinert>(handed.solid, report.area, options.volume_limit, slack.area,
                                                          progress_part(options.progress, 0.825, 0.85));
        report_progress(0.85);
        if (options.bop_analysis)
            bop_analysis(converted, handed, report, options.bop_seconds, progress_part(options.progress, 0.85, 0.95));
    } catch (const Standard_Failure& failure) {
        const char* message = failure.GetMessageString();
        report.failures.push_back(std::string("OpenCASCADE raised ") + failure.DynamicType()->Name() +
                                  (message && *message ? std::string(": ") + message : std::string()));
    }
    report_progress(0.95);
    report.closed_form_volume = solid.construction().exact_volume();

    const double deviation_limit = options.deviation_limit * report.size;
    if (!report.valid) report.failures.push_back("BRepCheck_Analyzer: the converted B-rep is not valid");
    if (!report.closed) report.failures.push_back("the converted shell is not closed (free edges)");
    if (!(report.max_deviation <= deviation_limit))
        report.failures.push_back("evaluation deviation " + number(report.max_deviation) + " exceeds " +
                                  number(deviation_limit));
    if (report.max_analytic_deviation && !(*report.max_analytic_deviation <= deviation_limit))
        report.failures.push_back("analytic surface deviation " + number(*report.max_analytic_deviation) +
                                  " exceeds " + number(deviation_limit));
    if (!agree(report.volume, report.occt_volume, options.volume_limit, slack.volume))
        report.failures.push_back("volume " + number(report.volume) + " differs from OCCT's " +
                                  number(report.occt_volume));
    if (!agree(report.area, report.occt_area, options.volume_limit, slack.area))
        report.failures.push_back("area " + number(report.area) + " differs from OCCT's " + number(report.occt_area));
    if (report.closed_form_volume && !(relative_difference(report.volume, *report.closed_form_volume) <= options.volume_limit))
        report.failures.push_back("volume " + number(report.volume) + " differs from the closed form " +
                                  number(*report.closed_form_volume));
    for (const std::string& finding : report.bop_findings) report.failures.push_back("BOP check: " + finding);
    if (options.bop_analysis && !report.bop_clean && report.bop_findings.empty() && report.failures.empty())
        report.failures.push_back("BOP check: not completed");
    report.passed = report.failures.empty();
    report_progress(1.0);
    return report;
}

std::string format_report(const CheckReport& report) {
    std::ostringstream out;
    const auto row = [&](const std::string& name, const std::string& value, std::optional<bool> ok) {
        out << "  " << name;
        for (std::size_t k = name.size(); k < 30; ++k) out << ' ';
        out << value;
        for (std::size_t k = value.size(); k < 28; ++k) out << ' ';
        out << (ok ? (*ok ? "PASS" : "FAIL") : "") << '\n';
    };
    const auto relative = [&](double a, double b) { return number(relative_difference(a, b)); };
    out << "OpenCASCADE check: " << (report.passed ? "PASSED" : "FAILED") << '\n';
    row("BRepCheck valid", report.valid ? "yes" : "no", report.valid);
    row("shell closed", report.closed ? "yes" : "no", report.closed);
    row("size (box diagonal)", number(report.size), std::nullopt);
    row("max |ours - OCCT D0|", number(report.max_deviation), std::nullopt);
    if (report.max_analytic_deviation) row("max analytic distance", number(*report.max_analytic_deviation), std::nullopt);
    row("volume (ours)", number(report.volume), std::nullopt);
    row("volume (OCCT)", number(report.occt_volume) + " rel " + relative(report.volume, report.occt_volume), std::nullopt);
    if (report.closed_form_volume)
        row("volume (closed form)",
            number(*report.closed_form_volume) + " rel " + relative(report.volume, *report.closed_form_volume), std::nullopt);
    row("area (ours)", number(report.area), std::nullopt);
    row("area (OCCT)", number(report.occt_area) + " rel " + relative(report.area, report.occt_area), std::nullopt);
    row("BOP check clean", report.bop_clean ? "yes" : "no", report.bop_clean);
    row("self-intersections (BOP)", std::to_string(report.self_intersections), report.self_intersections == 0);
    row("small edges (BOP)", std::to_string(report.small_edges), report.small_edges == 0);
    for (const std::string& failure : report.failures) out << "  FAIL: " << failure << '\n';
    return out.str();
}

}  // namespace ratbez::occt

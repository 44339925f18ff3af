// Solids -> TopoDS_Solid: every primitive, full and partial revolutions of several profiles and
// extrusions are BRepCheck-valid and closed, and OCCT's volume and area (BRepGProp, eps 1e-9) equal ours
// to 1e-6 relative; OCCT's own primitives (BRepPrimAPI) have the same volumes.

#include <gtest/gtest.h>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <gp_Dir.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepCheck_Shell.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp.hxx>
#include <BRepOffsetAPI_MakeThickSolid.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Line.hxx>
#include <Geom_SphericalSurface.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "exact_edges.hpp"
#include "occt_test_support.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/occt/check.hpp"
#include "ratbez/occt/geometry.hpp"
#include "ratbez/occt/shape_import.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/interpolation.hpp"
#include "ratbez/join.hpp"
#include "ratbez/loft.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/solid_transform.hpp"
#include "ratbez/sweep.hpp"

namespace ratbez::occt {
namespace {

using testing::MaxTracker;
using testing::bop_check_finds_faults;
constexpr double kPi = std::numbers::pi;
constexpr double kPropertiesEps = 1e-9;

MaxTracker& volume_tracker() {
    static MaxTracker tracker("solids: max |V_ours - V_OCCT| / V");
    return tracker;
}
MaxTracker& area_tracker() {
    static MaxTracker tracker("solids: max |A_ours - A_OCCT| / A");
    return tracker;
}

int count(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, type, map);
    return map.Extent();
}

double occt_volume(const TopoDS_Shape& shape) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props, kPropertiesEps);
    return props.Mass();
}

double occt_area(const TopoDS_Shape& shape) {
    GProp_GProps props;
    BRepGProp::SurfaceProperties(shape, props, kPropertiesEps);
    return props.Mass();
}

// Everything a valid closed solid must satisfy in OCCT; returns OCCT's volume.
double expect_valid_closed_solid(const Solid& solid, const std::string& name) {
    SCOPED_TRACE(name);
    const ConvertedSolid converted = convert(solid);
    BRepCheck_Analyzer analyzer(converted.solid);
    EXPECT_TRUE(analyzer.IsValid()) << name << ": BRepCheck_Analyzer reports an invalid shape";

    BRepCheck_Shell shell_check(converted.shell);
    EXPECT_EQ(shell_check.Closed(), BRepCheck_NoError);
    EXPECT_EQ(shell_check.Orientation(), BRepCheck_NoError);
    ShapeAnalysis_FreeBounds free_bounds(converted.solid);
    EXPECT_EQ(count(free_bounds.GetClosedWires(), TopAbs_EDGE), 0);
    EXPECT_EQ(count(free_bounds.GetOpenWires(), TopAbs_EDGE), 0);

    // Topology one to one: faces, proper edges (+ one degenerate edge per degenerate side), vertices; but a flat
    // face (a disc or an annulus swept by a line square to the axis) goes over as a plane face, as Part's, with
    // neither its seam nor a degenerate edge (nor the vertex at its centre).
    EXPECT_EQ(count(converted.solid, TopAbs_FACE), static_cast<int>(solid.faces().size()));
    std::set<const Edge*> dropped;
    int degenerate_sides = 0;
    for (std::size_t i = 0; i < solid.faces().size(); ++i) {
        const Face& face = solid.faces()[i];
        if (face.kind() != Face::Kind::surface) continue;
        const bool flat = BRepAdaptor_Surface(converted.faces[converted.first_face[i]]).GetType() == GeomAbs_Plane;
        const auto& sides = face.sides();
        if (flat && sides[1].edge == sides[3].edge) dropped.insert(sides[1].edge.get());
        for (const Coedge& c : sides) degenerate_sides += c.edge->degenerate && !flat ? 1 : 0;
    }
    int proper_edges = 0;
    std::set<const Vertex*> vertices;
    for (const EdgePtr& e : solid.edges())
        if (!e->degenerate && !dropped.count(e.get())) {
            ++proper_edges;
            vertices.insert({e->start.get(), e->end.get()});
        }
    EXPECT_EQ(count(converted.solid, TopAbs_EDGE), proper_edges + degenerate_sides);
    EXPECT_EQ(count(converted.solid, TopAbs_VERTEX), static_cast<int>(vertices.size()));

    // Outward: a point far away is outside, and OCCT's volume is positive.
    const Box box = solid.bounding_box();
    BRepClass3d_SolidClassifier classifier(converted.solid);
    const Vec3 far = box.max + Vec3{1, 1, 1} * box.diagonal();
    classifier.Perform(to_occt_point(far), 1e-7);
    EXPECT_EQ(classifier.State(), TopAbs_OUT);

    const double volume = solid.volume(), area = solid.area();
    const double their_volume = occt_volume(converted.solid), their_area = occt_area(converted.solid);
    volume_tracker().add(std::abs(volume - their_volume) / volume);
    area_tracker().add(std::abs(area - their_area) / area);
    EXPECT_NEAR(their_volume, volume, 1e-6 * volume);
    EXPECT_NEAR(their_area, area, 1e-6 * area);
    return their_volume;
}

double occt_primitive_volume(const TopoDS_Shape& shape) { return occt_volume(shape); }

gp_Ax2 frame_of(const Vec3& center, const Vec3& axis) {
    const Vec3 a = axis / norm(axis);
    return gp_Ax2(to_occt_point(center), gp_Dir(a.x, a.y, a.z));
}

// No face's surface and no edge's curve is C0 (OpenCASCADE's BOP check reports GeomAbs_C0 on them).
void expect_no_c0_geometry(const TopoDS_Shape& shape) {
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next())
        EXPECT_NE(BRep_Tool::Surface(TopoDS::Face(it.Current()))->Continuity(), GeomAbs_C0);
    for (TopExp_Explorer it(shape, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        if (BRep_Tool::Degenerated(edge)) continue;
        double first = 0, last = 0;
        EXPECT_NE(BRep_Tool::Curve(edge, first, last)->Continuity(), GeomAbs_C0);
    }
}

TEST(Topology, CylinderIsValidAndMatchesBRepPrimAPI) {
    const Vec3 center{1, -2, 0.5}, axis{1, 2, 3};
    const Solid ours = cylinder(2, 5, center, axis);
    const double volume = expect_valid_closed_solid(ours, "cylinder");
    EXPECT_NEAR(volume, kPi * 4 * 5, 1e-6 * volume);
    const double theirs = occt_primitive_volume(BRepPrimAPI_MakeCylinder(frame_of(center, axis), 2, 5).Shape());
    EXPECT_NEAR(ours.volume(), theirs, 1e-6 * theirs);
}

TEST(Topology, ConesAreValidAndMatchBRepPrimAPI) {
    struct Case {
        double r1, r2, h;
    };
    for (const Case c : {Case{2, 1, 3}, Case{1, 2.5, 2}, Case{2, 0, 3}, Case{0, 1.5, 2}}) {
        const Vec3 center{0.5, 0, -1}, axis{0, 1, 1};
        const Solid ours = cone(c.r1, c.r2, c.h, center, axis);
        const std::string name = "cone r1=" + std::to_string(c.r1) + " r2=" + std::to_string(c.r2);
        const double volume = expect_valid_closed_solid(ours, name);
        const double closed_form = kPi * c.h * (c.r1 * c.r1 + c.r1 * c.r2 + c.r2 * c.r2) / 3;
        EXPECT_NEAR(volume, closed_form, 1e-6 * closed_form) << name;
        const double theirs = occt_primitive_volume(BRepPrimAPI_MakeCone(frame_of(center, axis), c.r1, c.r2, c.h).Shape());
        EXPECT_NEAR(ours.volume(), theirs, 1e-6 * theirs) << name;
    }
}

TEST(Topology, SphereIsValidWithPolesAndMatchesBRepPrimAPI) {
    const Vec3 center{3, 1, -2};
    const Solid ours = sphere(2.5, center);
    const double volume = expect_valid_closed_solid(ours, "sphere");
    EXPECT_NEAR(volume, 4.0 / 3.0 * kPi * std::pow(2.5, 3), 1e-6 * volume);
    const double theirs = occt_primitive_volume(BRepPrimAPI_MakeSphere(to_occt_point(center), 2.5).Shape());
    EXPECT_NEAR(ours.volume(), theirs, 1e-6 * theirs);

    // One face, one seam and two degenerate pole edges, two vertices: OCCT's own sphere has the same.
    const TopoDS_Solid solid = to_occt(ours);
    EXPECT_EQ(count(solid, TopAbs_FACE), 1);
    EXPECT_EQ(count(solid, TopAbs_EDGE), 3);
    EXPECT_EQ(count(solid, TopAbs_VERTEX), 2);
    int degenerated = 0;
    for (TopExp_Explorer it(solid, TopAbs_EDGE); it.More(); it.Next())
        degenerated += BRep_Tool::Degenerated(TopoDS::Edge(it.Current())) ? 1 : 0;
    EXPECT_EQ(degenerated, 2) << "each pole edge appears once in the face's wire";
}

TEST(Topology, TorusIsValidWithTwoSeamsAndMatchesBRepPrimAPI) {
    const Vec3 center{-1, 0, 2}, axis{0.3, -0.2, 1};
    const Solid ours = torus(5, 1.5, center, axis);
    const double volume = expect_valid_closed_solid(ours, "torus");
    EXPECT_NEAR(volume, 2 * kPi * kPi * 5 * 1.5 * 1.5, 1e-6 * volume);
    const double theirs = occt_primitive_volume(BRepPrimAPI_MakeTorus(frame_of(center, axis), 5, 1.5).Shape());
    EXPECT_NEAR(ours.volume(), theirs, 1e-6 * theirs);
    const TopoDS_Solid solid = to_occt(ours);
    EXPECT_EQ(count(solid, TopAbs_FACE), 1);
    EXPECT_EQ(count(solid, TopAbs_EDGE), 2);
    EXPECT_EQ(count(solid, TopAbs_VERTEX), 1);
    for (TopExp_Explorer it(solid, TopAbs_EDGE); it.More(); it.Next())
        EXPECT_TRUE(BRep_Tool::IsClosed(TopoDS::Edge(it.Current()), TopoDS::Face(TopExp_Explorer(solid, TopAbs_FACE).Current())))
            << "both torus edges are seams";
}

// A vase: a rational cubic Bézier from the axis out and back to the axis, in the xz plane.
Profile vase_profile() {
    return Profile::from_beziers({BezierCurve({{0, 0, 0}, {4, 0, 0.5}, {0.5, 0, 3}, {0, 0, 4}}, {1, 0.5, 2, 1})});
}

// A ring section: a closed profile of four pieces away from the axis (lines and a rational bulge).
Profile ring_profile() {
    return Profile({line_segment({2, 0, 0}, {4, 0, 0}),
                    NurbsCurve::from_bezier(BezierCurve({{4, 0, 0}, {5.5, 0, 1}, {4, 0, 2}}, {1, 0.6, 1})),
                    line_segment({4, 0, 2}, {2, 0, 2}), line_segment({2, 0, 2}, {2, 0, 0})});
}

TEST(Topology, FullAndPartialRevolutionsOfAVaseAreValid) {
    const double full = expect_valid_closed_solid(revolve(vase_profile()), "vase 360");
    for (double angle : {90.0, 180.0, 270.0}) {
        const double partial = expect_valid_closed_solid(revolve(vase_profile(), {}, {0, 0, 1}, angle),
                                                         "vase " + std::to_string(angle));
        EXPECT_NEAR(partial, full * angle / 360.0, 1e-6 * full) << angle;
    }
}

TEST(Topology, FullAndPartialRevolutionsOfAClosedMultiPieceProfileAreValid) {
    const double full = expect_valid_closed_solid(revolve(ring_profile()), "ring 360");
    for (double angle : {90.0, 180.0, 270.0}) {
        const double partial = expect_valid_closed_solid(revolve(ring_profile(), {}, {0, 0, 1}, angle),
                                                         "ring " + std::to_string(angle));
        EXPECT_NEAR(partial, full * angle / 360.0, 1e-6 * full) << angle;
    }
    // A triangle ring: one piece per side, lines only.
    const double triangle = expect_valid_closed_solid(
        revolve(Profile({line_segment({2, 0, 0}, {4, 0, 0}), line_segment({4, 0, 0}, {3, 0, 2}),
                         line_segment({3, 0, 2}, {2, 0, 0})}),
                {0, 0, 0}, {0, 0, 1}, 360.0),
        "triangle ring");
    // Pappus: area of the triangle (2) times the path of its centroid (x = 3).
    EXPECT_NEAR(triangle, 2.0 * 2 * kPi * 3.0, 1e-6 * triangle);
}

TEST(Topology, ExtrusionsAreValid) {
    // A circle extruded obliquely: volume = base area times height along the normal.
    const double cylinder_like =
        expect_valid_closed_solid(extrude(Profile({circle(1.5, {0, 0, 0}, {0, 0, 1})}), {0.2, 0.1, 1}, 3), "extruded circle");
    const Vec3 d = Vec3{0.2, 0.1, 1} / norm(Vec3{0.2, 0.1, 1}) * 3.0;
    EXPECT_NEAR(cylinder_like, kPi * 1.5 * 1.5 * d.z, 1e-6 * cylinder_like);
    // A multi-piece profile: a square with one rational side.
    const Profile rounded({line_segment({0, 0, 0}, {2, 0, 0}),
                           NurbsCurve::from_bezier(BezierCurve({{2, 0, 0}, {3, 1, 0}, {2, 2, 0}}, {1, 0.8, 1})),
                           line_segment({2, 2, 0}, {0, 2, 0}), line_segment({0, 2, 0}, {0, 0, 0})});
    expect_valid_closed_solid(extrude(rounded, {0, 0, 1}, 1.5), "extruded rounded square");
}

// ---- ConvertOptions::bezier_faces: what FreeCAD's Shape.Volume / Area / CenterOfMass read

// OCCT's fixed Gauss rule (BRepGProp without eps, as FreeCAD calls it): volume, centre of mass and area.
struct FixedRule {
    double volume, area;
    Vec3 centre;
};
FixedRule fixed_rule(const TopoDS_Shape& shape) {
    GProp_GProps volume, area;
    BRepGProp::VolumeProperties(shape, volume);
    BRepGProp::SurfaceProperties(shape, area);
    return {volume.Mass(), area.Mass(), from_occt(volume.CentreOfMass())};
}

MaxTracker& fixed_rule_tracker(bool bezier_faces) {
    static MaxTracker native("OCCT's fixed rule, one face per face: max |V - V_ours| / V");
    static MaxTracker patches("OCCT's fixed rule, bezier_faces: max of |V - V_ours| / V, |A - A_ours| / A");
    return bezier_faces ? patches : native;
}

// Valid, closed, read by OCCT's fixed rule to 1e-8 (volume, area; centre of mass against `centre` when
// given, to 1e-8 of the size), no C0 knot in any surface or edge curve (what FreeCAD's "Run BOP check"
// flags as GeomAbs_C0). With `bop_check`, nothing for the rest of BOPAlgo's argument checks to flag either
// (self-intersection, small edges, curve on surface): 0.15 s (a cylinder) to 2 s (a sphere) each, so only
// where asked; the FreeCAD tests run FreeCAD's own BOP check on every primitive and example.
void expect_measurable(const Solid& solid, const std::string& name, std::optional<Vec3> centre = std::nullopt,
                       bool bop_check = false) {
    SCOPED_TRACE(name);
    const ConvertedSolid converted = convert(solid, ConvertOptions{true});
    EXPECT_TRUE(converted.gprop_tolerance_reached);
    EXPECT_TRUE(BRepCheck_Analyzer(converted.solid).IsValid());
    ShapeAnalysis_FreeBounds free_bounds(converted.solid);
    EXPECT_EQ(count(free_bounds.GetOpenWires(), TopAbs_EDGE), 0);
    EXPECT_EQ(converted.first_face.size(), solid.faces().size() + 1);
    EXPECT_EQ(converted.faces.size(), static_cast<std::size_t>(count(converted.solid, TopAbs_FACE)));

    const double volume = solid.volume(), area = solid.area(), size = solid.bounding_box().diagonal();
    const FixedRule ours_in_occt = fixed_rule(converted.solid);
    const double volume_error = std::abs(ours_in_occt.volume - volume) / volume;
    const double area_error = std::abs(ours_in_occt.area - area) / area;
    fixed_rule_tracker(true).add(std::max(volume_error, area_error));
    fixed_rule_tracker(false).add(std::abs(fixed_rule(to_occt(solid)).volume - volume) / volume);
    EXPECT_LT(volume_error, 1e-8);
    EXPECT_LT(area_error, 1e-8);
    if (centre) {
        EXPECT_LT(distance(ours_in_occt.centre, *centre), 1e-8 * size);
    }

    expect_no_c0_geometry(converted.solid);
    if (bop_check) {
        EXPECT_FALSE(bop_check_finds_faults(converted.solid));
    }

    // The same geometry: our points on OCCT's patches and edge pieces (check() maps each patch's unit square).
    CheckOptions options;
    options.grid = 9;
    options.convert.bezier_faces = true;
    const CheckReport report = check(solid, options);
    EXPECT_TRUE(report.passed) << format_report(report);
}

TEST(Topology, BezierFacesAreReadByOcctsFixedRuleAndPassTheBopCheck) {
    const Vec3 c{1, -2, 0.5}, axis{0, 1, 2};
    const Vec3 unit = axis / norm(axis);
    expect_measurable(sphere(3, c), "sphere", c);
    expect_measurable(cylinder(2, 5, c, axis), "cylinder", c + unit * 2.5, true);
    expect_measurable(cone(8, 3, 12, c, axis), "cone");
    expect_measurable(cone(4, 0, 9), "pointed cone", Vec3{0, 0, 9.0 / 4});
    expect_measurable(torus(10, 3, c, axis), "torus", c);
    expect_measurable(revolve(vase_profile()), "vase");
    expect_measurable(revolve(ring_profile(), {}, {0, 0, 1}, 270), "partial ring");
    expect_measurable(extrude(Profile({circle(3)}), {0, 0, 1}, 2, {Profile({circle(1, {1, 0, 0})})}), "disc with a hole");
    // Weights spread 400x within one Bézier span: patches halved, refined in v.
    const Profile strong({line_segment({0, 0, 0}, {6, 0, 0}),
                          NurbsCurve::from_bezier(BezierCurve({{6, 0, 0}, {14, 0, 6}, {1, 0, 14}, {4, 0, 20}}, {1, 20, 0.05, 1})),
                          line_segment({4, 0, 20}, {0, 0, 20})});
    expect_measurable(revolve(strong), "vase with weights 1, 20, 0.05, 1");
}

// The natural conversion (one OCCT face per face, the default): arcs in their one-span form (topology.hpp), so
// OCCT's fixed rule — FreeCAD's Shape.Volume, Area, CenterOfMass — reads every primitive and revolution to the
// issue's 1e-4 (measured: 3e-9 on a sphere, 2e-6 on a torus; 0.9 % before), Part's face counts (a cylinder 3
// faces, a sphere and a torus 1), a full circle one edge, and no C0 knot left in any face or edge.
void expect_natural(const Solid& solid, const std::string& name, std::size_t faces, std::optional<Vec3> centre = std::nullopt) {
    SCOPED_TRACE(name);
    const ConvertedSolid converted = convert(solid);
    EXPECT_TRUE(BRepCheck_Analyzer(converted.solid).IsValid());
    EXPECT_EQ(converted.faces.size(), faces);
    EXPECT_EQ(static_cast<std::size_t>(count(converted.solid, TopAbs_FACE)), faces);
    for (const auto& [edge, pieces] : converted.edges) EXPECT_EQ(pieces.size(), 1u);
    const double volume = solid.volume(), area = solid.area(), size = solid.bounding_box().diagonal();
    const FixedRule read = fixed_rule(converted.solid);
    EXPECT_LT(std::abs(read.volume - volume) / volume, 1e-5);
    EXPECT_LT(std::abs(read.area - area) / area, 1e-5);
    if (centre) {
        EXPECT_LT(distance(read.centre, *centre), 1e-5 * size);
    }
    expect_no_c0_geometry(converted.solid);
    // The same geometry: check() compares our points with OCCT's through the arcs' parameter maps.
    CheckOptions options;
    options.grid = 9;
    const CheckReport report = check(solid, options);
    EXPECT_TRUE(report.valid && report.closed) << format_report(report);
    EXPECT_LE(report.max_deviation, 1e-12 * size) << format_report(report);
}

TEST(Topology, NaturalFacesAreReadByOcctsFixedRule) {
    const Vec3 c{1, -2, 0.5}, axis{0, 1, 2};
    const Vec3 unit = axis / norm(axis);
    expect_natural(sphere(3, c), "sphere", 1, c);
    expect_natural(sphere(3, {0, 40, 0}), "sphere at (0, 40, 0)", 1, Vec3{0, 40, 0});
    expect_natural(cylinder(2, 5, c, axis), "cylinder", 3, c + unit * 2.5);
    expect_natural(cone(8, 3, 12, c, axis), "cone", 3);
    expect_natural(cone(4, 0, 9), "pointed cone", 2, Vec3{0, 0, 9.0 / 4});
    expect_natural(torus(10, 3, c, axis), "torus", 1, c);
    expect_natural(revolve(vase_profile()), "vase", revolve(vase_profile()).faces().size());
}

// A face that keeps a C0 direction which is not an arc (a ruled loft's crease at its middle circle) goes over as
// Bézier patches even in the natural conversion: read right by OCCT's fixed rule (9 % off as one face), nothing
// C0 left; the faces beside it stay whole (the planar caps: one each).
TEST(Topology, RoughFacesGoOverAsPatchesInTheNaturalConversion) {
    std::vector<Profile> sections;
    for (const auto& [r, z] : {std::pair{1.0, 0.0}, std::pair{2.0, 1.0}, std::pair{1.0, 2.0}})
        sections.push_back(Profile({circle(r, {0, 0, z})}));
    const Solid solid = loft(sections, 3, true);
    const ConvertedSolid natural = convert(solid);
    EXPECT_TRUE(BRepCheck_Analyzer(natural.solid).IsValid());
    EXPECT_LE(natural.faces.size(), convert(solid, ConvertOptions{true}).faces.size());
    EXPECT_GT(natural.faces.size(), solid.faces().size());
    const FixedRule read = fixed_rule(natural.solid);
    EXPECT_LT(std::abs(read.volume - solid.volume()) / solid.volume(), 1e-8);
    for (TopExp_Explorer it(natural.solid, TopAbs_FACE); it.More(); it.Next())
        EXPECT_NE(BRep_Tool::Surface(TopoDS::Face(it.Current()))->Continuity(), GeomAbs_C0);
}

// A face rough in one direction only where it is C1 (a revolved rational profile's joint, a quadratic's knot: the
// second derivative jumps) stays one face, as Part's Revolution and Extrusion make it: the edges of its sides along
// that direction are cut at the joints instead, which splits OCCT's rule there (topology.cpp, cut_on_sides); a face
// rough in u goes over with u and v exchanged (and OCCT's u reversed: the face stays FORWARD). Before:
// examples/partial_revolve.json 14 faces as patches (4e-4 off as one face), an extruded closed quadratic 1.1e-3 off
// in area. Now Part's faces, each profile or section edge in pieces, read to 1e-8; so are the full turn, whose seam
// is the cut edge, one moved far from the origin, and an oblique extrusion.
TEST(Topology, FacesRoughInOneDirectionStayWholeWithTheirSidesCut) {
    const Profile rational_side({NurbsCurve(2, {0, 0, 0, 0.5, 1, 1, 1}, {{10, 0, 0}, {10, 0, 3}, {8, 0, 5}, {6, 0, 3}},
                                            {1, 0.8, 1.2, 1}),
                                 line_segment({6, 0, 3}, {6, 0, 0}), line_segment({6, 0, 0}, {10, 0, 0})});
    const Solid partial = revolve(rational_side, {}, {0, 0, 1}, 270);
    const Profile quadratic(
        {interpolate({{7, 0, 0}, {0, 3, 0}, {-7, 0, 0}, {0, -3, 0}}, 2, Parameterization::chord, {}, true)});
    // name, solid, faces, edges as handed over (the kernel's, the rough edges cut at each joint).
    for (const auto& [name, solid, faces, edges] :
         {std::tuple{std::string("partial revolve"), partial, 5, 11},
          std::tuple{std::string("full revolve"), revolve(rational_side), 3, 6},  // the flat annulus has no seam
          std::tuple{std::string("partial revolve moved"), transformed(partial, AffineMap::translation({300, -2000, 45})),
                     5, 11},
          std::tuple{std::string("extruded closed quadratic"), extrude(quadratic, {0, 0, 1}, 5), 3, 11},
          std::tuple{std::string("oblique extrusion of it"), extrude(quadratic, {0, 1, 1}, 5), 3, 11}}) {
        SCOPED_TRACE(name);
        const ConvertedSolid natural = convert(solid);
        EXPECT_TRUE(BRepCheck_Analyzer(natural.solid).IsValid());
        EXPECT_EQ(natural.faces.size(), solid.faces().size());
        EXPECT_EQ(count(natural.solid, TopAbs_FACE), faces);
        EXPECT_EQ(count(natural.solid, TopAbs_EDGE), edges);
        const FixedRule read = fixed_rule(natural.solid);
        EXPECT_LT(std::abs(read.volume - solid.volume()) / solid.volume(), 1e-8);
        EXPECT_LT(std::abs(read.area - solid.area()) / solid.area(), 1e-8);
        expect_no_c0_geometry(natural.solid);
        for (const TopoDS_Face& face : natural.faces) EXPECT_EQ(face.Orientation(), TopAbs_FORWARD);
        const TopoDS_Solid handed = to_occt(solid);
        EXPECT_EQ(count(handed, TopAbs_FACE), faces);
        EXPECT_FALSE(bop_check_finds_faults(handed));
        CheckOptions options;
        options.grid = 9;
        const CheckReport report = check(solid, options);
        EXPECT_TRUE(report.passed) << format_report(report);
    }
}

// Lofts through circles and polygons go over with Part's Loft's faces: one side face per run between the
// knots every section needs (a square's corners; a rounded square's joints between its lines and arcs), not one
// per joint any section happens to have (a circle's own arcs: section_alignment.hpp), and cells whose weights
// dip between the sections are not halved when OCCT's fixed rule reads them (gprop_patches.hpp), and the seam of
// closed sections at a corner (align_sections). Before: the circle -> square -> circle loft 9 faces, then 7 with
// the seam halfway along a side (Part 7: its seam is there too), now 6; the example loft 34 (Part 11).
TEST(Topology, LoftsGoOverWithPartsFaces) {
    const Profile thirds({join({arc(2.0, 0, 120), arc(2.0, 120, 240), arc(2.0, 240, 360)})});  // OCCT's circle
    std::vector<Vec3> corners{{-1.5, -1.5, 4}, {1.5, -1.5, 4}, {1.5, 1.5, 4}, {-1.5, 1.5, 4}};
    std::vector<NurbsCurve> sides;
    for (std::size_t k = 0; k < 4; ++k) sides.push_back(line_segment(corners[k], corners[(k + 1) % 4]));
    const Profile top({join({arc(2.0, 0, 120, {0, 0, 8}), arc(2.0, 120, 240, {0, 0, 8}), arc(2.0, 240, 360, {0, 0, 8})})});
    // examples/loft.json: a circle, a rounded square, two circles.
    std::vector<NurbsCurve> rounded{line_segment({6, 0, 10}, {6, 4, 10})};
    const Vec3 centres[] = {{4, 4, 10}, {-4, 4, 10}, {-4, -4, 10}, {4, -4, 10}};
    const Vec3 next_sides[][2] = {{{4, 6, 10}, {-4, 6, 10}}, {{-6, 4, 10}, {-6, -4, 10}}, {{-4, -6, 10}, {4, -6, 10}}, {{6, -4, 10}, {6, 0, 10}}};
    for (int k = 0; k < 4; ++k) {
        rounded.push_back(arc(2.0, 90.0 * k, 90.0 * (k + 1), centres[k]));
        rounded.push_back(line_segment(next_sides[k][0], next_sides[k][1]));
    }
    const std::vector<Profile> example{Profile({circle(8)}), Profile(rounded), Profile({circle(4, {2, 0, 22})}),
                                       Profile({circle(6, {3, 0, 30})})};
    // examples/interpolated_loft.json: closed interpolations, matched by their own parameters from the starts of
    // least twist: one side face, C1 (the quadratic's knots), as Part's Loft of the same curves has no edge
    // across its side (it had 16 strips when matched by arc length at every knot). OCCT's rule reads it to 1e-7
    // (cubic cap edges of several C2 spans each; the issue asks for 1e-4).
    auto closed_interpolation = [](std::vector<Vec3> points, int degree, Parameterization kind) {
        return Profile({interpolate(points, degree, kind, {}, true)});
    };
    const std::vector<Profile> smooth{
        closed_interpolation({{6, 0, 0}, {2, 3, 0}, {-3, 5, 0}, {-3, 0, 0}, {-3, -5, 0}, {2, -3, 0}}, 3, Parameterization::centripetal),
        closed_interpolation({{0, 5, 8}, {-4, 4, 8}, {-5, 0, 8}, {-4, -4, 8}, {0, -5, 8}, {4, -4, 8}, {6, 0, 8}, {4, 4, 8}}, 3,
                             Parameterization::chord),
        closed_interpolation({{7, 0, 16}, {0, 3, 16}, {-7, 0, 16}, {0, -3, 16}}, 2, Parameterization::chord)};
    for (const auto& [name, solid, faces, reading] :
         {std::tuple{std::string("circle, square, circle"), loft({thirds, Profile(sides), top}), 6, 1e-8},
          std::tuple{std::string("ruled circle, square"), loft({thirds, Profile(sides)}, 3, true), 6, 1e-8},
          std::tuple{std::string("examples/loft"), loft(example), 11, 1e-8},
          std::tuple{std::string("examples/interpolated_loft"), loft(smooth, 2), 3, 1e-6}}) {
        SCOPED_TRACE(name);
        const ConvertedSolid converted = convert(solid);
        EXPECT_TRUE(BRepCheck_Analyzer(converted.solid).IsValid());
        EXPECT_EQ(count(converted.solid, TopAbs_FACE), faces);
        const FixedRule read = fixed_rule(converted.solid);
        EXPECT_LT(std::abs(read.volume - solid.volume()) / solid.volume(), reading);
        EXPECT_LT(std::abs(read.area - solid.area()) / solid.area(), reading);
        expect_no_c0_geometry(converted.solid);
        EXPECT_FALSE(bop_check_finds_faults(converted.solid));
    }
    // The loft's side faces are refined for OCCT's rule by degree elevation, one span, not by a simple knot: no
    // curvature jump inside a face (OCCT's offset of a C1 face is C0), as Part's loft faces (degree 8, one span).
    const TopoDS_Solid loft_solid = convert(loft({thirds, Profile(sides), top})).solid;
    for (TopExp_Explorer it(loft_solid, TopAbs_FACE); it.More(); it.Next())
        EXPECT_EQ(BRep_Tool::Surface(TopoDS::Face(it.Current()))->Continuity(), GeomAbs_CN);
}

// A sweep along a line and a tangent arc goes over with Part's Sweep's faces: one per path piece and profile edge,
// and the caps. The circle's tube was one face with a C0 joint (the speed along the path jumps where the pieces
// meet), which went over as patches: 3 x 2 side faces, 2 on a half-turn arc, where Part's Sweep has 2. As handed
// out (files, FreeCAD) it is OCCT's pipe on Part's surfaces: a cylinder, a torus and two planes.
TEST(Topology, SweepsAlongLinesAndArcsGoOverWithAFacePerPathPiece) {
    for (const double turn : {90.0, 180.0}) {
        SCOPED_TRACE(turn);
        const NurbsCurve path = join({line_segment({0, 0, 0}, {6, 0, 0}), arc(5.0, -90, -90 + turn, {6, 5, 0})});
        const double length = 6 + 5 * turn * kPi / 180;
        const Solid tube = sweep(Profile({circle(1.0, {0, 0, 0}, {1, 0, 0})}), path);
        const ConvertedSolid converted = convert(tube);
        EXPECT_TRUE(BRepCheck_Analyzer(converted.solid).IsValid());
        EXPECT_EQ(count(converted.solid, TopAbs_FACE), 4);
        const FixedRule read = fixed_rule(converted.solid);
        EXPECT_NEAR(read.volume, kPi * length, 1e-9 * kPi * length);
        expect_no_c0_geometry(converted.solid);
        EXPECT_FALSE(bop_check_finds_faults(converted.solid));
        const TopoDS_Solid handed = to_occt(tube);
        std::multiset<GeomAbs_SurfaceType> types;
        for (TopExp_Explorer it(handed, TopAbs_FACE); it.More(); it.Next())
            types.insert(BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType());
        EXPECT_EQ(types, (std::multiset<GeomAbs_SurfaceType>{GeomAbs_Plane, GeomAbs_Plane, GeomAbs_Cylinder, GeomAbs_Torus}));
        EXPECT_NEAR(fixed_rule(handed).volume, kPi * length, 1e-12 * kPi * length);
        EXPECT_FALSE(bop_check_finds_faults(handed));
    }
}

// OCCT's Thickness hollows a ruled solid through its top cap, as it hollows Part's ruled Loft. Before the seam of
// closed sections went to a corner (align_sections), the circle -> square's side faces met halfway along a side in
// a fold, and the Thickness's inner face there came out with p-curves 6e-5 apart, "Unorientable shape" (FreeCAD's
// test_part_operations listed it as a known failure).
TEST(Topology, RuledSolidsAreHollowedByOcctsThickness) {
    const Profile thirds({join({arc(2.0, 0, 120), arc(2.0, 120, 240), arc(2.0, 240, 360)})});  // OCCT's circle
    std::vector<NurbsCurve> sides;
    const std::vector<Vec3> corners{{-1.5, -1.5, 4}, {1.5, -1.5, 4}, {1.5, 1.5, 4}, {-1.5, 1.5, 4}};
    for (std::size_t k = 0; k < 4; ++k) sides.push_back(line_segment(corners[k], corners[(k + 1) % 4]));
    for (const auto& [name, solid] : {std::pair{std::string("circle, square"), loft({thirds, Profile(sides)}, 3, true)},
                                      std::pair{std::string("circle, circle"),
                                                loft({Profile({circle(2)}), Profile({circle(1, {0, 0, 4})})}, 3, true)}}) {
        SCOPED_TRACE(name);
        const TopoDS_Solid handed = to_occt(solid);
        TopoDS_Face top;
        double highest = -1e300;
        for (TopExp_Explorer it(handed, TopAbs_FACE); it.More(); it.Next()) {
            const TopoDS_Face face = TopoDS::Face(it.Current());
            if (BRepAdaptor_Surface(face).GetType() != GeomAbs_Plane) continue;
            GProp_GProps props;
            BRepGProp::SurfaceProperties(face, props);
            if (props.CentreOfMass().Z() > highest) { highest = props.CentreOfMass().Z(); top = face; }
        }
        ASSERT_FALSE(top.IsNull());
        TopTools_ListOfShape removed;
        removed.Append(top);
        BRepOffsetAPI_MakeThickSolid thick;
        thick.MakeThickSolidByJoin(handed, removed, -0.5, 1e-7);
        ASSERT_TRUE(thick.IsDone());
        EXPECT_TRUE(BRepCheck_Analyzer(thick.Shape()).IsValid());
        GProp_GProps props;
        BRepGProp::VolumeProperties(thick.Shape(), props);
        EXPECT_GT(props.Mass(), 0.1 * solid.volume());
        EXPECT_LT(props.Mass(), 0.9 * solid.volume());
    }
}

// Cylinders, cones, spheres and tori go over as OCCT's own primitives (analytic_primitives.hpp): by their record,
// or, for a lone sphere or torus face read from a file, by their surface. The BOP check's face self-intersection
// search flags a B-spline sphere's poles at (0, -40, 0) and (100, 0, 0) (OCCT's own NURBS sphere too), never an
// analytic one. analytic_primitives = false hands over the kernel's B-spline faces.
TEST(Topology, PrimitivesGoOverAsOcctsOwn) {
    const Vec3 c{1, -2, 0.5}, axis{0, 1, 2};
    const Solid read_sphere = from_occt(BRepPrimAPI_MakeSphere(gp_Pnt(100, 0, 0), 3).Shape());
    const Solid read_torus = from_occt(BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(5, 6, 7), gp_Dir(1, 1, 0)), 4, 1).Shape());
    ASSERT_EQ(read_sphere.construction().kind(), "none");
    const std::tuple<std::string, Solid, GeomAbs_SurfaceType> cases[] = {
        {"sphere at (0, -40, 0)", sphere(3, {0, -40, 0}), GeomAbs_Sphere},
        {"sphere at (100, 0, 0)", sphere(3, {100, 0, 0}), GeomAbs_Sphere},
        {"sphere read from OCCT", read_sphere, GeomAbs_Sphere},
        {"torus read from OCCT", read_torus, GeomAbs_Torus},
        {"torus", torus(10, 3, c, axis), GeomAbs_Torus},
        {"cylinder", cylinder(2, 5, c, axis), GeomAbs_Cylinder},
        {"cone", cone(8, 3, 12, c, axis), GeomAbs_Cone},
        {"pointed cone", cone(4, 0, 9), GeomAbs_Cone}};
    for (const auto& [name, solid, kind] : cases) {
        SCOPED_TRACE(name);
        const TopoDS_Solid handed = to_occt(solid);
        EXPECT_TRUE(BRepCheck_Analyzer(handed).IsValid());
        int curved = 0;
        for (TopExp_Explorer it(handed, TopAbs_FACE); it.More(); it.Next()) {
            const GeomAbs_SurfaceType type = BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType();
            EXPECT_TRUE(type == kind || type == GeomAbs_Plane) << type;
            curved += type == kind;
        }
        EXPECT_EQ(curved, 1);
        const FixedRule read = fixed_rule(handed);
        EXPECT_LT(std::abs(read.volume - solid.volume()) / solid.volume(), 1e-9);
        const CheckReport report = check(solid, CheckOptions{});
        EXPECT_TRUE(report.passed && report.bop_clean) << format_report(report);
        ConvertOptions bspline;
        bspline.analytic_primitives = false;
        for (TopExp_Explorer it(to_occt(solid, bspline), TopAbs_FACE); it.More(); it.Next()) {
            const GeomAbs_SurfaceType type = BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType();
            EXPECT_TRUE(type == GeomAbs_BSplineSurface || type == GeomAbs_Plane) << type;
        }
    }
}

// Extrusions and revolutions go over as OCCT's prism or revolution of their profile (swept_solids.hpp): lines and
// arcs as planes, cylinders, cones, spheres and tori, face i of ours face i of the shape. Part's Thickness works on
// those and flagged the B-spline forms (GeomAbs_C0). A sweep OCCT's fixed rule misreads (an oblique extrusion of a
// circle, Area 2.5e-4 off; the vase's revolved rational cubic, 1.2e-8) goes over as our B-splines (the vase's flat
// discs as planes).
TEST(Topology, ExtrusionsAndRevolutionsGoOverAsOcctSweepsThem) {
    using Types = std::vector<GeomAbs_SurfaceType>;
    constexpr auto P = GeomAbs_Plane, Cy = GeomAbs_Cylinder, Co = GeomAbs_Cone, Sp = GeomAbs_Sphere, To = GeomAbs_Torus,
                   Ex = GeomAbs_SurfaceOfExtrusion, B = GeomAbs_BSplineSurface;
    const Profile slot({line_segment({0, -2, 0}, {10, -2, 0}), arc(2, -90, 90, {10, 0, 0}), line_segment({10, 2, 0}, {0, 2, 0}),
                        arc(2, 90, 270, {0, 0, 0})});
    // In the xy plane, turned about the y axis: x in [2, 4], y in [0, 3], a half disc r = 1.5 on the right side.
    const Profile ring({line_segment({2, 0, 0}, {4, 0, 0}), arc(1.5, -90, 90, {4, 1.5, 0}), line_segment({4, 3, 0}, {2, 3, 0}),
                        line_segment({2, 3, 0}, {2, 0, 0})});
    const Profile bowl({line_segment({0, 0, 0}, {3, 0, 0}), line_segment({3, 0, 0}, {1, 4, 0}), line_segment({1, 4, 0}, {0, 4, 0})});
    const Profile half_disc({arc(2, -90, 90, {0, 0, 0})});
    const Profile vase({line_segment({0, 0, 0}, {6, 0, 0}),
                        NurbsCurve::from_bezier(BezierCurve({{6, 0, 0}, {14, 0, 6}, {1, 0, 14}, {4, 0, 20}}, {1, 2, 0.5, 1})),
                        line_segment({4, 0, 20}, {0, 0, 20})});
    const Vec3 y{0, 1, 0};
    const AffineMap moved = AffineMap::rotation({1, 2, 3}, {1, 1, 0}, 30).after(AffineMap::translation({-5, 40, 7}));
    const std::tuple<std::string, Solid, Types> cases[] = {
        {"slot", extrude(slot, {0, 0, 1}, 5), {P, Cy, P, Cy, P, P}},
        {"disc with a hole", extrude(Profile({circle(5)}), {0, 0, 1}, 3, {Profile({circle(1, {1, 0, 0})})}), {Cy, Cy, P, P}},
        {"ring, full turn", revolve(ring, {}, y), {P, To, P, Cy}},
        {"ring, 270 degrees", revolve(ring, {}, y, 270), {P, To, P, Cy, P, P}},
        {"ring, moved and turned", transformed(revolve(ring, {}, y, 270), moved), {P, To, P, Cy, P, P}},
        // A mirror image swaps its faces' parameters (v turns about the axis) and reverses the recorded axis.
        {"ring, mirrored", transformed(revolve(ring, {}, y, 270), AffineMap::mirror({1, 0, 0}, {1, 0, 0})), {P, To, P, Cy, P, P}},
        {"ring, full turn, mirrored", transformed(revolve(ring, {}, y), AffineMap::mirror({0, 0, 0}, {0, 1, 1})), {P, To, P, Cy}},
        {"bowl, open profile ending on the axis", revolve(bowl, {}, y), {P, Co, P}},
        {"ball", revolve(half_disc, {}, y), {Sp}},
        {"quarter ball", revolve(half_disc, {}, y, 90), {Sp, P, P}},
        {"oblique extrusion of a circle", extrude(Profile({circle(5)}), {0, 1, 1}, 3), {B, P, P}},
        {"extrusion of an interpolated curve and a line",
         extrude(Profile({interpolate({{0, 0, 0}, {1, -1, 0}, {3, -1, 0}, {4, 0, 0}}), line_segment({4, 0, 0}, {0, 0, 0})}), {0, 0, 1}, 2),
         {Ex, P, P, P}},
        {"examples/vase.json, a rational cubic revolved", revolve(vase, {}, {0, 0, 1}), {P, B, P}}};
    for (const auto& [name, solid, types] : cases) {
        SCOPED_TRACE(name);
        const TopoDS_Solid handed = to_occt(solid);
        EXPECT_TRUE(BRepCheck_Analyzer(handed).IsValid());
        Types handed_types;
        for (TopExp_Explorer it(handed, TopAbs_FACE); it.More(); it.Next())
            handed_types.push_back(BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType());
        EXPECT_EQ(handed_types, types);
        EXPECT_LT(std::abs(fixed_rule(handed).volume - solid.volume()) / solid.volume(), 1e-9);
        const CheckReport report = check(solid, CheckOptions{});
        EXPECT_TRUE(report.passed && report.bop_clean) << format_report(report);
    }
}

// A face trimmed on a sphere goes over on OCCT's spherical surface (elementary_faces.hpp): FreeCAD's sphere minus a
// box, read from a file (the kernel holds its face as a NURBS sphere in the NURBS Book's circle form), went over as
// six B-spline pieces (split at the circle form's C0 knots) that the BOP check's face self-intersection search
// flagged; on OCCT's sphere it is one face again, as in FreeCAD, and clean at every placement. Analytic primitives
// off (the workbench's B-spline preference): the B-spline faces, exact, as before.
TEST(Topology, FacesTrimmedOnASphereGoOverOnOcctsSphere) {
    for (const gp_Pnt& centre : {gp_Pnt(0, 0, 0), gp_Pnt(0, -40, 0), gp_Pnt(100, 0, 0), gp_Pnt(1e4, 1e4, -1e4)}) {
        SCOPED_TRACE(centre.X() + centre.Y() + centre.Z());
        BRepAlgoAPI_Cut cut(BRepPrimAPI_MakeSphere(centre, 6).Shape(),
                            BRepPrimAPI_MakeBox(centre, 10, 10, 10).Shape());
        const Solid read = from_occt(cut.Shape());
        const TopoDS_Solid handed = to_occt(read);
        int spherical = 0, bspline = 0, circles = 0;
        for (TopExp_Explorer it(handed, TopAbs_FACE); it.More(); it.Next()) {
            const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(it.Current()));
            spherical += !Handle(Geom_SphericalSurface)::DownCast(surface).IsNull();
            bspline += !Handle(Geom_BSplineSurface)::DownCast(surface).IsNull();
            if (Handle(Geom_SphericalSurface)::DownCast(surface).IsNull()) continue;
            // Its rims and its seam on OCCT's circles, exact (exact_edges.hpp), as on FreeCAD's own.
            for (TopExp_Explorer edges(it.Current(), TopAbs_EDGE); edges.More(); edges.Next()) {
                double first = 0, last = 0;
                const TopoDS_Edge& edge = TopoDS::Edge(edges.Current());
                if (BRep_Tool::Degenerated(edge)) continue;
                EXPECT_TRUE(BRep_Tool::Curve(edge, first, last)->IsKind(STANDARD_TYPE(Geom_Circle)));
                circles += 1;
            }
        }
        EXPECT_EQ(spherical, 1);
        EXPECT_EQ(bspline, 0);
        EXPECT_EQ(circles, 5);  // three rims, the seam on both sides
        EXPECT_EQ(count(handed, TopAbs_FACE), 4);
        EXPECT_FALSE(bop_check_finds_faults(handed));
        const CheckReport report = check(read, CheckOptions{});
        EXPECT_TRUE(report.passed && report.bop_clean) << format_report(report);
        const FixedRule rule = fixed_rule(handed);
        EXPECT_LT(std::abs(rule.volume - read.volume()) / read.volume(), 1e-7);
        EXPECT_LT(std::abs(rule.area - read.area()) / read.area(), 1e-7);
        ConvertOptions bspline_faces;
        bspline_faces.analytic_primitives = false;
        for (TopExp_Explorer it(to_occt(read, bspline_faces), TopAbs_FACE); it.More(); it.Next())
            EXPECT_TRUE(Handle(Geom_SphericalSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(it.Current()))).IsNull());
    }
}

// Read faces on a short arc of a cylinder far from the origin (a 15 degree fillet 225 units out: the plain fit of the
// arc's centre was 5e-9 off, find_arc's refined fit is not) and on a spindle torus (minor radius above the major: a
// fillet OpenCASCADE reads as its torus) go back on OCCT's cylinder and torus (analytic_primitives.cpp), as
// OpenCASCADE reads them, valid and BOP-clean; both went over as B-splines.
TEST(Topology, ReadShortArcsAndSpindleToriGoBackOnOcctsSurfaces) {
    const std::vector<std::pair<TopoDS_Shape, GeomAbs_SurfaceType>> cases = {
        {BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(200, 0, -225), gp_Dir(0, 0, 1)), 3, 50, 0.27).Shape(), GeomAbs_Cylinder},
        {BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(10, 20, 30), gp_Dir(0, 0, 1)), 1.5, 2.5, -std::numbers::pi / 3, std::numbers::pi / 3,
                               std::numbers::pi / 2).Shape(),
         GeomAbs_Torus}};
    for (const auto& [shape, kind] : cases) {
        SCOPED_TRACE(kind);
        const Solid read = from_occt(shape);
        const TopoDS_Solid handed = to_occt(read);
        int found = 0, bspline = 0;
        for (TopExp_Explorer it(handed, TopAbs_FACE); it.More(); it.Next()) {
            const GeomAbs_SurfaceType type = BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType();
            found += type == kind;
            bspline += type == GeomAbs_BSplineSurface;
        }
        EXPECT_EQ(found, 1);
        EXPECT_EQ(bspline, 0);
        EXPECT_TRUE(BRepCheck_Analyzer(handed).IsValid());
        EXPECT_FALSE(bop_check_finds_faults(handed));
        EXPECT_LT(std::abs(fixed_rule(handed).volume - read.volume()) / read.volume(), 1e-6);
    }
}

// An edge between planes that runs at constant speed goes over on OCCT's line (exact_edges.hpp), as Part's edges
// are, its parameter scaled by its speed (check() maps it back); at any other pace it stays the kernel's B-spline.
TEST(Topology, EdgesBetweenPlanesGoOverOnOcctsLines) {
    const auto vertex = [](const Vec3& p) { return std::make_shared<const Vertex>(Vertex{p}); };
    const VertexPtr a = vertex({0, 0, 0}), b = vertex({4, 0, 0});
    const auto quadratic = [&](double middle, double weight) {
        return Edge{NurbsCurve(2, {0, 0, 0, 2, 2, 2}, {{0, 0, 0}, {4 * middle, 0, 0}, {4, 0, 0}}, {1, weight, 1}), a, b};
    };
    const double fit = 1e-11;
    EXPECT_TRUE(detail::runs_linearly(Edge{line_segment({0, 0, 0}, {4, 0, 0}), a, b}, fit));
    EXPECT_TRUE(detail::runs_linearly(quadratic(0.5, 1), fit));      // degree 2, evenly spaced
    EXPECT_FALSE(detail::runs_linearly(quadratic(0.3, 1), fit));     // the same segment at another pace
    EXPECT_FALSE(detail::runs_linearly(quadratic(0.5, 0.7), fit));   // rational: the pace varies
    EXPECT_TRUE(detail::is_segment(quadratic(0.3, 0.7), fit));       // ... on the same segment
    EXPECT_FALSE(detail::runs_linearly(Edge{arc(2, 0, 90, {0, 0, 0}), vertex({2, 0, 0}), vertex({0, 2, 0})}, fit));

    for (const gp_Pnt& corner : {gp_Pnt(0, 0, 0), gp_Pnt(1e4, -1e4, 3)}) {
        SCOPED_TRACE(corner.X());
        const Solid box = from_occt(BRepPrimAPI_MakeBox(corner, 3, 4, 5).Shape());
        const TopoDS_Solid handed = to_occt(box);
        int lines = 0;
        TopTools_IndexedMapOfShape edges;
        TopExp::MapShapes(handed, TopAbs_EDGE, edges);
        for (int i = 1; i <= edges.Extent(); ++i) {
            double first = 0, last = 0;
            lines += BRep_Tool::Curve(TopoDS::Edge(edges(i)), first, last)->IsKind(STANDARD_TYPE(Geom_Line));
        }
        EXPECT_EQ(lines, 12);
        EXPECT_TRUE(BRepCheck_Analyzer(handed).IsValid());
        EXPECT_FALSE(bop_check_finds_faults(handed));
        const CheckReport report = check(box, CheckOptions{});
        EXPECT_TRUE(report.passed && report.bop_clean) << format_report(report);
    }
}

// An arc of a circle on the rim of a face ruled toward a line goes over on OCCT's circle (circle_edges.hpp), its
// p-curve refitted to the angle: the ruled solid of a circle and a square (the FreeCAD test's) keeps its exact faces,
// reads as before and passes the checks, and OCCT's chamfer of a corner ruling, and of all its edges, is valid; with
// the rims as the kernel's rational arcs the one left a corner face of negative area, the other raised. So do the
// rims of a loft through a circle, a square and a circle; a cylinder ruled between two arcs goes over as OCCT's
// pipe; with analytic primitives off the rims stay B-splines.
TEST(Topology, ArcsBesideBsplineFacesGoOverOnOcctsCircles) {
    const Profile square({line_segment({1.5, -1.5, 4}, {1.5, 1.5, 4}), line_segment({1.5, 1.5, 4}, {-1.5, 1.5, 4}),
                          line_segment({-1.5, 1.5, 4}, {-1.5, -1.5, 4}), line_segment({-1.5, -1.5, 4}, {1.5, -1.5, 4})});
    const Solid ruled = loft({Profile({circle(2)}), square}, 3, true);
    const TopoDS_Solid handed = to_occt(ruled);
    EXPECT_TRUE(BRepCheck_Analyzer(handed).IsValid());
    EXPECT_FALSE(bop_check_finds_faults(handed));
    EXPECT_LT(std::abs(fixed_rule(handed).volume - ruled.volume()) / ruled.volume(), 1e-9);
    const CheckReport report = check(ruled, CheckOptions{});
    EXPECT_TRUE(report.passed && report.bop_clean) << format_report(report);
    // The rims on circles, each edge within the refit's tolerance; the ruling from (sqrt 2, sqrt 2, 0) to (1.5, 1.5, 4).
    int circles = 0;
    std::optional<TopoDS_Edge> ruling;
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(handed, TopAbs_EDGE, edges);
    for (int i = 1; i <= edges.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
        double first = 0, last = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
        if (curve.IsNull()) continue;
        circles += curve->IsKind(STANDARD_TYPE(Geom_Circle));
        EXPECT_LT(BRep_Tool::Tolerance(edge), 1e-6);
        const gp_Pnt a = curve->Value(first), b = curve->Value(last);
        const gp_Pnt bottom(std::sqrt(2.0), std::sqrt(2.0), 0), top(1.5, 1.5, 4);
        if ((a.Distance(bottom) < 1e-9 && b.Distance(top) < 1e-9) || (a.Distance(top) < 1e-9 && b.Distance(bottom) < 1e-9))
            ruling = edge;
    }
    EXPECT_GE(circles, 4);
    ASSERT_TRUE(ruling.has_value());
    BRepFilletAPI_MakeChamfer chamfer(handed);
    chamfer.Add(0.5, *ruling);
    chamfer.Build();
    ASSERT_TRUE(chamfer.IsDone());
    EXPECT_TRUE(BRepCheck_Analyzer(chamfer.Shape()).IsValid());
    EXPECT_LT(occt_volume(chamfer.Shape()), ruled.volume());
    BRepFilletAPI_MakeChamfer all(handed);
    for (int i = 1; i <= edges.Extent(); ++i) all.Add(0.5, TopoDS::Edge(edges(i)));
    all.Build();
    ASSERT_TRUE(all.IsDone());
    EXPECT_TRUE(BRepCheck_Analyzer(all.Shape()).IsValid());
    EXPECT_NEAR(ruled.volume() - occt_volume(all.Shape()), 4.1203, 0.02 * 4.1203);  // Part's ruled Loft: 4.1203

    // A loft through a circle, the square and a circle has its rims on circles too: its faces do not turn with them.
    // Part Chamfer of every edge at 0.2, and of the bottom rim at 0.02, works (with its rims as the kernel's arcs the
    // first came out invalid and the second raised; Chamfer of every edge worked at 23 of 49 sizes from 0.02 to 0.98,
    // 41 now: bench/freecad_edge_tool_sizes.py; Part's Loft, 30).
    const Solid through_square = loft({Profile({circle(2)}), square, Profile({circle(2, {0, 0, 8})})});
    const TopoDS_Solid loft_handed = to_occt(through_square);
    EXPECT_TRUE(BRepCheck_Analyzer(loft_handed).IsValid());
    EXPECT_FALSE(bop_check_finds_faults(loft_handed));
    EXPECT_LT(std::abs(fixed_rule(loft_handed).volume - through_square.volume()) / through_square.volume(), 1e-9);
    TopTools_IndexedMapOfShape loft_edges;
    TopExp::MapShapes(loft_handed, TopAbs_EDGE, loft_edges);
    BRepFilletAPI_MakeChamfer every_edge(loft_handed), bottom_rim(loft_handed);
    int rim_circles = 0;
    for (int i = 1; i <= loft_edges.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(loft_edges(i));
        double first = 0, last = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
        const bool on_circle = curve->IsKind(STANDARD_TYPE(Geom_Circle));
        rim_circles += on_circle;
        every_edge.Add(0.2, edge);
        if (on_circle && std::abs(curve->Value(first).Z()) < 1e-12) bottom_rim.Add(0.02, edge);
    }
    EXPECT_EQ(rim_circles, 8);  // a quarter of each rim per side face
    for (BRepFilletAPI_MakeChamfer* chamfer : {&every_edge, &bottom_rim}) {
        chamfer->Build();
        ASSERT_TRUE(chamfer->IsDone());
        EXPECT_TRUE(BRepCheck_Analyzer(chamfer->Shape()).IsValid());
        EXPECT_LT(occt_volume(chamfer->Shape()), through_square.volume());
    }
    // A cylinder ruled between two circles (without its record, as a file's) is a tube along a line, and goes over as
    // OCCT's pipe: its cylinder and planes, as Part's ruled Loft of two circles is a cylinder (swept_solids.hpp).
    std::multiset<GeomAbs_SurfaceType> types;
    for (TopExp_Explorer it(to_occt(loft({Profile({circle(2)}), Profile({circle(2, {0, 0, 4})})}, 3, true)), TopAbs_FACE);
         it.More(); it.Next())
        types.insert(BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType());
    EXPECT_EQ(types, (std::multiset<GeomAbs_SurfaceType>{GeomAbs_Plane, GeomAbs_Plane, GeomAbs_Cylinder}));

    ConvertOptions bspline;
    bspline.analytic_primitives = false;
    for (TopExp_Explorer it(to_occt(ruled, bspline), TopAbs_EDGE); it.More(); it.Next()) {
        double first = 0, last = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(TopoDS::Edge(it.Current()), first, last);
        EXPECT_TRUE(curve.IsNull() || !curve->IsKind(STANDARD_TYPE(Geom_Circle)));
    }
}

// An arc from the circle's own start runs from 0, as OCCT's arcs do: where the start's angle rounded to 2 pi
// (atan2 of -1e-17), the arc ran over [2 pi, 8 pi / 3], and OCCT's fillet of the ruled circle -> triangle, all its
// edges at 0.4, took 8 s and came out "BOPAlgo GeomAbs_C0" (Part's Loft: 0.1 s, clean); from 0: 0.2 s and clean.
TEST(Topology, ArcsOnOcctsCirclesStartWhereTheCircleStarts) {
    const auto corner = [](double degrees) {
        return Vec3{2.5 * std::cos(degrees * std::numbers::pi / 180), 2.5 * std::sin(degrees * std::numbers::pi / 180), 4};
    };
    const Profile triangle({line_segment(corner(0), corner(120)), line_segment(corner(120), corner(240)),
                            line_segment(corner(240), corner(0))});
    const Solid ruled = loft({Profile({circle(2)}), triangle}, 3, true);
    const TopoDS_Solid handed = to_occt(ruled);
    int circles = 0;
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(handed, TopAbs_EDGE, edges);
    BRepFilletAPI_MakeFillet fillet(handed);
    for (int i = 1; i <= edges.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
        double first = 0, last = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
        if (curve.IsNull()) continue;
        fillet.Add(0.4, edge);
        if (!curve->IsKind(STANDARD_TYPE(Geom_Circle))) continue;
        ++circles;
        EXPECT_GE(first, 0);
        EXPECT_LT(first, 2 * std::numbers::pi - 1e-6);
        EXPECT_LE(last, 2 * std::numbers::pi + 1e-12);
    }
    EXPECT_EQ(circles, 3);
    fillet.Build();
    ASSERT_TRUE(fillet.IsDone());
    EXPECT_TRUE(BRepCheck_Analyzer(fillet.Shape()).IsValid());
    EXPECT_FALSE(bop_check_finds_faults(fillet.Shape()));
    EXPECT_NEAR(occt_volume(fillet.Shape()), 40.5503, 1e-3);  // Part's Loft: 40.8101 on its other surface
}

// The other side of the same cut: the octant of the sphere inside the box (OCCT's Common; what OCCT's STEP reader,
// FreeCAD's too, makes of FreeCAD's own STEP file of the sphere minus a box at (0, -40, 0)). Its face's rims lie on
// the sphere's seam, where ShapeFix_Face projected OCCT's circles onto the wrong side and took the face for the
// other seven octants; the rebuild then goes with the kernel's arcs (elementary_faces.cpp), still one spherical face.
TEST(Topology, AnOctantOfASphereGoesOverOnOcctsSphere) {
    for (const gp_Pnt& centre : {gp_Pnt(0, 0, 0), gp_Pnt(0, -40, 0), gp_Pnt(3, -40, 0), gp_Pnt(100, 0, 0)}) {
        SCOPED_TRACE(centre.X() + centre.Y() + centre.Z());
        BRepAlgoAPI_Common common(BRepPrimAPI_MakeSphere(centre, 6).Shape(), BRepPrimAPI_MakeBox(centre, 10, 10, 10).Shape());
        const Solid read = from_occt(common.Shape());
        EXPECT_NEAR(read.volume(), std::numbers::pi * 36, 1e-9 * read.volume());  // 4/3 pi r^3 / 8
        const TopoDS_Solid handed = to_occt(read);
        int spherical = 0;
        for (TopExp_Explorer it(handed, TopAbs_FACE); it.More(); it.Next())
            spherical += !Handle(Geom_SphericalSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(it.Current()))).IsNull();
        EXPECT_EQ(spherical, 1);
        EXPECT_EQ(count(handed, TopAbs_FACE), 4);
        EXPECT_FALSE(bop_check_finds_faults(handed));
        EXPECT_LT(std::abs(fixed_rule(handed).volume - read.volume()) / read.volume(), 1e-7);
    }
}

TEST(Topology, BezierFacesCutEachFaceAtItsKnots) {
    // A sphere: 4 quarter circles around, 2 along the meridian: 8 patches, the seam and the equator cut
    // into pieces, one degenerate edge per pole patch; the caps of a cylinder stay one plane each.
    const ConvertedSolid ball = convert(sphere(1), ConvertOptions{true});
    EXPECT_EQ(ball.faces.size(), 8u);
    int degenerated = 0;
    for (TopExp_Explorer it(ball.solid, TopAbs_EDGE); it.More(); it.Next())
        degenerated += BRep_Tool::Degenerated(TopoDS::Edge(it.Current())) ? 1 : 0;
    EXPECT_EQ(degenerated, 8);
    EXPECT_EQ(count(ball.solid, TopAbs_VERTEX), 2 + 4);  // poles, and the equator's four quarter points
    const Solid drum = cylinder(1, 2);
    const ConvertedSolid converted = convert(drum, ConvertOptions{true});
    EXPECT_EQ(converted.faces.size(), 4u + 2u);
    EXPECT_EQ(converted.first_face, (std::vector<std::size_t>{0, 4, 5, 6}));
    for (const auto& [edge, pieces] : converted.edges) EXPECT_EQ(pieces.size(), edge->curve.knots().size() > 4 ? 4u : 1u);
}

}  // namespace
}  // namespace ratbez::occt

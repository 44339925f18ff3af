// Every model of the corpus (tests/corpus/freecad: FreeCAD's booleans, fillets, chamfers, PartDesign features,
// lofts, sweeps, primitives, compounds and the solids of the .fcstd files FreeCAD ships, made by make_corpus.py)
// and every STEP part FreeCAD ships in its Idf library, read as a user's model (issue 24):
//  - every solid converts, and the volume agrees with OpenCASCADE's BRepGProp at epsilon 1e-11 on the file's own
//    shapes to 1e-6 (or to area x the file's tolerance, where the file's edges sit that far off their faces);
//    each passes occt::check (`ratbez check`);
//  - its mesh at the default tolerance is CGAL-clean (closed, 2-manifold, outward, no self-intersection) and within
//    the tolerance both ways, measured (mesh to surface and surface to mesh);
//  - the STEP ratbez writes of it reads back as the same solids, valid for BRepCheck;
//  - at a deflection of 1e-3 of its size it meshes in no more triangles than OpenCASCADE's BRepMesh at the same
//    deflection (issue 24's target; bench/tessellation_bench.cpp times both and measures their deviations).

#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <Bnd_Box.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IMeshTools_Parameters.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeFix_Solid.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS_Shape.hxx>
#include <Poly_Triangulation.hxx>
#include <TopLoc_Location.hxx>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <optional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "build_paths.hpp"
#include "occt_test_support.hpp"
#include "ratbez/deviation.hpp"
#include "ratbez/export/export.hpp"
#include "ratbez/export/mesh_checks.hpp"
#include "ratbez/occt/check.hpp"
#include "ratbez/occt/files.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/tessellate.hpp"

namespace {

namespace fs = std::filesystem;
using namespace ratbez;

bool is_brep(const fs::path& file) { return file.extension() == ".brep"; }

// The corpus files, then FreeCAD's Idf parts where FreeCAD is installed; sorted, so the test names are stable.
std::vector<fs::path> model_files() {
    std::vector<fs::path> files;
    for (const fs::path& dir : {fs::path(ratbez::build_paths::corpus_dir), fs::path("/usr/share/freecad/Mod/Idf/Idflibs")}) {
        std::error_code ignored;
        std::vector<fs::path> here;
        for (const auto& entry : fs::directory_iterator(dir, ignored)) {
            const std::string ext = entry.path().extension().string();
            if (ext == ".step" || ext == ".stp" || ext == ".brep") here.push_back(entry.path());
        }
        std::sort(here.begin(), here.end());
        files.insert(files.end(), here.begin(), here.end());
    }
    return files;
}

// The file as OpenCASCADE reads it, without ratbez.
TopoDS_Shape occt_shape(const fs::path& file) {
    if (is_brep(file)) {
        TopoDS_Shape shape;
        BRep_Builder builder;
        EXPECT_TRUE(BRepTools::Read(shape, file.c_str(), builder)) << file;
        return shape;
    }
    STEPControl_Reader reader;
    EXPECT_EQ(reader.ReadFile(file.c_str()), IFSelect_RetDone) << file;
    reader.TransferRoots();
    return reader.OneShape();
}

// OpenCASCADE's volume of the file's solids by Gauss integration to a relative error of 1e-11. A surface model
// (faces in shells, no solid entity: SOD_323, SOT23) has no volume in OpenCASCADE until sewn: its faces are sewn
// and each closed shell oriented as a solid, the OpenCASCADE way (BRepBuilderAPI_Sewing, ShapeFix_Solid); an
// open shell bounds no volume (SOD_323's leads miss faces: ratbez leaves them out too).
double occt_volume(const TopoDS_Shape& shape) {
    TopoDS_Shape solids = shape;
    if (!TopExp_Explorer(shape, TopAbs_SOLID).More()) {
        Bnd_Box box;
        BRepBndLib::Add(shape, box);
        BRepBuilderAPI_Sewing sewing(1e-6 * std::sqrt(box.SquareExtent()));
        sewing.Add(shape);
        sewing.Perform();
        TopoDS_Compound compound;
        BRep_Builder builder;
        builder.MakeCompound(compound);
        for (TopExp_Explorer it(sewing.SewedShape(), TopAbs_SHELL); it.More(); it.Next())
            if (BRep_Tool::IsClosed(it.Current()))
                builder.Add(compound, ShapeFix_Solid().SolidFromShell(TopoDS::Shell(it.Current())));
        solids = compound;
    }
    double volume = 0;
    for (TopExp_Explorer it(solids, TopAbs_SOLID); it.More(); it.Next()) {
        GProp_GProps props;
        BRepGProp::VolumeProperties(it.Current(), props, 1e-11);
        volume += props.Mass();
    }
    return volume;
}

double max_face_tolerance(const Solid& solid) {
    double tolerance = 0;
    for (const Face& face : solid.faces()) tolerance = std::max(tolerance, face.tolerance());
    return tolerance;
}

// The file whose OpenCASCADE reading is the reference: a STEP file's .brep sibling where FreeCAD wrote both
// (make_corpus.py), the same solids in OpenCASCADE's own format. OpenCASCADE's STEP reader turns a face bound that
// it cannot tell the sides of (sphere_minus_box_off_axis: read as the eighth of the sphere in the box; ratbez reads
// the bounds as written, files.cpp), so its reading of the STEP file is no reference there.
fs::path reference_file(const fs::path& file) {
    fs::path brep = file;
    brep.replace_extension(".brep");
    return !is_brep(file) && fs::exists(brep) ? brep : file;
}

std::vector<Solid> read_all(const fs::path& file) {
    return is_brep(file) ? occt::read_brep_all(file.string()) : occt::read_step_all(file.string());
}

class CorpusModel : public ::testing::TestWithParam<fs::path> {};

TEST_P(CorpusModel, ReadsWithOpenCascadesVolumeAndPassesItsCheck) {
    const std::vector<Solid> solids = read_all(GetParam());
    ASSERT_FALSE(solids.empty());
    double volume = 0, area_times_tolerance = 0;
    for (const Solid& solid : solids) {
        volume += solid.volume();
        area_times_tolerance += solid.area() * max_face_tolerance(solid);
    }
    const double reference = occt_volume(occt_shape(reference_file(GetParam())));
    // A face trimmed by p-curves a file tolerance t off its edges moves the boundary by up to t: the volume by up
    // to area x t. Exact files (t ~ 1e-7) are held to the 1e-6 of issue 24.
    const double bound = std::max(1e-6 * reference, area_times_tolerance);
    EXPECT_NEAR(volume, reference, bound) << solids.size() << " solids; relative difference "
                                          << std::abs(volume - reference) / reference;
    // `ratbez check` of each solid: converted back, valid for BRepCheck, its evaluations, volume and area
    // OpenCASCADE's within the file's tolerance (check.hpp), and OpenCASCADE's BOP argument analysis (on the STEP
    // files, which hold the .brep files' solids: it is the check's slowest part) finds nothing: no C0 geometry
    // (the check runs on the solid as handed out, faces still C0 inside split there; issue 25: it checked the
    // unsplit one and flagged 12 models), no self-intersection, no small edge.
    // sphere_minus_box's face trimmed on a sphere with a pole drew "BOPAlgo SelfIntersect" as a B-spline; it goes
    // over on OCCT's sphere now (elementary_faces.hpp), as the whole sphere part_sphere goes over as OCCT's own.
    occt::CheckOptions options;
    options.bop_analysis = !is_brep(GetParam());
    for (const Solid& solid : solids) {
        const occt::CheckReport report = occt::check(solid, options);
        for (const std::string& failure : report.failures) ADD_FAILURE() << solid.name() << ": " << failure;
        EXPECT_TRUE(report.valid && report.closed) << solid.name();
        EXPECT_EQ(report.self_intersections, 0) << solid.name();
        EXPECT_EQ(report.small_edges, 0) << solid.name();
    }
}

TEST_P(CorpusModel, MeshesWithinToleranceBothWaysCgalClean) {
    for (const Solid& solid : read_all(GetParam())) {
        SCOPED_TRACE(solid.name().empty() ? std::string("(unnamed solid)") : solid.name());
        const double tolerance = default_tolerance(solid);
        TessellationOptions options;
        options.tolerance = tolerance;
        const Mesh mesh = exporter::tessellate_for_export(solid, options);
        const exporter::MeshReport report = exporter::check_mesh(mesh, exporter::tessellation_checks(solid, mesh, tolerance));
        for (const std::string& problem : report.problems) ADD_FAILURE() << problem;
        EXPECT_EQ(report.self_intersection_free, std::optional<bool>(true));
        EXPECT_LE(max_deviation(solid, mesh), tolerance);
        EXPECT_LE(max_surface_to_mesh_distance(solid, mesh), tolerance);
    }
}

// BRepMesh's triangles of every solid of the file at the deflection (the bench's parameters: angle 0.5 rad).
std::size_t brepmesh_triangles(const TopoDS_Shape& shape, double deflection) {
    IMeshTools_Parameters parameters;
    parameters.Deflection = deflection;
    parameters.Angle = 0.5;
    parameters.Relative = Standard_False;
    parameters.InParallel = Standard_False;
    std::size_t triangles = 0;
    for (TopExp_Explorer solids(shape, TopAbs_SOLID); solids.More(); solids.Next()) {
        BRepTools::Clean(solids.Current());
        BRepMesh_IncrementalMesh mesher(solids.Current(), parameters);
        for (TopExp_Explorer faces(solids.Current(), TopAbs_FACE); faces.More(); faces.Next()) {
            TopLoc_Location location;
            const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(TopoDS::Face(faces.Current()), location);
            if (!triangulation.IsNull()) triangles += static_cast<std::size_t>(triangulation->NbTriangles());
        }
    }
    return triangles;
}

TEST_P(CorpusModel, MeshesInNoMoreTrianglesThanBRepMeshAtItsDeflection) {
    const std::vector<Solid> solids = read_all(GetParam());
    const TopoDS_Shape shape = occt_shape(reference_file(GetParam()));
    std::size_t shapes = 0;
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) ++shapes;
    if (shapes != solids.size())
        GTEST_SKIP() << "OpenCASCADE holds " << shapes << " solids, ratbez " << solids.size() << ": a surface model ratbez sews";
    double size = 0;
    for (const Solid& solid : solids) size = std::max(size, solid.bounding_box().diagonal());
    const double deflection = 1e-3 * size;
    std::size_t ours = 0;
    for (const Solid& solid : solids) {
        const Mesh mesh = tessellate(solid, deflection);
        EXPECT_LE(max_deviation(solid, mesh), deflection) << solid.name();
        ours += mesh.triangles.size();
    }
    EXPECT_LE(ours, brepmesh_triangles(shape, deflection)) << "at deflection " << deflection;
}

TEST_P(CorpusModel, RoundTripsThroughStep) {
    const std::vector<Solid> solids = read_all(GetParam());
    // Named after the whole file name and the process: x.brep and x.step run side by side under ctest -j.
    const fs::path written = fs::temp_directory_path() /
                             ("ratbez_corpus_" + GetParam().filename().string() + "_" + std::to_string(getpid()) + ".step");
    occt::write_step(solids, written.string());
    const std::vector<Solid> back = occt::read_step_all(written.string());
    ASSERT_EQ(back.size(), solids.size());
    for (std::size_t i = 0; i < solids.size(); ++i) {
        // Exact to 1e-9; a face whose p-curves were fitted (to 1e-3 of the file's tolerance t, pcurve_fit.hpp)
        // may be fitted again on the way back: up to area x 1e-3 t.
        const double bound = std::max(1e-9 * std::abs(solids[i].volume()), 1e-3 * solids[i].area() * max_face_tolerance(solids[i]));
        EXPECT_NEAR(back[i].volume(), solids[i].volume(), bound);
        EXPECT_EQ(back[i].name(), solids[i].name());
        EXPECT_TRUE(BRepCheck_Analyzer(occt::to_occt(back[i])).IsValid()) << "solid " << i;
    }
    fs::remove(written);
}

// What the files hold (occt::to_occt) is read right by OpenCASCADE's fixed Gauss rule, what FreeCAD's Shape.Volume
// and Area use: no face left C0 inside (a face trimmed on a cylinder, cone or sphere is split at its surface's
// C0 knots, kernel/occt/src/c0_split.hpp; whole, FreeCAD's sphere_minus_box read 2.5e-3 off in area), to 1e-6; a
// solid whose faces go back on the file's own cylinders, cones and tori (elementary_faces.hpp) to within 4 times
// the rule's error on OpenCASCADE's reading of the file itself (18 points across such a face: cylinder_cut_cylinder
// 3.5e-6 ours, 1.6e-6 its own), and to issue 25's 1e-4 in any case.
TEST_P(CorpusModel, WrittenSolidsAreReadRightByTheFixedRule) {
    const std::vector<Solid> solids = read_all(GetParam());
    // The rule's relative error on OpenCASCADE's own reading of the file, over all its solids.
    double exact_volume = 0, exact_area = 0;
    for (const Solid& solid : solids) exact_volume += solid.volume(), exact_area += solid.area();
    GProp_GProps own_volume, own_area;
    const TopoDS_Shape own = occt_shape(reference_file(GetParam()));
    for (TopExp_Explorer it(own, TopAbs_SOLID); it.More(); it.Next()) {
        BRepGProp::VolumeProperties(it.Current(), own_volume);
        BRepGProp::SurfaceProperties(it.Current(), own_area);
    }
    const bool own_solids = TopExp_Explorer(own, TopAbs_SOLID).More();
    const double own_volume_error = own_solids ? std::abs(own_volume.Mass() - exact_volume) / exact_volume : 0;
    const double own_area_error = own_solids ? std::abs(own_area.Mass() - exact_area) / exact_area : 0;
    for (const Solid& solid : solids) {
        SCOPED_TRACE(solid.name());
        const TopoDS_Solid shape = occt::to_occt(solid);
        EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
        for (TopExp_Explorer faces(shape, TopAbs_FACE); faces.More(); faces.Next())
            EXPECT_NE(BRep_Tool::Surface(TopoDS::Face(faces.Current()))->Continuity(), GeomAbs_C0);
        GProp_GProps volume, area;
        BRepGProp::VolumeProperties(shape, volume);
        BRepGProp::SurfaceProperties(shape, area);
        // Exact files as above; as against OpenCASCADE's reading of the file above, a face trimmed by p-curves a
        // file tolerance t off its edges may move its boundary by t: the volume by up to area x t, the area by up
        // to its boundary's length x t, bounded here by area / size x t.
        const double t = max_face_tolerance(solid), size = solid.bounding_box().diagonal();
        const double volume_rule = std::max(1e-6, 4 * own_volume_error), area_rule = std::max(1e-6, 4 * own_area_error);
        EXPECT_NEAR(volume.Mass(), solid.volume(), std::max(volume_rule * solid.volume(), solid.area() * t));
        EXPECT_NEAR(area.Mass(), solid.area(), std::max(area_rule * solid.area(), solid.area() / size * t));
        EXPECT_LT(std::abs(volume.Mass() - solid.volume()), std::max(1e-4 * solid.volume(), solid.area() * t));
        EXPECT_LT(std::abs(area.Mass() - solid.area()), std::max(1e-4 * solid.area(), solid.area() / size * t));
    }
}

// The surface kinds of the file's faces, as OpenCASCADE reads them (planes, cylinders, cones, spheres, tori...).
std::multiset<GeomAbs_SurfaceType> surface_kinds(const TopoDS_Shape& shape) {
    std::multiset<GeomAbs_SurfaceType> kinds;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next())
        kinds.insert(BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType());
    return kinds;
}

// A read solid goes back to OpenCASCADE (files, FreeCAD) with its faces on the file's own cylinders, cones,
// spheres and tori (elementary_faces.hpp), not as the B-splines the kernel holds them as: OCCT's BOP check and
// booleans of B-spline faces are far slower (a real bracket, 030_bmg_astrosyn_mount.step: FreeCAD's BOP check
// 166 s, 4.2 s with its faces on cylinders, cones and tori; OpenCASCADE's own reading, 1.8 s).
TEST(CorpusModels, ReadFacesGoBackOnTheFilesElementarySurfaces) {
    for (const char* name :
         {"cylinder_cut_cylinder", "fused_cylinders", "cone_fillet", "filleted_box", "box_with_hole", "partdesign_pocket_hole"}) {
        SCOPED_TRACE(name);
        const fs::path file = fs::path(ratbez::build_paths::corpus_dir) / (std::string(name) + ".step");
        const std::vector<Solid> solids = read_all(file);
        ASSERT_EQ(solids.size(), 1u);
        const TopoDS_Solid handed = occt::to_occt(solids.front());
        EXPECT_TRUE(BRepCheck_Analyzer(handed).IsValid());
        EXPECT_EQ(surface_kinds(handed), surface_kinds(occt_shape(file)));
        EXPECT_FALSE(occt::testing::bop_check_finds_faults(handed));
    }
}

// The number of each of OpenCASCADE's elementary surfaces (planes, cylinders, cones, spheres, tori) among the faces.
std::map<GeomAbs_SurfaceType, int> elementary_kinds(const TopoDS_Shape& shape) {
    std::map<GeomAbs_SurfaceType, int> kinds;
    for (const GeomAbs_SurfaceType kind : surface_kinds(shape))
        if (kind == GeomAbs_Plane || kind == GeomAbs_Cylinder || kind == GeomAbs_Cone || kind == GeomAbs_Sphere || kind == GeomAbs_Torus)
            ++kinds[kind];
    return kinds;
}

// Every face of the corpus's STEP files (FreeCAD's own models) that OpenCASCADE reads on a plane, cylinder, cone,
// sphere or torus goes back on one (extrusions and revolutions of B-splines stay B-splines). FreeCAD's drilled plate
// kept 3 of its 27 cylinders as B-splines until the p-curves ShapeFix projected 0.003 to 0.015 off them were fitted
// again, and a PartDesign pocket its drill point's cone (run a little past its apex) and the cylinder beside it (a
// rough face, in three patches) until those were recognised and taken whole (elementary_faces.cpp). Not FreeCAD's
// Idf parts from other systems: some of their B-spline faces are exact cylinders and spheres, which go back so too.
// And where a plane meets a cylinder, the edge is OCCT's line, circle or ellipse, as OpenCASCADE reads it: the
// drilled plate's slanted holes kept the kernel's rational ellipses (C0 at their knots by multiplicity), cut up
// by the C0 split (elementary_faces.cpp's analytic_edges).
TEST(CorpusModels, ElementaryFacesGoBackOnTheirOwnSurfaces) {
    for (const fs::path& file : model_files()) {
        if (file.parent_path() != fs::path(ratbez::build_paths::corpus_dir) || file.extension() != ".step") continue;
        SCOPED_TRACE(file.filename().string());
        std::map<GeomAbs_SurfaceType, int> ours;
        for (const Solid& solid : read_all(file)) {
            const TopoDS_Solid handed = occt::to_occt(solid);
            for (const auto& [kind, count] : elementary_kinds(handed)) ours[kind] += count;
            TopTools_IndexedDataMapOfShapeListOfShape faces_of;
            TopExp::MapShapesAndUniqueAncestors(handed, TopAbs_EDGE, TopAbs_FACE, faces_of);
            for (int i = 1; i <= faces_of.Extent(); ++i) {
                std::multiset<GeomAbs_SurfaceType> beside;
                for (const TopoDS_Shape& face : faces_of(i)) beside.insert(BRepAdaptor_Surface(TopoDS::Face(face)).GetType());
                if (beside != std::multiset<GeomAbs_SurfaceType>{GeomAbs_Plane, GeomAbs_Cylinder}) continue;
                const GeomAbs_CurveType curve = BRepAdaptor_Curve(TopoDS::Edge(faces_of.FindKey(i))).GetType();
                EXPECT_TRUE(curve == GeomAbs_Line || curve == GeomAbs_Circle || curve == GeomAbs_Ellipse) << "an edge of kind " << curve;
            }
        }
        EXPECT_EQ(ours, elementary_kinds(occt_shape(reference_file(file))));
    }
}

// "box_with_hole_step", "Idf_SOT23_stp": FreeCAD's shipped parts are told apart from the corpus.
std::string test_name(const ::testing::TestParamInfo<fs::path>& info) {
    std::string name = (info.param.parent_path().filename() == "Idflibs" ? "Idf_" : "") + info.param.filename().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Files, CorpusModel, ::testing::ValuesIn(model_files()), test_name);

}  // namespace

// OCCT's ThruSections and MakePipeShell on ratbez input; see reference_modelling.hpp.

#include "ratbez/occt/reference_modelling.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepOffsetAPI_MakePipeShell.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <string>

#include "ratbez/error.hpp"
#include "ratbez/occt/geometry.hpp"

namespace ratbez::occt {

TopoDS_Wire to_occt_wire(const std::vector<NurbsCurve>& pieces) {
    BRepBuilderAPI_MakeWire wire;
    for (const NurbsCurve& piece : pieces) wire.Add(BRepBuilderAPI_MakeEdge(to_occt(piece)).Edge());
    require(wire.IsDone(), "profile", "OCCT could not make a wire of its pieces");
    return wire.Wire();
}

TopoDS_Shape thru_sections(const std::vector<Profile>& profiles, bool ruled) {
    try {
        BRepOffsetAPI_ThruSections loft(Standard_True, ruled ? Standard_True : Standard_False);
        for (const Profile& p : profiles) loft.AddWire(to_occt_wire(p.pieces()));
        loft.Build();
        require(loft.IsDone(), "profiles", "BRepOffsetAPI_ThruSections failed");
        return loft.Shape();
    } catch (const Standard_Failure& e) {
        throw Error("profiles", std::string("BRepOffsetAPI_ThruSections raised ") + e.GetMessageString());
    }
}

TopoDS_Shape pipe_shell(const Profile& profile, const NurbsCurve& path, double tolerance) {
    try {
        BRepOffsetAPI_MakePipeShell pipe(to_occt_wire({path}));
        pipe.SetMode(Standard_False);  // CorrectedFrenet
        pipe.SetTolerance(tolerance, tolerance, 1e-2);
        pipe.Add(to_occt_wire(profile.pieces()));
        pipe.Build();
        require(pipe.IsDone(), "path", "BRepOffsetAPI_MakePipeShell failed");
        require(pipe.MakeSolid(), "path", "BRepOffsetAPI_MakePipeShell could not make a solid");
        return pipe.Shape();
    } catch (const Standard_Failure& e) {
        throw Error("path", std::string("BRepOffsetAPI_MakePipeShell raised ") + e.GetMessageString());
    }
}

ShapeFacts shape_facts(const TopoDS_Shape& shape) {
    ShapeFacts facts;
    facts.valid = BRepCheck_Analyzer(shape).IsValid();
    GProp_GProps properties;
    BRepGProp::VolumeProperties(shape, properties, 1e-9);
    facts.volume = properties.Mass();
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(it.Current()));
        const Handle(Geom_BSplineSurface) bspline = Handle(Geom_BSplineSurface)::DownCast(surface);
        if (!bspline.IsNull()) facts.control_points += static_cast<long>(bspline->NbUPoles()) * bspline->NbVPoles();
    }
    return facts;
}

long control_points(const Solid& solid) {
    long count = 0;
    for (const Face& face : solid.faces())
        if (face.kind() == Face::Kind::surface) count += static_cast<long>(face.surface().rows()) * face.surface().columns();
    return count;
}

}  // namespace ratbez::occt

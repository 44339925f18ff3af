// Faces split at C0 knots (see c0_split.hpp).

#include "c0_split.hpp"

#include <BRepCheck_Analyzer.hxx>
#include <BRepLib.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <ShapeUpgrade_ShapeDivideContinuity.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

namespace ratbez::occt::detail {
namespace {

bool has_c0_face(const TopoDS_Solid& solid) {
    for (TopExp_Explorer faces(solid, TopAbs_FACE); faces.More(); faces.Next()) {
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(faces.Current()));
        if (!surface.IsNull() && surface->Continuity() == GeomAbs_C0) return true;
    }
    return false;
}

}  // namespace

TopoDS_Solid split_at_c0_knots(const TopoDS_Solid& solid) {
    if (!has_c0_face(solid)) return solid;
    try {
        ShapeUpgrade_ShapeDivideContinuity divide(solid);
        divide.SetBoundaryCriterion(GeomAbs_C1);
        divide.SetPCurveCriterion(GeomAbs_C1);
        divide.SetSurfaceCriterion(GeomAbs_C1);
        if (!divide.Perform()) return solid;
        TopoDS_Shape result = divide.Result();
        // The new edges along the knot lines come without SameParameter: computed here, they make the
        // pieces valid (BRepCheck flagged every split face before).
        BRepLib::SameParameter(result, BRep_Tool::MaxTolerance(solid, TopAbs_EDGE), Standard_True);
        if (result.ShapeType() != TopAbs_SOLID || !BRepCheck_Analyzer(result).IsValid()) return solid;
        return TopoDS::Solid(result);
    } catch (const Standard_Failure&) {
        return solid;
    }
}

}  // namespace ratbez::occt::detail

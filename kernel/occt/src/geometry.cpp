// Conversions between ratbez geometry and OCCT's Geom classes (see geometry.hpp for the conventions).

#include "ratbez/occt/geometry.hpp"

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <cmath>
#include <string>
#include <vector>

#include "ratbez/error.hpp"

namespace ratbez::occt {
namespace {

// A flat knot vector as OCCT's distinct knots and multiplicities. Grouping by exact equality keeps the
// conversion lossless: expanding the result reproduces `flat` bit for bit.
struct DistinctKnots {
    TColStd_Array1OfReal knots;
    TColStd_Array1OfInteger multiplicities;
};

DistinctKnots distinct_knots(const std::vector<double>& flat) {
    std::vector<double> values;
    std::vector<int> counts;
    for (double k : flat) {
        if (!values.empty() && values.back() == k) {
            ++counts.back();
        } else {
            values.push_back(k);
            counts.push_back(1);
        }
    }
    DistinctKnots out{TColStd_Array1OfReal(1, static_cast<int>(values.size())),
                      TColStd_Array1OfInteger(1, static_cast<int>(values.size()))};
    for (std::size_t i = 0; i < values.size(); ++i) {
        out.knots.SetValue(static_cast<int>(i) + 1, values[i]);
        out.multiplicities.SetValue(static_cast<int>(i) + 1, counts[i]);
    }
    return out;
}

std::vector<double> to_vector(const TColStd_Array1OfReal& array) {
    std::vector<double> out;
    out.reserve(static_cast<std::size_t>(array.Length()));
    for (int i = array.Lower(); i <= array.Upper(); ++i) out.push_back(array.Value(i));
    return out;
}

// OCCT's flat knot sequence, made non-decreasing where rounding made a knot dip below its predecessor:
// OCCT keeps distinct knots apart only by its own Epsilon, and files written with 12 digits (STEP) or
// SetNotPeriodic's arithmetic leave a knot 1e-15 below the one before it, which OCCT tolerates and our
// validation (rightly, for user input) does not. A dip larger than 1e-12 of the knot vector's span is
// left for the validation to report.
std::vector<double> knot_sequence(const TColStd_Array1OfReal& array) {
    std::vector<double> knots = to_vector(array);
    const double span = knots.empty() ? 0 : std::abs(knots.back() - knots.front());
    for (std::size_t k = 1; k < knots.size(); ++k)
        if (knots[k] < knots[k - 1] && knots[k - 1] - knots[k] <= 1e-12 * span) knots[k] = knots[k - 1];
    return knots;
}

void require_degree(int degree, int max_degree, const std::string& argument) {
    require(degree >= 1, argument,
            "degree " + std::to_string(degree) + " cannot be represented in OpenCASCADE (it needs degree >= 1)");
    require(degree <= max_degree, argument,
            "degree " + std::to_string(degree) + " exceeds OpenCASCADE's maximum degree " +
                std::to_string(max_degree));
}

// OCCT validates its input again (strictly increasing distinct knots beyond Epsilon, multiplicities,
// weights > gp::Resolution()); translate its exceptions into ours so callers see one error type.
template <class Make>
auto guarded(const std::string& argument, Make&& make) {
    try {
        return make();
    } catch (const Standard_Failure& failure) {
        const char* message = failure.GetMessageString();
        throw Error(argument, std::string("OpenCASCADE rejected the geometry (") + failure.DynamicType()->Name() +
                    (message && *message ? std::string(": ") + message : std::string()) + ")");
    }
}

TColgp_Array1OfPnt poles_of(const std::vector<Vec3>& points) {
    TColgp_Array1OfPnt poles(1, static_cast<int>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) poles.SetValue(static_cast<int>(i) + 1, to_occt_point(points[i]));
    return poles;
}

TColStd_Array1OfReal weights_of(const std::vector<double>& weights) {
    TColStd_Array1OfReal out(1, static_cast<int>(weights.size()));
    for (std::size_t i = 0; i < weights.size(); ++i) out.SetValue(static_cast<int>(i) + 1, weights[i]);
    return out;
}

TColgp_Array2OfPnt poles_of(const std::vector<std::vector<Vec3>>& net) {
    const int rows = static_cast<int>(net.size());
    const int columns = static_cast<int>(net.front().size());
    TColgp_Array2OfPnt poles(1, rows, 1, columns);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j)
            poles.SetValue(i + 1, j + 1, to_occt_point(net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]));
    return poles;
}

TColStd_Array2OfReal weights_of(const std::vector<std::vector<double>>& weights) {
    const int rows = static_cast<int>(weights.size());
    const int columns = static_cast<int>(weights.front().size());
    TColStd_Array2OfReal out(1, rows, 1, columns);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j)
            out.SetValue(i + 1, j + 1, weights[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
    return out;
}

std::vector<Vec3> points_of(const TColgp_Array1OfPnt& poles) {
    std::vector<Vec3> out;
    out.reserve(static_cast<std::size_t>(poles.Length()));
    for (int i = poles.Lower(); i <= poles.Upper(); ++i) out.push_back(from_occt(poles.Value(i)));
    return out;
}

std::vector<std::vector<Vec3>> net_of(const TColgp_Array2OfPnt& poles) {
    std::vector<std::vector<Vec3>> net;
    for (int i = poles.LowerRow(); i <= poles.UpperRow(); ++i) {
        auto& row = net.emplace_back();
        for (int j = poles.LowerCol(); j <= poles.UpperCol(); ++j) row.push_back(from_occt(poles.Value(i, j)));
    }
    return net;
}

std::vector<std::vector<double>> weights_of(const TColStd_Array2OfReal& weights) {
    std::vector<std::vector<double>> out;
    for (int i = weights.LowerRow(); i <= weights.UpperRow(); ++i) {
        auto& row = out.emplace_back();
        for (int j = weights.LowerCol(); j <= weights.UpperCol(); ++j) row.push_back(weights.Value(i, j));
    }
    return out;
}

}  // namespace

Handle(Geom_BezierCurve) to_occt(const BezierCurve& curve) {
    require_degree(curve.degree(), Geom_BezierCurve::MaxDegree(), "curve");
    const TColgp_Array1OfPnt poles = poles_of(curve.points());
    return guarded("curve", [&]() -> Handle(Geom_BezierCurve) {
        if (!curve.is_rational()) return new Geom_BezierCurve(poles);
        return new Geom_BezierCurve(poles, weights_of(curve.weights()));
    });
}

Handle(Geom_BSplineCurve) to_occt(const NurbsCurve& curve) {
    require_degree(curve.degree(), Geom_BSplineCurve::MaxDegree(), "curve");
    const TColgp_Array1OfPnt poles = poles_of(curve.points());
    const DistinctKnots knots = distinct_knots(curve.knots());
    return guarded("curve", [&]() -> Handle(Geom_BSplineCurve) {
        if (!curve.is_rational())
            return new Geom_BSplineCurve(poles, knots.knots, knots.multiplicities, curve.degree(), false);
        return new Geom_BSplineCurve(poles, weights_of(curve.weights()), knots.knots, knots.multiplicities,
                                     curve.degree(), false, true);
    });
}

Handle(Geom_BezierSurface) to_occt(const BezierSurface& surface) {
    require_degree(surface.degree_u(), Geom_BezierSurface::MaxDegree(), "surface (degree_u)");
    require_degree(surface.degree_v(), Geom_BezierSurface::MaxDegree(), "surface (degree_v)");
    const TColgp_Array2OfPnt poles = poles_of(surface.points());
    return guarded("surface", [&]() -> Handle(Geom_BezierSurface) {
        if (!surface.is_rational()) return new Geom_BezierSurface(poles);
        return new Geom_BezierSurface(poles, weights_of(surface.weights()));
    });
}

Handle(Geom_BSplineSurface) to_occt(const NurbsSurface& surface) {
    require_degree(surface.degree_u(), Geom_BSplineSurface::MaxDegree(), "surface (degree_u)");
    require_degree(surface.degree_v(), Geom_BSplineSurface::MaxDegree(), "surface (degree_v)");
    const TColgp_Array2OfPnt poles = poles_of(surface.points());
    const DistinctKnots knots_u = distinct_knots(surface.knots_u());
    const DistinctKnots knots_v = distinct_knots(surface.knots_v());
    return guarded("surface", [&]() -> Handle(Geom_BSplineSurface) {
        if (!surface.is_rational())
            return new Geom_BSplineSurface(poles, knots_u.knots, knots_v.knots, knots_u.multiplicities,
                                           knots_v.multiplicities, surface.degree_u(), surface.degree_v());
        return new Geom_BSplineSurface(poles, weights_of(surface.weights()), knots_u.knots, knots_v.knots,
                                       knots_u.multiplicities, knots_v.multiplicities, surface.degree_u(),
                                       surface.degree_v());
    });
}

BezierCurve from_occt(const Handle(Geom_BezierCurve)& curve) {
    require(!curve.IsNull(), "curve", "is a null handle");
    std::vector<Vec3> points = points_of(curve->Poles());
    if (!curve->IsRational()) return BezierCurve(std::move(points));
    TColStd_Array1OfReal weights(1, curve->NbPoles());
    curve->Weights(weights);
    return BezierCurve(std::move(points), to_vector(weights));
}

NurbsCurve from_occt(const Handle(Geom_BSplineCurve)& curve) {
    require(!curve.IsNull(), "curve", "is a null handle");
    Handle(Geom_BSplineCurve) source = curve;
    if (curve->IsPeriodic()) {
        // Ours are never periodic: the non-periodic form of the same curve (same parameterization).
        source = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
        source->SetNotPeriodic();
    }
    std::vector<Vec3> points = points_of(source->Poles());
    std::vector<double> knots = knot_sequence(source->KnotSequence());
    if (!source->IsRational()) return NurbsCurve(source->Degree(), std::move(knots), std::move(points));
    TColStd_Array1OfReal weights(1, source->NbPoles());
    source->Weights(weights);
    return NurbsCurve(source->Degree(), std::move(knots), std::move(points), to_vector(weights));
}

BezierSurface from_occt(const Handle(Geom_BezierSurface)& surface) {
    require(!surface.IsNull(), "surface", "is a null handle");
    std::vector<std::vector<Vec3>> net = net_of(surface->Poles());
    // IsURational() || IsVRational(): either direction with varying weights makes the patch rational
    // (IsURational alone is true when weights vary along V within a row — SETUP-NOTES).
    if (!surface->IsURational() && !surface->IsVRational()) return BezierSurface(std::move(net));
    TColStd_Array2OfReal weights(1, surface->NbUPoles(), 1, surface->NbVPoles());
    surface->Weights(weights);
    return BezierSurface(std::move(net), weights_of(weights));
}

NurbsSurface from_occt(const Handle(Geom_BSplineSurface)& surface) {
    require(!surface.IsNull(), "surface", "is a null handle");
    Handle(Geom_BSplineSurface) source = surface;
    if (surface->IsUPeriodic() || surface->IsVPeriodic()) {
        source = Handle(Geom_BSplineSurface)::DownCast(surface->Copy());
        if (source->IsUPeriodic()) source->SetUNotPeriodic();
        if (source->IsVPeriodic()) source->SetVNotPeriodic();
    }
    std::vector<std::vector<Vec3>> net = net_of(source->Poles());
    std::vector<double> knots_u = knot_sequence(source->UKnotSequence());
    std::vector<double> knots_v = knot_sequence(source->VKnotSequence());
    if (!source->IsURational() && !source->IsVRational())
        return NurbsSurface(source->UDegree(), source->VDegree(), std::move(knots_u), std::move(knots_v),
                            std::move(net));
    TColStd_Array2OfReal weights(1, source->NbUPoles(), 1, source->NbVPoles());
    source->Weights(weights);
    return NurbsSurface(source->UDegree(), source->VDegree(), std::move(knots_u), std::move(knots_v),
                        std::move(net), weights_of(weights));
}

NurbsCurve from_occt_2d(const Handle(Geom2d_BSplineCurve)& curve) {
    require(!curve.IsNull(), "curve", "is a null handle");
    Handle(Geom2d_BSplineCurve) source = curve;
    if (curve->IsPeriodic()) {
        source = Handle(Geom2d_BSplineCurve)::DownCast(curve->Copy());
        source->SetNotPeriodic();
    }
    std::vector<Vec3> points;
    for (int i = 1; i <= source->NbPoles(); ++i) points.push_back({source->Pole(i).X(), source->Pole(i).Y(), 0.0});
    std::vector<double> knots = knot_sequence(source->KnotSequence());
    if (!source->IsRational()) return NurbsCurve(source->Degree(), std::move(knots), std::move(points));
    std::vector<double> weights;
    for (int i = 1; i <= source->NbPoles(); ++i) weights.push_back(source->Weight(i));
    return NurbsCurve(source->Degree(), std::move(knots), std::move(points), std::move(weights));
}

Handle(Geom2d_BSplineCurve) to_occt_2d(const NurbsCurve& curve, const Vec3& origin, const Vec3& x_axis,
                                       const Vec3& y_axis) {
    require_degree(curve.degree(), Geom2d_BSplineCurve::MaxDegree(), "curve");
    const std::vector<Vec3> points = curve.points();
    TColgp_Array1OfPnt2d poles(1, static_cast<int>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 d = points[i] - origin;
        poles.SetValue(static_cast<int>(i) + 1, gp_Pnt2d(dot(d, x_axis), dot(d, y_axis)));
    }
    const DistinctKnots knots = distinct_knots(curve.knots());
    return guarded("curve", [&]() -> Handle(Geom2d_BSplineCurve) {
        if (!curve.is_rational())
            return new Geom2d_BSplineCurve(poles, knots.knots, knots.multiplicities, curve.degree(), false);
        return new Geom2d_BSplineCurve(poles, weights_of(curve.weights()), knots.knots, knots.multiplicities,
                                       curve.degree(), false);
    });
}

}  // namespace ratbez::occt

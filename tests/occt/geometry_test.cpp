// Geometry conversions against OCCT: our evaluation equals OCCT's D0/D1 of the converted geometry, and
// round trips (ours -> OCCT -> ours, OCCT -> ours -> OCCT) return the same data.
//
// Sizes: 250 random NURBS curves and 250 random NURBS surfaces (degrees 1..7, clamped and unclamped knot
// vectors with interior multiplicities up to the degree, 80% rational with weights in [0.1, 10], fixed
// seeds), 1,000 parameters each (random ones plus every knot and both domain ends); 200 Bézier curves and
// 200 Bézier surfaces likewise (degrees 1..7), and the Bézier curves once more against a long-double
// reference evaluation.

#include <gtest/gtest.h>

#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

#include "occt_test_support.hpp"
#include "ratbez/error.hpp"
#include "ratbez/occt/geometry.hpp"

namespace ratbez::occt {
namespace {

using testing::MaxTracker;
using testing::Random;

constexpr int kShapes = 250;
constexpr int kBezierShapes = 200;
constexpr int kParameters = 1000;
constexpr double kTolerance = 1e-12;
// First derivatives: with weight ratios up to 100 OCCT's evaluation (span caches in power form) loses
// about two more digits to rounding; RandomBezierCurvesAgainstALongDoubleReference measures it: OCCT's D1
// is off the long-double reference by up to 4.8e-13 of the derivative's size (3.9e-12 at degree 9), ours by
// 1.4e-15. Measured ours vs OCCT: 1.15e-12 (NURBS curves), 1.07e-12 (Bézier surfaces).
constexpr double kDerivativeTolerance = 5e-12;

// Parameters: both domain ends, every distinct knot inside the domain, then uniform random ones.
std::vector<double> parameters(Random& random, const Interval& domain, const std::vector<double>& knots, int count) {
    std::vector<double> out{domain.min, domain.max};
    for (double k : knots)
        if (k > domain.min && k < domain.max && (out.empty() || out.back() != k)) out.push_back(k);
    while (static_cast<int>(out.size()) < count) out.push_back(random.uniform(domain.min, domain.max));
    return out;
}

// |ours - theirs| relative to a scale: for points the shape's size (control-point box diagonal); for
// first derivatives the size of the derivative over the sampled parameters (max |OCCT D1|), the same
// notion of size for the hodograph (rational ones with weight ratios of 100 reach far beyond size / width).
double relative(const Vec3& ours, const Vec3& theirs, double scale) { return distance(ours, theirs) / scale; }

struct CurveSample {
    double u;
    gp_Pnt p;
    gp_Vec d1;
};

template <class Curve>
std::vector<CurveSample> occt_samples(const Curve& curve, const std::vector<double>& us, double& max_d1) {
    std::vector<CurveSample> out;
    max_d1 = 0;
    for (double u : us) {
        CurveSample s{u, {}, {}};
        curve->D1(u, s.p, s.d1);
        max_d1 = std::max(max_d1, s.d1.Magnitude());
        out.push_back(s);
    }
    return out;
}

struct SurfaceSample {
    double u, v;
    gp_Pnt p;
    gp_Vec du, dv;
};
struct SurfaceSamples {
    std::vector<SurfaceSample> samples;
    double max_du = 0, max_dv = 0;
};

template <class Surface>
SurfaceSamples occt_surface_samples(const Surface& surface, const std::vector<std::pair<double, double>>& uv) {
    SurfaceSamples out;
    for (const auto& [u, v] : uv) {
        SurfaceSample s{u, v, {}, {}, {}};
        surface->D1(u, v, s.p, s.du, s.dv);
        out.max_du = std::max(out.max_du, s.du.Magnitude());
        out.max_dv = std::max(out.max_dv, s.dv.Magnitude());
        out.samples.push_back(s);
    }
    return out;
}

// Our point and first derivative against OCCT's D0/D1 at every sample (relative to the curve's size
// and to the largest |D1| sampled).
template <class Curve>
void expect_curve_matches(const Curve& ours, const std::vector<CurveSample>& samples, double size, double d1_size,
                          int shape, MaxTracker& point_error, MaxTracker& derivative_error) {
    for (const CurveSample& s : samples) {
        const std::vector<Vec3> d = ours.derivatives(s.u, 1);
        const double e0 = relative(d[0], from_occt(s.p), size);
        const double e1 = relative(d[1], from_occt(s.d1), d1_size);
        point_error.add(e0);
        derivative_error.add(e1);
        ASSERT_LE(e0, kTolerance) << "curve " << shape << " u = " << s.u;
        ASSERT_LE(e1, kDerivativeTolerance) << "curve " << shape << " u = " << s.u;
    }
}

// Our point and first partials against OCCT's D1 at each sample: the point relative to the control net's
// size, each partial relative to the largest OCCT partial of its direction.
template <class Surface>
void expect_surface_matches(const Surface& ours, const SurfaceSamples& samples, double size, int shape,
                            MaxTracker& point_error, MaxTracker& derivative_error) {
    for (const SurfaceSample& s : samples.samples) {
        const auto d = ours.derivatives(s.u, s.v, 1);
        const double e0 = relative(d[0][0], from_occt(s.p), size);
        const double eu = relative(d[1][0], from_occt(s.du), samples.max_du);
        const double ev = relative(d[0][1], from_occt(s.dv), samples.max_dv);
        point_error.add(e0);
        derivative_error.add(std::max(eu, ev));
        ASSERT_LE(e0, kTolerance) << "surface " << shape << " (u, v) = " << s.u << ", " << s.v;
        ASSERT_LE(std::max(eu, ev), kDerivativeTolerance) << "surface " << shape << " (u, v) = " << s.u << ", " << s.v;
    }
}

TEST(GeometryConversion, RandomNurbsCurvesEvaluateLikeOcct) {
    Random random(20240601);
    MaxTracker point_error("NURBS curves: max |C - D0| / size");
    MaxTracker derivative_error("NURBS curves: max |C' - D1| / scale");
    for (int shape = 0; shape < kShapes; ++shape) {
        const NurbsCurve ours = random.nurbs_curve();
        const Handle(Geom_BSplineCurve) theirs = to_occt(ours);
        ASSERT_EQ(theirs->Degree(), ours.degree());
        ASSERT_EQ(theirs->NbPoles(), static_cast<int>(ours.points().size()));
        ASSERT_EQ(theirs->IsRational(), ours.is_rational());
        const Interval domain = ours.domain();
        ASSERT_EQ(theirs->FirstParameter(), domain.min);
        ASSERT_EQ(theirs->LastParameter(), domain.max);
        const double size = testing::diagonal(ours.points());
        double d1_size = 0;
        const auto samples = occt_samples(theirs, parameters(random, domain, ours.knots(), kParameters), d1_size);
        expect_curve_matches(ours, samples, size, d1_size, shape, point_error, derivative_error);
    }
}

TEST(GeometryConversion, RandomNurbsSurfacesEvaluateLikeOcct) {
    Random random(20240602);
    MaxTracker point_error("NURBS surfaces: max |S - D0| / size");
    MaxTracker derivative_error("NURBS surfaces: max |S_u - D1u|, |S_v - D1v| / scale");
    for (int shape = 0; shape < kShapes; ++shape) {
        const NurbsSurface ours = random.nurbs_surface();
        const Handle(Geom_BSplineSurface) theirs = to_occt(ours);
        ASSERT_EQ(theirs->UDegree(), ours.degree_u());
        ASSERT_EQ(theirs->VDegree(), ours.degree_v());
        ASSERT_EQ(theirs->NbUPoles(), ours.rows());
        ASSERT_EQ(theirs->NbVPoles(), ours.columns());
        ASSERT_EQ(theirs->IsURational() || theirs->IsVRational(), ours.is_rational());
        const Interval du = ours.domain_u(), dv = ours.domain_v();
        double u0, u1, v0, v1;
        theirs->Bounds(u0, u1, v0, v1);
        ASSERT_EQ(u0, du.min);
        ASSERT_EQ(u1, du.max);
        ASSERT_EQ(v0, dv.min);
        ASSERT_EQ(v1, dv.max);
        const double size = testing::diagonal(testing::flatten(ours.points()));
        const std::vector<double> us = parameters(random, du, ours.knots_u(), kParameters);
        const std::vector<double> vs = parameters(random, dv, ours.knots_v(), kParameters);
        // Pair knots of one direction with random values of the other (the first entries of each list are
        // the domain ends and knots, the rest random).
        std::vector<std::pair<double, double>> uv;
        for (int k = 0; k < kParameters; ++k)
            uv.emplace_back(us[static_cast<std::size_t>(k)], vs[static_cast<std::size_t>((k * 7) % kParameters)]);
        expect_surface_matches(ours, occt_surface_samples(theirs, uv), size, shape, point_error, derivative_error);
    }
}

// A reference in long double (64-bit mantissa, 2^11 times finer than double): A(u) = sum B_i P^w_i and
// A'(u) = n sum B_{i,n-1} (P^w_{i+1} - P^w_i) by Bernstein sums, then C = A / w and the quotient rule
// C' = (A' - w' C) / w. It tells which side of a disagreement the rounding is on.
struct Reference {
    Vec3 point, derivative;
};
Reference reference(const BezierCurve& curve, double u_double) {
    const auto& pw = curve.homogeneous_points();
    const int n = curve.degree();
    const long double u = u_double;
    auto bernstein_ld = [&](int i, int degree) {
        long double binomial = 1;
        for (int k = 1; k <= i; ++k) binomial = binomial * (degree - k + 1) / k;
        return binomial * std::pow(u, static_cast<long double>(i)) * std::pow(1 - u, static_cast<long double>(degree - i));
    };
    long double a[4] = {0, 0, 0, 0}, d[4] = {0, 0, 0, 0};
    for (int i = 0; i <= n; ++i) {
        const long double b = bernstein_ld(i, n);
        const Vec4& p = pw[static_cast<std::size_t>(i)];
        a[0] += b * p.x, a[1] += b * p.y, a[2] += b * p.z, a[3] += b * p.w;
        if (i < n) {
            const long double b1 = n * bernstein_ld(i, n - 1);
            const Vec4& q = pw[static_cast<std::size_t>(i + 1)];
            d[0] += b1 * ((long double)q.x - p.x), d[1] += b1 * ((long double)q.y - p.y);
            d[2] += b1 * ((long double)q.z - p.z), d[3] += b1 * ((long double)q.w - p.w);
        }
    }
    const long double c[3] = {a[0] / a[3], a[1] / a[3], a[2] / a[3]};
    Reference r;
    r.point = {static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])};
    r.derivative = {static_cast<double>((d[0] - d[3] * c[0]) / a[3]), static_cast<double>((d[1] - d[3] * c[1]) / a[3]),
                    static_cast<double>((d[2] - d[3] * c[2]) / a[3])};
    return r;
}

// Which side of a disagreement with OCCT the rounding is on: ours stays within 1e-14 of the reference.
TEST(GeometryConversion, RandomBezierCurvesAgainstALongDoubleReference) {
    Random random(20240603);
    MaxTracker ours_point("Bezier curves: max |ours C - reference| / size");
    MaxTracker occt_point("Bezier curves: max |OCCT D0 - reference| / size");
    MaxTracker ours_d1("Bezier curves: max |ours C' - reference| / scale");
    MaxTracker occt_d1("Bezier curves: max |OCCT D1 - reference| / scale");
    for (int shape = 0; shape < kBezierShapes; ++shape) {
        const BezierCurve ours = random.bezier_curve();
        const Handle(Geom_BezierCurve) theirs = to_occt(ours);
        const double size = testing::diagonal(ours.points());
        double d1_size = 0;
        for (const CurveSample& s : occt_samples(theirs, parameters(random, {0.0, 1.0}, {}, kParameters), d1_size)) {
            const std::vector<Vec3> d = ours.derivatives(s.u, 1);
            const Reference r = reference(ours, s.u);
            ours_point.add(distance(d[0], r.point) / size);
            occt_point.add(distance(from_occt(s.p), r.point) / size);
            ours_d1.add(distance(d[1], r.derivative) / d1_size);
            occt_d1.add(distance(from_occt(s.d1), r.derivative) / d1_size);
            ASSERT_LE(distance(d[0], r.point), 1e-14 * size) << "curve " << shape << " u = " << s.u;
            ASSERT_LE(distance(d[1], r.derivative), 1e-14 * d1_size) << "curve " << shape << " u = " << s.u;
        }
    }
}

TEST(GeometryConversion, RandomBezierCurvesEvaluateLikeOcct) {
    Random random(20240603);
    MaxTracker point_error("Bezier curves: max |C - D0| / size");
    MaxTracker derivative_error("Bezier curves: max |C' - D1| / scale");
    for (int shape = 0; shape < kBezierShapes; ++shape) {
        const BezierCurve ours = random.bezier_curve();
        const Handle(Geom_BezierCurve) theirs = to_occt(ours);
        ASSERT_EQ(theirs->Degree(), ours.degree());
        ASSERT_EQ(theirs->IsRational(), ours.is_rational());
        const double size = testing::diagonal(ours.points());
        double d1_size = 0;
        const auto samples = occt_samples(theirs, parameters(random, {0.0, 1.0}, {}, kParameters), d1_size);
        expect_curve_matches(ours, samples, size, d1_size, shape, point_error, derivative_error);
    }
}

TEST(GeometryConversion, RandomBezierSurfacesEvaluateLikeOcct) {
    Random random(20240604);
    MaxTracker point_error("Bezier surfaces: max |S - D0| / size");
    MaxTracker derivative_error("Bezier surfaces: max |S_u - D1u|, |S_v - D1v| / scale");
    for (int shape = 0; shape < kBezierShapes; ++shape) {
        const BezierSurface ours = random.bezier_surface();
        const Handle(Geom_BezierSurface) theirs = to_occt(ours);
        ASSERT_EQ(theirs->UDegree(), ours.degree_u());
        ASSERT_EQ(theirs->VDegree(), ours.degree_v());
        ASSERT_EQ(theirs->IsURational() || theirs->IsVRational(), ours.is_rational());
        const double size = testing::diagonal(testing::flatten(ours.points()));
        std::vector<std::pair<double, double>> uv{{0.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {1.0, 0.0}};
        while (static_cast<int>(uv.size()) < kParameters) uv.emplace_back(random.uniform(0, 1), random.uniform(0, 1));
        expect_surface_matches(ours, occt_surface_samples(theirs, uv), size, shape, point_error, derivative_error);
    }
}

// Euclidean points differ from the originals by the rounding of w * (P) / w: at most a few ulps.
void expect_points_equal(const std::vector<Vec3>& a, const std::vector<Vec3>& b, MaxTracker& tracker) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double scale = std::max({1.0, norm(a[i])});
        tracker.add(distance(a[i], b[i]) / scale);
        EXPECT_LE(distance(a[i], b[i]), 4e-16 * scale) << "point " << i;
    }
}

TEST(GeometryConversion, NurbsCurveRoundTripsAreIdentical) {
    Random random(20240605);
    MaxTracker points("NURBS curve round trip: max relative point difference");
    for (int shape = 0; shape < kShapes; ++shape) {
        const NurbsCurve ours = random.nurbs_curve();
        const NurbsCurve back = from_occt(to_occt(ours));
        EXPECT_EQ(back.degree(), ours.degree());
        EXPECT_EQ(back.knots(), ours.knots());  // bit for bit
        EXPECT_EQ(back.weights(), ours.weights());
        EXPECT_EQ(back.is_rational(), ours.is_rational());
        expect_points_equal(back.points(), ours.points(), points);

        // OCCT -> ours -> OCCT.
        const Handle(Geom_BSplineCurve) theirs = to_occt(ours);
        const Handle(Geom_BSplineCurve) again = to_occt(from_occt(theirs));
        ASSERT_EQ(again->NbKnots(), theirs->NbKnots());
        for (int i = 1; i <= theirs->NbKnots(); ++i) {
            EXPECT_EQ(again->Knot(i), theirs->Knot(i));
            EXPECT_EQ(again->Multiplicity(i), theirs->Multiplicity(i));
        }
        for (int i = 1; i <= theirs->NbPoles(); ++i) {
            EXPECT_EQ(again->Weight(i), theirs->Weight(i));
            EXPECT_LE(again->Pole(i).Distance(theirs->Pole(i)), 4e-16 * std::max(1.0, theirs->Pole(i).XYZ().Modulus()));
        }
    }
}

TEST(GeometryConversion, NurbsSurfaceRoundTripsAreIdentical) {
    Random random(20240606);
    MaxTracker points("NURBS surface round trip: max relative point difference");
    for (int shape = 0; shape < kShapes; ++shape) {
        const NurbsSurface ours = random.nurbs_surface();
        const NurbsSurface back = from_occt(to_occt(ours));
        EXPECT_EQ(back.degree_u(), ours.degree_u());
        EXPECT_EQ(back.degree_v(), ours.degree_v());
        EXPECT_EQ(back.knots_u(), ours.knots_u());
        EXPECT_EQ(back.knots_v(), ours.knots_v());
        EXPECT_EQ(back.weights(), ours.weights());
        EXPECT_EQ(back.is_rational(), ours.is_rational());
        expect_points_equal(testing::flatten(back.points()), testing::flatten(ours.points()), points);
    }
}

TEST(GeometryConversion, BezierRoundTripsAreIdentical) {
    Random random(20240607);
    MaxTracker points("Bezier round trip: max relative point difference");
    for (int shape = 0; shape < kBezierShapes; ++shape) {
        const BezierCurve curve = random.bezier_curve();
        const BezierCurve curve_back = from_occt(to_occt(curve));
        EXPECT_EQ(curve_back.degree(), curve.degree());
        EXPECT_EQ(curve_back.weights(), curve.weights());
        EXPECT_EQ(curve_back.is_rational(), curve.is_rational());
        expect_points_equal(curve_back.points(), curve.points(), points);

        const BezierSurface surface = random.bezier_surface();
        const BezierSurface surface_back = from_occt(to_occt(surface));
        EXPECT_EQ(surface_back.degree_u(), surface.degree_u());
        EXPECT_EQ(surface_back.degree_v(), surface.degree_v());
        EXPECT_EQ(surface_back.weights(), surface.weights());
        EXPECT_EQ(surface_back.is_rational(), surface.is_rational());
        expect_points_equal(testing::flatten(surface_back.points()), testing::flatten(surface.points()), points);
    }
}

// OCCT decides rationality itself: equal weights make a polynomial curve, which comes back with weights 1.
TEST(GeometryConversion, EqualWeightsBecomePolynomial) {
    const NurbsCurve ours(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {1, 2, 0}, {2, 0, 1}}, {3, 3, 3});
    const Handle(Geom_BSplineCurve) theirs = to_occt(ours);
    EXPECT_FALSE(theirs->IsRational());
    const NurbsCurve back = from_occt(theirs);
    EXPECT_FALSE(back.is_rational());
    EXPECT_EQ(back.weights(), (std::vector<double>{1, 1, 1}));
    for (double u : {0.0, 0.3, 0.77, 1.0}) EXPECT_LE(distance(back.point(u), ours.point(u)), 1e-15);
}

// A periodic OCCT B-spline (closed, C^2) comes back unperiodized: clamped, same points and parameters.
TEST(GeometryConversion, PeriodicCurvesAreUnperiodized) {
    const int n = 7, degree = 3;
    TColgp_Array1OfPnt poles(1, n);
    TColStd_Array1OfReal weights(1, n), knots(1, n + 1);
    TColStd_Array1OfInteger multiplicities(1, n + 1);
    for (int i = 1; i <= n; ++i) {
        const double a = 2 * M_PI * i / n;
        poles.SetValue(i, gp_Pnt(3 * std::cos(a), 2 * std::sin(a), 0.5 * std::sin(2 * a)));
        weights.SetValue(i, 1 + 0.5 * (i % 3));
    }
    for (int i = 1; i <= n + 1; ++i) {
        knots.SetValue(i, 0.25 * (i - 1));
        multiplicities.SetValue(i, 1);
    }
    const Handle(Geom_BSplineCurve) theirs =
        new Geom_BSplineCurve(poles, weights, knots, multiplicities, degree, /*Periodic=*/true);
    ASSERT_TRUE(theirs->IsPeriodic());
    const NurbsCurve ours = from_occt(theirs);
    EXPECT_TRUE(theirs->IsPeriodic()) << "the caller's curve must not be modified";
    EXPECT_EQ(ours.domain().min, theirs->FirstParameter());
    EXPECT_EQ(ours.domain().max, theirs->LastParameter());
    EXPECT_TRUE(ours.is_rational());
    MaxTracker error("periodic curve: max |C - D0|");
    for (int k = 0; k <= 1000; ++k) {
        const double u = theirs->FirstParameter() + (theirs->LastParameter() - theirs->FirstParameter()) * k / 1000.0;
        gp_Pnt p;
        gp_Vec v;
        theirs->D1(u, p, v);
        const auto d = ours.derivatives(u, 1);
        error.add(distance(d[0], from_occt(p)));
        EXPECT_LE(distance(d[0], from_occt(p)), 1e-12 * 8);
        EXPECT_LE(distance(d[1], from_occt(v)), 1e-12 * std::max(8.0, v.Magnitude()));
    }
    EXPECT_LE(distance(ours.start_point(), ours.end_point()), 1e-12);
}

TEST(GeometryConversion, PeriodicSurfacesAreUnperiodized) {
    // Periodic in u (a closed tube), non-periodic clamped in v.
    const int nu = 6, degree_u = 2, nv = 3, degree_v = 2;
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    TColStd_Array2OfReal weights(1, nu, 1, nv);
    for (int i = 1; i <= nu; ++i)
        for (int j = 1; j <= nv; ++j) {
            const double a = 2 * M_PI * i / nu;
            const double r = 2 + 0.3 * j;
            poles.SetValue(i, j, gp_Pnt(r * std::cos(a), r * std::sin(a), j));
            weights.SetValue(i, j, 1 + 0.25 * ((i + j) % 3));
        }
    TColStd_Array1OfReal uknots(1, nu + 1), vknots(1, 2);
    TColStd_Array1OfInteger umults(1, nu + 1), vmults(1, 2);
    for (int i = 1; i <= nu + 1; ++i) {
        uknots.SetValue(i, i - 1.0);
        umults.SetValue(i, 1);
    }
    vknots.SetValue(1, 0);
    vknots.SetValue(2, 1);
    vmults.SetValue(1, 3);
    vmults.SetValue(2, 3);
    const Handle(Geom_BSplineSurface) theirs = new Geom_BSplineSurface(poles, weights, uknots, vknots, umults,
                                                                       vmults, degree_u, degree_v, true, false);
    ASSERT_TRUE(theirs->IsUPeriodic());
    const NurbsSurface ours = from_occt(theirs);
    double u0, u1, v0, v1;
    theirs->Bounds(u0, u1, v0, v1);
    EXPECT_EQ(ours.domain_u().min, u0);
    EXPECT_EQ(ours.domain_u().max, u1);
    MaxTracker error("periodic surface: max |S - D0|");
    for (int a = 0; a <= 40; ++a)
        for (int b = 0; b <= 40; ++b) {
            const double u = u0 + (u1 - u0) * a / 40.0, v = v0 + (v1 - v0) * b / 40.0;
            gp_Pnt p;
            theirs->D0(u, v, p);
            error.add(distance(ours.point(u, v), from_occt(p)));
            EXPECT_LE(distance(ours.point(u, v), from_occt(p)), 1e-12 * 8);
        }
}

TEST(GeometryConversion, PlaneCoordinatesOfACurve) {
    // A planar rational quadratic in the plane z = 2 with the frame x' = y, y' = -x.
    const NurbsCurve curve(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 2}, {1, 1, 2}, {0, 1, 2}}, {1, std::sqrt(0.5), 1});
    const Handle(Geom2d_BSplineCurve) pcurve = to_occt_2d(curve, {0, 0, 2}, {0, 1, 0}, {-1, 0, 0});
    for (double t : {0.0, 0.1, 0.5, 0.9, 1.0}) {
        const Vec3 p = curve.point(t);
        const gp_Pnt2d q = pcurve->Value(t);
        EXPECT_NEAR(q.X(), p.y, 1e-15);
        EXPECT_NEAR(q.Y(), -p.x, 1e-15);
    }
}

TEST(GeometryConversion, UnrepresentableDataThrowsNamingTheArgument) {
    const NurbsCurve constant(0, {0, 1}, {{1, 2, 3}});
    try {
        (void)to_occt(constant);
        FAIL() << "degree 0 must throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("curve"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("degree"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)from_occt(Handle(Geom_BSplineCurve)()), Error);
    EXPECT_THROW((void)from_occt(Handle(Geom_BezierSurface)()), Error);
    try {
        (void)from_occt(Handle(Geom_BSplineSurface)());
        FAIL() << "a null handle must throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("surface"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace ratbez::occt

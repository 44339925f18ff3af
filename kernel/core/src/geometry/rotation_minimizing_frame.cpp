// The double reflection method (Wang, Jüttler, Zheng, Liu 2008, Algorithm 1); see rotation_minimizing_frame.hpp.
#include "ratbez/rotation_minimizing_frame.hpp"

#include "ratbez/error.hpp"

namespace ratbez {

namespace {

// The reflection of a in the plane through the origin normal to v (v . v = c > 0): a - (2 / c)(v . a) v.
Vec3 reflect(const Vec3& a, const Vec3& v, double c) { return a - v * (2.0 / c * dot(v, a)); }

Vec3 unit(const Vec3& a) { return a / norm(a); }

}  // namespace

Vec3 double_reflection(const Vec3& x_i, const Vec3& t_i, const Vec3& r_i, const Vec3& x_next, const Vec3& t_next) {
    // R1: reflection in the bisecting plane of x_i and x_next.
    const Vec3 v1 = x_next - x_i;
    const double c1 = dot(v1, v1);
    const Vec3 r_left = c1 > 0 ? reflect(r_i, v1, c1) : r_i;
    const Vec3 t_left = c1 > 0 ? reflect(t_i, v1, c1) : t_i;
    // R2: reflection in the plane that takes t_left to t_next (normal t_next - t_left).
    const Vec3 v2 = t_next - t_left;
    const double c2 = dot(v2, v2);
    const Vec3 r_next = c2 > 0 ? reflect(r_left, v2, c2) : r_left;
    // Reflections preserve length and angles exactly in exact arithmetic; remove the rounding drift so that
    // thousands of steps stay orthonormal.
    return unit(r_next - t_next * dot(r_next, t_next));
}

std::vector<Vec3> rotation_minimizing_frame(const std::vector<Vec3>& points, const std::vector<Vec3>& tangents,
                                            const Vec3& r0) {
    require(points.size() == tangents.size(), "tangents", "must have one tangent per point");
    std::vector<Vec3> r;
    r.reserve(points.size());
    if (points.empty()) return r;
    r.push_back(r0);
    for (std::size_t k = 1; k < points.size(); ++k)
        r.push_back(double_reflection(points[k - 1], tangents[k - 1], r[k - 1], points[k], tangents[k]));
    return r;
}

}  // namespace ratbez

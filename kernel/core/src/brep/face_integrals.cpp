// The walk over a shell's faces (face_integrals.hpp), onto the engine of analysis/cubature.hpp.
// Surface faces: area = ∫∫ |S_u x S_v| du dv, volume contribution = (1/3) ∫∫ (S - c) · (S_u x S_v) du dv
// (divergence theorem with div(x - c) = 3; any reference point c gives the same total over a closed
// shell, and the centre of the control box, the origin of the cubature's local frame, keeps the integrand
// small and well conditioned wherever the solid lies).
// Planar faces: area by Green's theorem on their loops in the plane frame, A = (1/2) ∮ (x dy - y dx);
// on a plane (S - c) · n is the constant (origin - c) · n, so the volume contribution is
// (1/3) ((origin - c) · n) A.
// Trimmed faces: the same integrands as surface faces over the region their p-curves bound in (u, v)
// (Cubature::add_trimmed_surface, Green's theorem on the region).
#include "brep/face_integrals.hpp"

#include "analysis/cubature.hpp"

namespace ratbez::detail {
namespace {

// A planar face's loop edges for `factor` times Green's area integral in the plane frame, edge by edge
// (a reversed coedge contributes with the opposite sign).
void add_planar(const Face& face, double factor, Cubature& cubature) {
    const Plane& plane = face.plane();
    for (const auto& loop : face.loops())
        for (const Coedge& coedge : loop)
            cubature.add_green(coedge.edge->curve, plane.origin, plane.x_axis, plane.y_axis,
                               coedge.reversed ? -factor : factor);
}

// A trimmed face's boundary in (u, v): its p-curves, each in the direction the face runs it.
std::vector<Cubature::TrimmingCurve> trimming_curves(const Face& face) {
    std::vector<Cubature::TrimmingCurve> curves;
    for (const auto& loop : face.loops())
        for (const Coedge& coedge : loop) curves.push_back({coedge.pcurve.get(), coedge.reversed ? -1.0 : 1.0});
    return curves;
}

void add_face_area(const Face& face, Cubature& cubature) {
    if (face.kind() == Face::Kind::planar) return add_planar(face, 1.0, cubature);
    if (face.kind() == Face::Kind::trimmed)
        return cubature.add_trimmed_surface(face.surface(), trimming_curves(face),
                                            [](const SurfaceFirstDerivatives& d) { return norm(cross(d.su, d.sv)); });
    cubature.add_surface_area(face.surface());
}

// The face's contribution to the volume: (1/3) of the flux of (x - c) through it; (S - c) · (S_u x S_v)
// has degree 3p - 1 along a direction of degree p on a polynomial face. `c` is the cubature's reference
// point, the origin of its local frame, where the integrands see the surfaces (cubature.hpp); a planar
// face's height above it is a difference of world coordinates (correctly rounded), then a local length.
void add_face_volume(const Face& face, const Vec3& c, Cubature& cubature) {
    if (face.kind() == Face::Kind::planar) {
        const Plane& plane = face.plane();
        return add_planar(face, cubature.frame().to_local(dot(plane.origin - c, plane.normal)) / 3.0, cubature);
    }
    const auto flux = [](const SurfaceFirstDerivatives& d) { return dot(d.s, cross(d.su, d.sv)) / 3.0; };
    if (face.kind() == Face::Kind::trimmed) return cubature.add_trimmed_surface(face.surface(), trimming_curves(face), flux);
    cubature.add_surface(face.surface(), flux, 3);
}

Box box_of(const std::vector<Face>& faces) {
    Box box;
    for (const Face& face : faces) box.add(face.surface().control_box());
    return box;
}

}  // namespace

double faces_volume(const std::vector<Face>& faces, std::string_view argument, bool quick, const Progress& progress) {
    Cubature volume(box_of(faces), 3, quick);
    for (const Face& face : faces) add_face_volume(face, volume.frame().reference, volume);
    return volume.integrate(argument, &progress);
}

double faces_area(const std::vector<Face>& faces, std::string_view argument, const Progress& progress) {
    Cubature area(box_of(faces), 2);
    for (const Face& face : faces) add_face_area(face, area);
    return area.integrate(argument, &progress);
}

}  // namespace ratbez::detail

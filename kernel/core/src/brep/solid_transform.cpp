// Affine maps of faces and solids (solid_transform.hpp).

#include "ratbez/solid_transform.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "brep/brep_build.hpp"
#include "math/solid_scale.hpp"
#include "ratbez/error.hpp"

namespace ratbez {
namespace {

// S'(u, v) = S(v, u): the same surface with its parameters swapped (the net transposed).
NurbsSurface swapped_parameters(const NurbsSurface& s) {
    std::vector<Vec4> net;
    net.reserve(s.homogeneous_points().size());
    for (int j = 0; j < s.columns(); ++j)
        for (int i = 0; i < s.rows(); ++i) net.push_back(s.homogeneous_point(i, j));
    return NurbsSurface::from_homogeneous(s.degree_v(), s.degree_u(), s.knots_v(), s.knots_u(), std::move(net),
                                          s.is_rational());
}

Coedge reversed(const Coedge& coedge) { return {coedge.edge, !coedge.reversed, coedge.pcurve}; }

// A p-curve with its coordinates swapped, (u, v) -> (v, u), for the surface with swapped parameters.
std::shared_ptr<const NurbsCurve> swapped_coordinates(const NurbsCurve& pcurve) {
    std::vector<Vec4> points = pcurve.homogeneous_points();
    for (Vec4& p : points) std::swap(p.x, p.y);
    return std::make_shared<const NurbsCurve>(
        NurbsCurve::from_homogeneous(pcurve.degree(), pcurve.knots(), std::move(points), pcurve.is_rational()));
}

// How much the map can stretch a distance at most (the Frobenius norm of its linear part bounds the
// spectral norm): a face's tolerance grows by no more.
double largest_stretch(const AffineMap& map) {
    double sum = 0;
    for (const Vec3& row : map.linear()) sum += dot(row, row);
    return std::sqrt(sum);
}

// Maps faces one by one, each edge and vertex once, so the images share them as the originals did.
class BrepMapper {
public:
    explicit BrepMapper(const AffineMap& map) : map_(map), reflects_(map.reflects()) {}

    Face face(const Face& face) {
        if (face.kind() == Face::Kind::planar) return planar(face);
        if (face.kind() == Face::Kind::trimmed) return trimmed(face);
        const auto& sides = face.sides();
        std::array<Coedge, 4> mapped;
        for (std::size_t s = 0; s < 4; ++s) mapped[s] = coedge(sides[s]);
        NurbsSurface surface = transformed(face.surface(), map_);
        if (!reflects_) return Face::from_surface(std::move(surface), mapped);
        // S'(u, v) = S(v, u): its v_min side is S's u_min side run the other way (v now increases along it
        // where S's u_min side ran v decreasing), and so on round; each edge keeps its parameter (the
        // side's running parameter is the same surface parameter), only the coedges reverse.
        const auto at = [&](Side side) { return reversed(mapped[static_cast<std::size_t>(side)]); };
        return Face::from_surface(swapped_parameters(surface),
                                  {at(Side::u_min), at(Side::v_max), at(Side::u_max), at(Side::v_min)});
    }

private:
    // The surface maps as a surface face's; the p-curves stay where they are in (u, v). A reflection turns
    // S_u x S_v inward, so the image's parameters are swapped (as for surface faces): the p-curves swap
    // their coordinates, which runs every loop the other way round in (u, v), and the loops are run
    // backwards to make the outer loop counterclockwise again.
    Face trimmed(const Face& face) {
        std::vector<std::vector<Coedge>> loops;
        for (const auto& loop : face.loops()) {
            std::vector<Coedge> mapped;
            for (const Coedge& c : loop) {
                Coedge image = coedge(c);
                if (reflects_) image = reversed(Coedge{image.edge, image.reversed, swapped_coordinates(*c.pcurve)});
                mapped.push_back(std::move(image));
            }
            if (reflects_) std::reverse(mapped.begin(), mapped.end());
            loops.push_back(std::move(mapped));
        }
        NurbsSurface surface = transformed(face.surface(), map_);
        if (reflects_) surface = swapped_parameters(surface);
        return Face::trimmed(std::move(surface), std::move(loops), face.tolerance() * largest_stretch(map_));
    }

    Face planar(const Face& face) {
        const Plane& plane = face.plane();
        // The image plane's outward normal is L^-T n (the outside half-space maps to the outside); x_axis
        // maps into the plane; y completes the right-handed frame.
        Plane image;
        image.origin = map_(plane.origin);
        image.normal = map_.normal_image(plane.normal);
        image.normal = image.normal / norm(image.normal);
        image.x_axis = map_.apply_linear(plane.x_axis);
        image.x_axis = image.x_axis / norm(image.x_axis);
        image.y_axis = cross(image.normal, image.x_axis);
        // Loops run counterclockwise seen from cof(L) n = det(L) L^-T n after the map: from the outside
        // unless the map reflects, when every loop is run backwards.
        std::vector<std::vector<Coedge>> loops;
        for (const auto& loop : face.loops()) {
            std::vector<Coedge> mapped;
            for (const Coedge& c : loop) mapped.push_back(coedge(c));
            if (reflects_) {
                std::reverse(mapped.begin(), mapped.end());
                for (Coedge& c : mapped) c = reversed(c);
            }
            loops.push_back(std::move(mapped));
        }
        return Face::planar(image, std::move(loops), face.tolerance() * largest_stretch(map_));
    }

    Coedge coedge(const Coedge& c) { return {edge(c.edge), c.reversed, c.pcurve}; }

    EdgePtr edge(const EdgePtr& e) {
        auto [it, inserted] = edges_.try_emplace(e.get());
        if (inserted)
            it->second = detail::make_edge(transformed(e->curve, map_), vertex(e->start), vertex(e->end), e->degenerate);
        return it->second;
    }

    VertexPtr vertex(const VertexPtr& v) {
        auto [it, inserted] = vertices_.try_emplace(v.get());
        if (inserted) it->second = detail::make_vertex(map_(v->point));
        return it->second;
    }

    const AffineMap& map_;
    bool reflects_;
    std::map<const Edge*, EdgePtr> edges_;
    std::map<const Vertex*, VertexPtr> vertices_;
};

Vec3 unit(const Vec3& v) { return v / norm(v); }

}  // namespace

Face transformed(const Face& face, const AffineMap& map) { return BrepMapper(map).face(face); }

Solid transformed(const Solid& solid, const AffineMap& map) {
    try {
        BrepMapper mapper(map);
        std::vector<Face> faces;
        faces.reserve(solid.faces().size());
        for (const Face& face : solid.faces()) faces.push_back(mapper.face(face));
        Solid image(std::move(faces), transformed(solid.construction(), map));
        image.set_name(solid.name());
        return image;
    } catch (const Error&) {
        // A map that takes the solid too far from the origin for its size (sphere(2) moved to 1e15) breaks its
        // faces first, in their words ("side u_max collapses to a point"): the scale rule, on the box the map
        // makes of the solid's (which holds the image), names the map instead. Only after a failure: that box
        // can be larger than the image's own, and must not refuse an image that is fine.
        Box image;
        const Box box = solid.bounding_box();
        for (int corner = 0; corner < 8; ++corner)
            image.add(map({corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                           corner & 4 ? box.max.z : box.min.z}));
        detail::require_solid_scale(image.diagonal(), detail::reach_of(image), "map", "map", detail::largest_box_diagonal);
        throw;
    }
}

Construction transformed(const Construction& construction, const AffineMap& map) {
    if (const auto* e = construction.get<Construction::Extrusion>()) {
        const Vec3 d = map.apply_linear(e->direction);
        return Construction::Extrusion{unit(d), e->distance * norm(d)};
    }
    const std::optional<double> scale = map.similarity_scale();
    if (!scale) return {};
    const double s = *scale;
    const auto axis = [&](const Vec3& a) { return unit(map.apply_linear(a)); };
    if (const auto* c = construction.get<Construction::Cylinder>())
        return Construction::Cylinder{map(c->center), axis(c->axis), s * c->radius, s * c->height};
    if (const auto* k = construction.get<Construction::Cone>())
        return Construction::Cone{map(k->center), axis(k->axis), s * k->radius1, s * k->radius2, s * k->height};
    if (const auto* p = construction.get<Construction::Sphere>()) return Construction::Sphere{map(p->center), s * p->radius};
    if (const auto* t = construction.get<Construction::Torus>())
        return Construction::Torus{map(t->center), axis(t->axis), s * t->major_radius, s * t->minor_radius};
    if (const auto* r = construction.get<Construction::Revolution>()) {
        // A reflection turns the sweep's sense: the image is the revolution about the reversed axis.
        const Vec3 direction = axis(r->axis_dir) * (map.reflects() ? -1.0 : 1.0);
        return Construction::Revolution{map(r->axis_point), direction, r->angle_deg};
    }
    return {};
}

}  // namespace ratbez

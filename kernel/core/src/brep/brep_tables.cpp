// Faces as indexed tables and back (brep_tables.hpp).

#include "ratbez/brep_tables.hpp"

#include <map>
#include <string>
#include <utility>

#include "brep/brep_build.hpp"
#include "ratbez/error.hpp"

namespace ratbez {
namespace {

class TableWriter {
public:
    BrepTables tables;

    BrepTables::CoedgeRecord coedge(const Coedge& c) {
        return {edge(c.edge), c.reversed, c.pcurve ? std::optional<NurbsCurve>(*c.pcurve) : std::nullopt};
    }

private:
    std::size_t edge(const EdgePtr& e) {
        const auto [it, inserted] = edges_.try_emplace(e.get(), tables.edges.size());
        if (inserted) tables.edges.push_back({e->curve, vertex(e->start), vertex(e->end), e->degenerate});
        return it->second;
    }
    std::size_t vertex(const VertexPtr& v) {
        const auto [it, inserted] = vertices_.try_emplace(v.get(), tables.vertices.size());
        if (inserted) tables.vertices.push_back(v->point);
        return it->second;
    }
    std::map<const Edge*, std::size_t> edges_;
    std::map<const Vertex*, std::size_t> vertices_;
};

class FaceReader {
public:
    explicit FaceReader(const BrepTables& tables) : tables_(tables) {
        vertices_.reserve(tables.vertices.size());
        for (const Vec3& p : tables.vertices) vertices_.push_back(detail::make_vertex(p));
        edges_.resize(tables.edges.size());
    }

    Coedge coedge(const BrepTables::CoedgeRecord& c, const std::string& where) {
        return {edge(c.edge, where), c.reversed, c.pcurve ? std::make_shared<const NurbsCurve>(*c.pcurve) : nullptr};
    }

private:
    EdgePtr edge(std::size_t index, const std::string& where) {
        require(index < tables_.edges.size(), where, [&] {
            return "edge index " + std::to_string(index) + " is out of range [0, " + std::to_string(tables_.edges.size()) + ")";
        });
        if (!edges_[index]) {
            const BrepTables::EdgeRecord& e = tables_.edges[index];
            const std::string edge_where = "edges[" + std::to_string(index) + "]";
            edges_[index] = detail::make_edge(e.curve, vertex(e.start, edge_where), vertex(e.end, edge_where), e.degenerate);
        }
        return edges_[index];
    }
    VertexPtr vertex(std::size_t index, const std::string& where) {
        require(index < vertices_.size(), where, [&] {
            return "vertex index " + std::to_string(index) + " is out of range [0, " + std::to_string(vertices_.size()) + ")";
        });
        return vertices_[index];
    }

    const BrepTables& tables_;
    std::vector<VertexPtr> vertices_;
    std::vector<EdgePtr> edges_;
};

}  // namespace

BrepTables tables_of(std::span<const Face> faces) {
    TableWriter writer;
    for (const Face& face : faces) {
        BrepTables::FaceRecord record;
        record.kind = face.kind();
        if (face.kind() == Face::Kind::surface) {
            record.surface = face.surface();
            for (std::size_t s = 0; s < 4; ++s) record.sides[s] = writer.coedge(face.sides()[s]);
        } else {
            if (face.kind() == Face::Kind::trimmed) record.surface = face.surface();
            record.plane = face.plane();
            record.tolerance = face.tolerance();
            for (const auto& loop : face.loops()) {
                std::vector<BrepTables::CoedgeRecord> coedges;
                for (const Coedge& c : loop) coedges.push_back(writer.coedge(c));
                record.loops.push_back(std::move(coedges));
            }
        }
        writer.tables.faces.push_back(std::move(record));
    }
    return std::move(writer.tables);
}

std::vector<Face> faces_of(const BrepTables& tables) {
    FaceReader reader(tables);
    std::vector<Face> faces;
    faces.reserve(tables.faces.size());
    for (std::size_t f = 0; f < tables.faces.size(); ++f) {
        const BrepTables::FaceRecord& record = tables.faces[f];
        const std::string where = "faces[" + std::to_string(f) + "]";
        try {
            if (record.kind == Face::Kind::surface) {
                require(record.surface.has_value(), where, "a surface face needs its surface");
                std::array<Coedge, 4> sides;
                for (std::size_t s = 0; s < 4; ++s) sides[s] = reader.coedge(record.sides[s], where);
                faces.push_back(Face::from_surface(*record.surface, sides));
            } else {
                std::vector<std::vector<Coedge>> loops;
                for (const auto& loop : record.loops) {
                    std::vector<Coedge> coedges;
                    for (const auto& c : loop) coedges.push_back(reader.coedge(c, where));
                    loops.push_back(std::move(coedges));
                }
                if (record.kind == Face::Kind::trimmed) {
                    require(record.surface.has_value(), where, "a trimmed face needs its surface");
                    faces.push_back(Face::trimmed(*record.surface, std::move(loops), record.tolerance));
                } else {
                    faces.push_back(Face::planar(record.plane, std::move(loops), record.tolerance));
                }
            }
        } catch (const Error& e) {
            if (e.argument().starts_with("faces[") || e.argument().starts_with("edges[")) throw;
            throw e.under(where);
        }
    }
    return faces;
}

}  // namespace ratbez

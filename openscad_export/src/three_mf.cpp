// 3MF through lib3mf 1.8's C interface (NMR_DLLInterfaces.h), the only translation unit that includes
// lib3mf: its headers define SAL annotations (_In_, _Out_, ...) and Windows types (DWORD, BOOL, HRESULT).
#include "ratbez/export/three_mf.hpp"

#include <algorithm>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Model/COM/NMR_DLLInterfaces.h>

#include "ratbez/error.hpp"

namespace ratbez::exporter {
namespace {

using namespace NMR;

// A lib3mf instance, released with lib3mf_release.
struct Releaser {
    void operator()(PLib3MFBase* instance) const {
        if (instance != nullptr) lib3mf_release(instance);
    }
};
using Handle = std::unique_ptr<PLib3MFBase, Releaser>;

// lib3mf 1.8.1 sets the process's C locale to "C" while it writes or reads and leaves it so (measured: after
// one write Python's LC_CTYPE was C and its file encoding ASCII, so a host's non-ASCII file names broke).
// The host's locale is restored when lib3mf returns. (setlocale is process-wide: lib3mf's own call cannot
// be made thread-local, so a host thread reading the locale meanwhile may see "C".)
class LocaleRestorer {
public:
    LocaleRestorer() {
        if (const char* current = std::setlocale(LC_ALL, nullptr)) saved_ = current;
    }
    ~LocaleRestorer() {
        if (!saved_.empty()) std::setlocale(LC_ALL, saved_.c_str());
    }
    LocaleRestorer(const LocaleRestorer&) = delete;
    LocaleRestorer& operator=(const LocaleRestorer&) = delete;

private:
    std::string saved_;
};

// lib3mf's last error on `instance` (or the bare code when it has none), as a ratbez::Error naming "3mf".
[[noreturn]] void fail(PLib3MFBase* instance, LIB3MFRESULT code, const char* what) {
    std::string reason = std::string("lib3mf ") + what + " failed";
    DWORD error = 0;
    LPCSTR message = nullptr;
    if (instance != nullptr && lib3mf_getlasterror(instance, &error, &message) == LIB3MF_OK && message != nullptr &&
        *message != '\0')
        reason += ": " + std::string(message);
    char hex[16];
    std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(code));
    throw Error("3mf", reason + " (error 0x" + hex + ")");
}

void check(PLib3MFBase* instance, LIB3MFRESULT code, const char* what) {
    if (code != LIB3MF_OK) fail(instance, code, what);
}

Handle new_model() {
    PLib3MFModel* model = nullptr;
    if (const LIB3MFRESULT code = lib3mf_createmodel(&model); code != LIB3MF_OK) fail(nullptr, code, "createmodel");
    return Handle(model);
}

std::uint8_t channel_byte(double channel) { return static_cast<std::uint8_t>(std::lround(std::clamp(channel, 0.0, 1.0) * 255)); }

// The package goes to memory through lib3mf's write and seek callbacks (ZIP writing seeks back to patch
// the local headers). A callback returns 0 for success.
struct MemorySink {
    std::string bytes;
    std::size_t position = 0;
};

std::uint32_t write_callback(const unsigned char* data, std::uint32_t count, void* user) {
    auto& sink = *static_cast<MemorySink*>(user);
    if (sink.position + count > sink.bytes.size()) sink.bytes.resize(sink.position + count);
    std::memcpy(sink.bytes.data() + sink.position, data, count);
    sink.position += count;
    return 0;
}

std::uint32_t seek_callback(std::uint64_t position, void* user) {
    auto& sink = *static_cast<MemorySink*>(user);
    if (position > sink.bytes.size()) return 1;
    sink.position = static_cast<std::size_t>(position);
    return 0;
}

// lib3mf's progress callback: forwards to the caller's Progress; an exception it throws is kept and stops
// the writing (returning false aborts lib3mf's call), and is rethrown after lib3mf has returned.
struct ProgressRelay {
    const Progress* progress = nullptr;
    std::exception_ptr thrown;
};

bool progress_callback(int percent, ProgressIdentifier, void* user) {
    auto& relay = *static_cast<ProgressRelay*>(user);
    try {
        (*relay.progress)(std::clamp(percent, 0, 100) / 100.0);
        return true;
    } catch (...) {
        relay.thrown = std::current_exception();
        return false;
    }
}

// A UTF-8 string lib3mf returns through a (buffer, size, needed) call.
template <class Get>
std::string utf8_string(PLib3MFBase* instance, const char* what, Get get) {
    ULONG needed = 0;
    check(instance, get(nullptr, 0, &needed), what);
    std::string text(needed + 1, '\0');
    check(instance, get(text.data(), static_cast<ULONG>(text.size()), &needed), what);
    text.resize(std::strlen(text.c_str()));
    return text;
}

}  // namespace

std::string write_three_mf(const std::vector<ThreeMfObject>& objects,
                           const std::vector<std::pair<std::string, std::string>>& metadata, const Progress& progress) {
    require(!objects.empty(), "solids", "is empty");
    const LocaleRestorer locale;
    Handle model = new_model();
    check(model.get(), lib3mf_model_setunit(model.get(), MODELUNIT_MILLIMETER), "setunit");
    for (const auto& [name, value] : metadata)
        check(model.get(), lib3mf_model_addmetadatautf8(model.get(), name.c_str(), value.c_str()), "addmetadata");

    Handle materials;  // one base material group for every coloured object, created when the first needs it
    DWORD materials_id = 0;
    std::vector<Handle> kept;  // lib3mf hands out references; they are released after the writing
    std::vector<MODELMESHVERTEX> vertices;
    std::vector<MODELMESHTRIANGLE> triangles;
    for (const ThreeMfObject& object : objects) {
        require(object.mesh != nullptr, "solids", "an object has no mesh");
        const Mesh& mesh = *object.mesh;
        require(mesh.vertices.size() <= std::numeric_limits<std::uint32_t>::max() &&
                    mesh.triangles.size() <= std::numeric_limits<std::uint32_t>::max(),
                "mesh", "too large for 3MF");
        vertices.resize(mesh.vertices.size());
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            const Vec3& p = mesh.vertices[i];
            require(is_finite(p) && std::abs(p.x) <= three_mf_max_coordinate && std::abs(p.y) <= three_mf_max_coordinate &&
                        std::abs(p.z) <= three_mf_max_coordinate,
                    "mesh", [&] {
                        return "vertex " + std::to_string(i) + " of '" + object.name +
                               "' lies beyond 3MF's coordinate range (1e9 mm, lib3mf's limit)";
                    });
            vertices[i].m_fPosition[0] = static_cast<float>(p.x);
            vertices[i].m_fPosition[1] = static_cast<float>(p.y);
            vertices[i].m_fPosition[2] = static_cast<float>(p.z);
        }
        triangles.resize(mesh.triangles.size());
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            for (std::size_t k = 0; k < 3; ++k) {
                require(mesh.triangles[t][k] < mesh.vertices.size(), "mesh", "a triangle refers to a missing vertex");
                triangles[t].m_nIndices[k] = mesh.triangles[t][k];
            }

        PLib3MFModelMeshObject* added = nullptr;
        check(model.get(), lib3mf_model_addmeshobject(model.get(), &added), "addmeshobject");
        Handle mesh_object(added);
        check(mesh_object.get(), lib3mf_object_setnameutf8(mesh_object.get(), object.name.c_str()), "setname");
        check(mesh_object.get(), lib3mf_object_settype(mesh_object.get(), MODELOBJECTTYPE_MODEL), "settype");
        check(mesh_object.get(),
              lib3mf_meshobject_setgeometry(mesh_object.get(), vertices.data(), static_cast<DWORD>(vertices.size()),
                                            triangles.data(), static_cast<DWORD>(triangles.size())),
              "setgeometry");
        if (object.color) {
            if (!materials) {
                PLib3MFModelBaseMaterial* group = nullptr;
                check(model.get(), lib3mf_model_addbasematerialgroup(model.get(), &group), "addbasematerialgroup");
                materials.reset(group);
                check(materials.get(), lib3mf_resource_getresourceid(materials.get(), &materials_id), "getresourceid");
            }
            const Color& c = *object.color;
            DWORD index = 0;
            check(materials.get(),
                  lib3mf_basematerial_addmaterialutf8(materials.get(), object.name.c_str(), channel_byte(c.red),
                                                      channel_byte(c.green), channel_byte(c.blue), &index),
                  "addmaterial");
            check(materials.get(),
                  lib3mf_basematerial_setdisplaycolorrgba(materials.get(), index, channel_byte(c.red), channel_byte(c.green),
                                                          channel_byte(c.blue), channel_byte(c.alpha)),
                  "setdisplaycolor");
            PLib3MFDefaultPropertyHandler* handler = nullptr;
            check(mesh_object.get(), lib3mf_object_createdefaultpropertyhandler(mesh_object.get(), &handler),
                  "createdefaultpropertyhandler");
            Handle default_property(handler);
            check(default_property.get(), lib3mf_defaultpropertyhandler_setbasematerial(default_property.get(), materials_id, index),
                  "setbasematerial");
        }
        PLib3MFModelBuildItem* item = nullptr;
        check(model.get(), lib3mf_model_addbuilditem(model.get(), mesh_object.get(), nullptr, &item), "addbuilditem");
        kept.emplace_back(item);
        kept.push_back(std::move(mesh_object));
    }

    PLib3MFModelWriter* created = nullptr;
    check(model.get(), lib3mf_model_querywriter(model.get(), "3mf", &created), "querywriter");
    Handle writer(created);
    ProgressRelay relay{&progress, nullptr};
    if (progress) check(writer.get(), lib3mf_writer_setprogresscallback(writer.get(), progress_callback, &relay), "setprogresscallback");
    MemorySink sink;
    const LIB3MFRESULT written = lib3mf_writer_writetocallback(writer.get(), reinterpret_cast<void*>(&write_callback),
                                                               reinterpret_cast<void*>(&seek_callback), &sink);
    if (relay.thrown) std::rethrow_exception(relay.thrown);
    check(writer.get(), written, "write");
    return std::move(sink.bytes);
}

namespace {

Handle read_model(std::string_view package) {
    Handle model = new_model();
    PLib3MFModelReader* created = nullptr;
    check(model.get(), lib3mf_model_queryreader(model.get(), "3mf", &created), "queryreader");
    Handle reader(created);
    std::vector<BYTE> bytes(package.begin(), package.end());  // lib3mf takes a non-const buffer
    check(reader.get(), lib3mf_reader_readfrombuffer(reader.get(), bytes.data(), bytes.size()), "read");
    return model;
}

// The display colour of an object's default base material, if it has one.
std::optional<Color> base_material_color(PLib3MFModel* model, PLib3MFModelResource* object) {
    PLib3MFDefaultPropertyHandler* created = nullptr;
    check(object, lib3mf_object_createdefaultpropertyhandler(object, &created), "createdefaultpropertyhandler");
    const Handle handler(created);
    eModelPropertyType type = MODELPROPERTYTYPE_NONE;
    check(handler.get(), lib3mf_defaultpropertyhandler_getpropertytype(handler.get(), &type), "getpropertytype");
    if (type != MODELPROPERTYTYPE_BASEMATERIALS) return std::nullopt;
    DWORD group_id = 0, index = 0;
    check(handler.get(), lib3mf_defaultpropertyhandler_getbasematerial(handler.get(), &group_id, &index), "getbasematerial");
    PLib3MFModelBaseMaterial* group = nullptr;
    check(model, lib3mf_model_getbasematerialbyid(model, group_id, &group), "getbasematerialbyid");
    const Handle materials(group);
    BYTE rgba[4] = {};
    check(materials.get(), lib3mf_basematerial_getdisplaycolor(materials.get(), index, &rgba[0], &rgba[1], &rgba[2], &rgba[3]),
          "getdisplaycolor");
    return Color{rgba[0] / 255.0, rgba[1] / 255.0, rgba[2] / 255.0, rgba[3] / 255.0};
}

}  // namespace

std::vector<ThreeMfMesh> read_three_mf(std::string_view package) {
    const LocaleRestorer locale;
    const Handle model = read_model(package);
    PLib3MFModelResourceIterator* created = nullptr;
    check(model.get(), lib3mf_model_getmeshobjects(model.get(), &created), "getmeshobjects");
    const Handle iterator(created);
    std::vector<ThreeMfMesh> result;
    for (;;) {
        BOOL more = 0;
        check(iterator.get(), lib3mf_resourceiterator_movenext(iterator.get(), &more), "movenext");
        if (!more) break;
        PLib3MFModelResource* current = nullptr;
        check(iterator.get(), lib3mf_resourceiterator_getcurrent(iterator.get(), &current), "getcurrent");
        const Handle object(current);
        ThreeMfMesh read;
        read.name = utf8_string(object.get(), "getname", [&](LPSTR buffer, ULONG size, ULONG* needed) {
            return lib3mf_object_getnameutf8(object.get(), buffer, size, needed);
        });
        DWORD vertex_count = 0, triangle_count = 0;
        check(object.get(), lib3mf_meshobject_getvertexcount(object.get(), &vertex_count), "getvertexcount");
        check(object.get(), lib3mf_meshobject_gettrianglecount(object.get(), &triangle_count), "gettrianglecount");
        std::vector<MODELMESHVERTEX> vertices(vertex_count);
        std::vector<MODELMESHTRIANGLE> triangles(triangle_count);
        if (vertex_count > 0)
            check(object.get(), lib3mf_meshobject_getvertices(object.get(), vertices.data(), vertex_count, nullptr), "getvertices");
        if (triangle_count > 0)
            check(object.get(), lib3mf_meshobject_gettriangleindices(object.get(), triangles.data(), triangle_count, nullptr),
                  "gettriangleindices");
        read.mesh.vertices.reserve(vertex_count);
        for (const MODELMESHVERTEX& v : vertices) read.mesh.vertices.push_back({v.m_fPosition[0], v.m_fPosition[1], v.m_fPosition[2]});
        read.mesh.triangles.reserve(triangle_count);
        for (const MODELMESHTRIANGLE& t : triangles) read.mesh.triangles.push_back({t.m_nIndices[0], t.m_nIndices[1], t.m_nIndices[2]});
        read.color = base_material_color(model.get(), object.get());
        result.push_back(std::move(read));
    }
    return result;
}

std::vector<std::pair<std::string, std::string>> read_three_mf_metadata(std::string_view package) {
    const LocaleRestorer locale;
    const Handle model = read_model(package);
    DWORD count = 0;
    check(model.get(), lib3mf_model_getmetadatacount(model.get(), &count), "getmetadatacount");
    std::vector<std::pair<std::string, std::string>> result;
    for (DWORD i = 0; i < count; ++i) {
        std::string key = utf8_string(model.get(), "getmetadatakey", [&](LPSTR buffer, ULONG size, ULONG* needed) {
            return lib3mf_model_getmetadatakeyutf8(model.get(), i, buffer, size, needed);
        });
        std::string value = utf8_string(model.get(), "getmetadatavalue", [&](LPSTR buffer, ULONG size, ULONG* needed) {
            return lib3mf_model_getmetadatavalueutf8(model.get(), i, buffer, size, needed);
        });
        result.emplace_back(std::move(key), std::move(value));
    }
    return result;
}

}  // namespace ratbez::exporter

// The memory the mesh checks may count on (mesh_checks.hpp: memory_left, checked_triangle_limit), outside the
// CGAL translation unit so that it compiles in a second.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>

#include "ratbez/export/mesh_checks.hpp"

namespace ratbez::exporter {
namespace {

// A field of /proc/self/status in bytes ("VmSize:  123456 kB"), 0 when it cannot be read.
std::size_t status_bytes(const char* field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    const std::size_t length = std::strlen(field);
    while (std::getline(status, line))
        if (line.compare(0, length, field) == 0 && line.size() > length && line[length] == ':') {
            unsigned long long kilobytes = 0;
            if (std::sscanf(line.c_str() + length + 1, "%llu", &kilobytes) == 1) return static_cast<std::size_t>(kilobytes) * 1024;
        }
    return 0;
}

// A limit's soft value less the use it counts, if the limit is set.
std::optional<std::size_t> left_under(int resource, const char* used_field) {
    rlimit limit{};
    if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
    const std::size_t used = status_bytes(used_field);
    return limit.rlim_cur > used ? static_cast<std::size_t>(limit.rlim_cur - used) : std::size_t{0};
}

// "1.8 GB", "350 MB": two significant digits are plenty for a limit.
std::string bytes_text(double bytes) {
    char text[32];
    if (bytes >= 1e9)
        std::snprintf(text, sizeof text, "%.2g GB", bytes / 1e9);
    else
        std::snprintf(text, sizeof text, "%.2g MB", bytes / 1e6);
    return text;
}

}  // namespace

std::optional<std::size_t> memory_left() {
    const std::optional<std::size_t> address_space = left_under(RLIMIT_AS, "VmSize");
    const std::optional<std::size_t> data = left_under(RLIMIT_DATA, "VmData");
    if (address_space && data) return std::min(*address_space, *data);
    return address_space ? address_space : data;
}

TriangleLimit checked_triangle_limit(const MeshCheckOptions& options) {
    const double per_triangle = static_cast<double>(bytes_per_checked_triangle);
    TriangleLimit result{options.max_triangles,
                         "the export's mesh checks' limit of " + std::to_string(options.max_triangles) +
                             " triangles (about " + bytes_text(static_cast<double>(options.max_triangles) * per_triangle) +
                             " at " + std::to_string(bytes_per_checked_triangle) + " bytes each)"};
    if (const std::optional<std::size_t> left = memory_left()) {
        const std::size_t room = *left / bytes_per_checked_triangle;
        if (room < result.triangles)
            result = {room, "the " + std::to_string(room) + " triangles the process's memory limit leaves room for (" +
                                bytes_text(static_cast<double>(*left)) + " left at " +
                                std::to_string(bytes_per_checked_triangle) + " bytes each)"};
    }
    return result;
}

}  // namespace ratbez::exporter

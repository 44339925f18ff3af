// Area and volume of exact solids (properties.hpp): the adaptive cubature of analysis/cubature.hpp on every
// face (through brep/face_integrals.hpp), with the solid's argument name in its errors and non-finite
// totals refused.
#include "ratbez/properties.hpp"

#include <cmath>
#include <future>

#include "analysis/cubature.hpp"
#include "brep/face_integrals.hpp"
#include "ratbez/error.hpp"

namespace ratbez {

double surface_area(const Face& face) { return detail::faces_area({face}, "face"); }

double surface_area(const NurbsSurface& surface) { return detail::surface_area(surface, "surface"); }

double surface_area(const Solid& solid) { return surface_area(solid, Progress{}); }

double enclosed_volume(const Solid& solid) { return enclosed_volume(solid, Progress{}); }

double surface_area(const Solid& solid, const Progress& progress) {
    const double area = detail::faces_area(solid.faces(), "solid", progress);
    require(std::isfinite(area), "solid", "its area is not a finite double (the solid is too large to measure)");
    if (progress) progress(1.0);
    return area;
}

double enclosed_volume(const Solid& solid, const Progress& progress) {
    const double volume = detail::faces_volume(solid.faces(), "solid", false, progress);
    // A solid of size 1e150 has a volume past the double range: say so rather than return inf.
    require(std::isfinite(volume), "solid", "its volume is not a finite double (the solid is too large to measure)");
    if (progress) progress(1.0);
    return volume;
}

SolidMeasures measure(const Solid& solid) {
    // The kernel keeps no mutable state, so the two integrals may run at once; the area's thread is joined before
    // an error of the volume's leaves (std::async's future waits in its destructor).
    std::future<double> area = std::async(std::launch::async, [&solid] { return surface_area(solid); });
    const double volume = enclosed_volume(solid);
    return SolidMeasures{area.get(), volume};
}

}  // namespace ratbez

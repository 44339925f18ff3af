#pragma once
// Checking a solid against OpenCASCADE: validity of the converted B-rep, our evaluation against OCCT's
// evaluation of the converted geometry, our points against OCCT's analytic surface of the same
// primitive, and volumes (ours / OCCT / closed form). OCCT-free header (see files.hpp).

#include <optional>
#include <string>
#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/occt/convert_options.hpp"

namespace ratbez::occt {

// What the solid is known to be, for the analytic-surface and closed-form comparisons.
struct AnalyticShape {
    enum class Kind { none, cylinder, cone, sphere, torus, revolution } kind = Kind::none;
    Vec3 center{}, axis{0, 0, 1};
    double radius1 = 0, radius2 = 0, height = 0;  // cylinder: radius1, height; cone: radius1, radius2, height;
                                                   // sphere: radius1; torus: radius1 = major, radius2 = minor
    std::optional<double> closed_form_volume;
};

struct CheckOptions {
    int grid = 50;                    // samples per face direction for the deviation grids
    double deviation_limit = 1e-9;    // relative to the solid's size: larger deviations fail the check
    double volume_limit = 1e-6;       // relative volume disagreement that fails the check
    AnalyticShape analytic{};
    ConvertOptions convert{};         // the representation checked (validity, deviation, OCCT's volume)
};

struct CheckReport {
    bool valid = false;               // BRepCheck_Analyzer
    bool closed = false;              // every edge of the shell shared by two faces
    double max_deviation = 0;         // |ours - OCCT D0| over the grids of every face (absolute)
    std::optional<double> max_analytic_deviation;  // distance of our points to OCCT's analytic surface
    double volume = 0, occt_volume = 0, area = 0, occt_area = 0;
    std::optional<double> closed_form_volume;
    double size = 0;                  // bounding-box diagonal, the scale deviations are relative to
    bool passed = false;              // everything above within the limits
    std::vector<std::string> failures;  // one line per failed check
};

CheckReport check(const Solid& solid, const CheckOptions& options = {});

// A human-readable table of the report (one row per quantity, a PASS / FAIL column).
std::string format_report(const CheckReport& report);

}  // namespace ratbez::occt

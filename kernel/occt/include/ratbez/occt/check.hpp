#pragma once
// Checking a solid against OpenCASCADE: validity of the converted B-rep, our evaluation against OCCT's
// evaluation of the converted geometry, our points against OCCT's analytic surface of what the solid
// was built as (Solid::construction(): the primitive's quadric or torus, a revolution's surface of
// revolution), and volumes (ours / OCCT / the construction's closed form). OCCT-free header (see files.hpp).

#include <optional>
#include <string>
#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/occt/convert_options.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::occt {

struct CheckOptions {
    int grid = 50;                    // samples per face direction for the deviation grids
    double deviation_limit = 1e-9;    // relative to the solid's size: larger deviations fail the check
    double volume_limit = 1e-6;       // relative volume disagreement that fails the check
    ConvertOptions convert{};         // the representation checked (validity, deviation, OCCT's volume)
    // OpenCASCADE's BOP argument analysis (below). Off only for callers that assert validity and deviation
    // alone on many random solids: its face self-intersection search can take minutes on extreme weights.
    bool bop_analysis = true;
    // The analysis runs in a child process and is stopped past this wall-clock time (or 4 GiB): it can run on for
    // minutes and gigabytes on real parts. The report then says "BOP check: not completed: ..." (not passed).
    double bop_seconds = 60;
    Progress progress;                // optional: called between the steps and faces; may throw to cancel
};

struct CheckReport {
    bool valid = false;               // BRepCheck_Analyzer
    bool closed = false;              // every edge of the shell shared by two faces
    double max_deviation = 0;         // |ours - OCCT D0| over the grids of every face (absolute)
    std::optional<double> max_analytic_deviation;  // distance of our points to OCCT's analytic surface (a
                                                   // revolution: to its point at the same profile parameter);
                                                   // none for an extrusion or a Solid of kind none
    double volume = 0, occt_volume = 0, area = 0, occt_area = 0;
    std::optional<double> closed_form_volume;      // Construction::exact_volume()
    double size = 0;                  // bounding-box diagonal, the scale deviations are relative to
    // OpenCASCADE's BOP argument analysis (BOPAlgo_ArgumentAnalyzer with every check FreeCAD's "Check geometry"
    // > "Run BOP check" turns on): what a boolean, fillet or offset would trip over.
    bool bop_clean = false;           // it found nothing
    int self_intersections = 0;       // BOPAlgo SelfIntersect findings (sub-shapes of the solid that meet)
    int small_edges = 0;              // BOPAlgo TooSmallEdge findings
    std::vector<std::string> bop_findings;  // every finding: "BOPAlgo <status>: <shape kinds> (our face i)"
    bool passed = false;              // everything above within the limits and the BOP analysis clean
    std::vector<std::string> failures;  // one line per failed check
};

CheckReport check(const Solid& solid, const CheckOptions& options = {});

// Every entry of the report under its name, the keys of `ratbez check --json` and of Python's occt_check
// dict: visit(name, value) with a bool, an int, a double, a std::optional<double> or a list of strings.
template <class Visit>
void for_each_entry(const CheckReport& report, Visit&& visit) {
    visit("valid", report.valid);
    visit("closed", report.closed);
    visit("max_deviation", report.max_deviation);
    visit("max_analytic_deviation", report.max_analytic_deviation);
    visit("volume", report.volume);
    visit("occt_volume", report.occt_volume);
    visit("area", report.area);
    visit("occt_area", report.occt_area);
    visit("closed_form_volume", report.closed_form_volume);
    visit("size", report.size);
    visit("bop_clean", report.bop_clean);
    visit("self_intersections", report.self_intersections);
    visit("small_edges", report.small_edges);
    visit("bop_findings", report.bop_findings);
    visit("passed", report.passed);
    visit("failures", report.failures);
}

// A human-readable table of the report (one row per quantity, a PASS / FAIL column).
std::string format_report(const CheckReport& report);

}  // namespace ratbez::occt

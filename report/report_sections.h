#pragma once

// The scan report's text sections (report_html.h), each an HTML fragment from the scan's inputs.
// A section whose data the scan did not write says so in a line or is left out.

#include <string>

#include "report/report_inputs.h"

namespace avc::report {

std::string HeaderSection(const ReportInputs& in);      // id, date, state, images
std::string KeyFiguresSection(const ReportInputs& in);  // traits; ground-truth scores if any
std::string TimingsSection(const ReportInputs& in);     // per phase: table and bar chart
std::string ViewsSection(const ReportInputs& in);       // every capture: phase, reason, kept
std::string ClustersSection(const ReportInputs& in);    // traits per cluster
std::string SurfaceSection(const ReportInputs& in);     // what the surfacer made, its warnings
std::string CalibrationSection(const ReportInputs& in);
std::string PlannerSection(const ReportInputs& in);
std::string ConfigurationSection(const ReportInputs& in);  // what each stage ran with
std::string NotesSection(const ReportInputs& in);          // inputs left out

}  // namespace avc::report

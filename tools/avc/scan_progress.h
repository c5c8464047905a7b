#pragma once

// What `avc scan` and `avc demo` show of a scan: the progress line (phase, images, elapsed, ETA;
// rewritten in place on a terminal, one line per event in a log) and the closing message with
// the exit code.

#include "orchestrator/scan_run.h"

namespace avc::cli {

void ShowScanProgress(const orchestrator::ScanProgress& progress);

// Prints where the results are, or why the scan stopped and how to resume it. Returns the exit
// code: 0 done, 3 stopped by a fault, 4 paused.
int ReportScanOutcome(const orchestrator::ScanOutcome& outcome);

}  // namespace avc::cli

// The single-scan job's resize step (scan_steps.cc), in its own file so the
// measure steps do not pull in the resize library's headers.
#ifndef BESPOKE_PIPELINE_BATCH_SCAN_STEP_RESIZE_H_
#define BESPOKE_PIPELINE_BATCH_SCAN_STEP_RESIZE_H_

#include "pipeline/batch/scan_steps.h"

namespace bespoke {

// The job's design drafted at its base size and fitted to the job's
// measurements (as `bespoke resize --design D`, default GA settings):
// fitted.json/.svg/.dxf and resize_report.json in the scan's folder. A
// binding needing a measurement the scan lacks is an InputError naming it.
void ResizeStep(JobState& s);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_SCAN_STEP_RESIZE_H_

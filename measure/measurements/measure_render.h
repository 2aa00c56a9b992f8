// A picture for a person to check the measuring at a glance: the scan seen
// from the front and from the right side (one scale), with the datum points
// (labelled), the girth loops (hull polygons, closed) and the geodesic paths
// drawn over it (scanners/render/render.h does the drawing).
//
// Input: the cleaned cloud and landmarks in the body frame (mm) and the
// result of Measure with keep_geometry. Colours: girths red, geodesic
// lengths blue, breadths and point-to-line distances green; flagged
// measurements orange. Output: an RGB image; WriteMeasureRender writes a PNG
// atomically. Failure: InputError as Render (empty scene, bad folder, not
// .png).
#ifndef BESPOKE_MEASURE_MEASUREMENTS_MEASURE_RENDER_H_
#define BESPOKE_MEASURE_MEASUREMENTS_MEASURE_RENDER_H_

#include <filesystem>

#include "measure/landmarks/landmarks.h"
#include "measure/measurements/measure.h"
#include "scanners/render/render.h"

namespace bespoke {

RgbImage RenderMeasurements(const PointCloud& body_cloud, const LandmarkSet& landmarks,
                            const MeasureResult& result, int height_px = 900);

void WriteMeasureRender(const std::filesystem::path& file, const PointCloud& body_cloud,
                        const LandmarkSet& landmarks, const MeasureResult& result,
                        int height_px = 900);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_MEASURE_RENDER_H_

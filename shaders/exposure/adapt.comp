#version 460
// Meters the histogram — the mean log2 luminance of the non-black pixels between two
// percentiles — and moves the exposure in use a fraction of the way there (in stops), or all of
// it on a restart. One invocation: 128 bins.
#extension GL_GOOGLE_include_directive : require

#include "shared/exposure.h"

layout(local_size_x = 1) in;

layout(set = 0, binding = EXPOSURE_BINDING_PARAMS, std430) readonly buffer Params { ExposureParams gParams; };
layout(set = 0, binding = EXPOSURE_BINDING_HISTOGRAM, std430) readonly buffer Histogram { uint gHistogram[]; };
layout(set = 0, binding = EXPOSURE_BINDING_STATE, std430) buffer State { ExposureState gState; };

void main() {
    float total = 0.0;
    for (uint b = 1u; b < EXPOSURE_BINS; ++b) total += float(gHistogram[b]);
    const float previous = gParams.restart != 0u ? 0.0 : log2(max(gState.value.x, 1.0e-30));
    if (total <= 0.0) {  // a black image: nothing to meter, keep the exposure
        gState.value = vec4(exp2(previous), gState.value.y, gState.value.z, 0.0);
        return;
    }
    // The pixels ranked lowPercentile..highPercentile, bin by bin (a bin counts by its overlap).
    const float low = gParams.lowPercentile * total, high = gParams.highPercentile * total;
    const float binStops = (EXPOSURE_LOG2_MAX - EXPOSURE_LOG2_MIN) / float(EXPOSURE_BINS);
    float below = 0.0, sum = 0.0, weight = 0.0;
    for (uint b = 1u; b < EXPOSURE_BINS; ++b) {
        const float n = float(gHistogram[b]);
        const float take = max(min(below + n, high) - max(below, low), 0.0);
        sum += take * (EXPOSURE_LOG2_MIN + (float(b) + 0.5) * binStops);
        weight += take;
        below += n;
    }
    const float metered = sum / max(weight, 1.0);
    const float target = clamp(log2(gParams.key) - metered, gParams.minLog2, gParams.maxLog2);
    const float stops = gParams.restart != 0u ? target : mix(previous, target, gParams.adaptation);
    gState.value = vec4(exp2(stops), metered, exp2(target), total);
}

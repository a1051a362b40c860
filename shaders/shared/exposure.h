// Automatic exposure's histogram, state and bindings (shaders/exposure/, engine/render/exposure/).
// The tonemap reads the state's exposure when FrameParams.exposure.y is 1 (auto), else the fixed
// FrameParams.exposure.x.
#ifndef SHARED_EXPOSURE_H
#define SHARED_EXPOSURE_H
#include "interop.h"

SHARED_BEGIN

// Bins of log2 luminance over [EXPOSURE_LOG2_MIN, EXPOSURE_LOG2_MAX): a quarter stop each. Bin 0
// holds what is darker (black pixels among them), which the metering leaves out.
SHARED_CONST uint EXPOSURE_BINS = 128u;
SHARED_CONST float EXPOSURE_LOG2_MIN = -16.0f;
SHARED_CONST float EXPOSURE_LOG2_MAX = 16.0f;

struct ExposureParams {
    float key;         // exposure = key / metered luminance
    float adaptation;  // fraction of the way (in stops) to the metered exposure per frame
    uint restart;      // 1: take the metered exposure at once (first frame, new size or settings)
    float lowPercentile;     // the metering averages the pixels between these percentiles of the
    float highPercentile;    // non-black ones: dark corners and a few lamps do not swing it
    float minLog2, maxLog2;  // the exposure's range in stops
    uint pad0;
};
SHARED_ASSERT_SIZE(ExposureParams, 32);

struct ExposureState {
    vec4 value;  // x exposure in use, y metered log2 luminance, z the metered exposure, w pixels
                 // metered
};
SHARED_ASSERT_SIZE(ExposureState, 16);

SHARED_CONST uint EXPOSURE_BINDING_FRAME = 0u;      // FrameParams
SHARED_CONST uint EXPOSURE_BINDING_PARAMS = 1u;     // ExposureParams
SHARED_CONST uint EXPOSURE_BINDING_RADIANCE = 2u;   // vec4 per pixel
SHARED_CONST uint EXPOSURE_BINDING_HISTOGRAM = 3u;  // uint per bin
SHARED_CONST uint EXPOSURE_BINDING_STATE = 4u;      // ExposureState

SHARED_END

#endif

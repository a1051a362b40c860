// Numeric command-line options go through the one number check (core/number_check.h), the same
// as scene files, scripts and the lighting knobs: NaN, infinities and values out of range are
// refused with the option's name, its range and unit ("vox: --fov: must be a finite number in
// (1, 179) degrees, not nan"), exit status 2. Zero is in a range or refused, never "the default":
// options whose default comes from elsewhere (--fov, capture --fps) are optional instead.
#pragma once

#include <CLI/CLI.hpp>

#include "core/number_check.h"

namespace vox {

// A CLI11 check: the whole argument must be a number within `range`.
CLI::Validator numberIn(const engine::NumberRange& range);

// Ranges several commands share.
inline constexpr engine::NumberRange kExposureRange = engine::aboveRange(0.0, 1e6);
inline constexpr engine::NumberRange kFrameCountRange = engine::wholeRange(1, 100000, "frames");
inline constexpr engine::NumberRange kWarmupRange = engine::wholeRange(0, 100000, "frames");
inline constexpr engine::NumberRange kSamplesRange =
    engine::wholeRange(1, 1000000, "samples per pixel");
// --render-scale: the lighting's size as a fraction of the display's (render, capture, play).
inline constexpr engine::NumberRange kRenderScaleRange = engine::closedRange(1.0 / 16.0, 1.0);

// --render-scale of the commands that write images at --size (vox render, vox capture): one help
// text and one check.
void addRenderScaleOption(CLI::App& cmd, float& scale);

}  // namespace vox

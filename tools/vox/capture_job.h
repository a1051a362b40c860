// A capture as a job (job_manifest.h): `vox capture … --scheduler S --tasks N` splits its frames
// into N slices, each rendered by one task after its warm-up as `--frames A:B` does. A task
// renders only the frames of its slice that are missing, damaged or made with other settings,
// reads each written PNG back, checks it holds what was rendered, and records it in the manifest:
// the file's size and checksum, the settings' hash, the engine, host and device, and its CSV row.
// The join (capture_join.h) makes the single CSV, contact sheet and MP4 from the records.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "capture_options.h"
#include "capture_render.h"
#include "core/json.h"
#include "job_kind.h"

namespace vox {

const job::JobKind& captureJobKind();

// Every input that changes a frame: the world and path files (by checksum), size, frame rate,
// frames, warm-up, exposure, EXR, and the lighting options given.
engine::Json captureSettings(const CaptureOptions& o, const CaptureSetup& setup);

// `vox capture … --scheduler S`: a new job, or the resume of the one in --out.
int submitCaptureJob(const CaptureOptions& o);
// `vox capture … --out DIR --job-task I`: renders task I's frames that need it.
int runCaptureTask(const CaptureOptions& o);

}  // namespace vox

// The options of `vox capture` (docs/CAPTURE.md), shared by its parts: the render loop, the job
// it can be split into, the join and the status.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "job_scheduler.h"
#include "lighting_options.h"

namespace vox {

struct CaptureOptions {
    std::string world;
    std::string path;
    std::string out;
    std::string size = "320x180";
    float renderScale = 1.0f;   // the lighting's size as a fraction of --size (the frames')
    std::optional<double> fps;  // absent: the path file's
    std::string frames;
    std::uint32_t warmup = 30;
    bool exr = false;
    bool noVideo = false;
    std::uint32_t sheet = 24;
    float exposure = 1.0f;
    LightingOptions lighting;
    job::JobOptions job;                   // --scheduler …: split into tasks (capture_job.h)
    std::string join, status;              // --join DIR, --status DIR
    std::optional<std::uint32_t> jobTask;  // --job-task I: run task I of the job in --out
};

}  // namespace vox

// The engine's progress reports (core/progress.h) as a ProgressLine on stderr, shown only once a
// task has run for a second: short generators stay silent, long ones say how far they are.
#pragma once

namespace vox {

void showLongProgress();

}  // namespace vox

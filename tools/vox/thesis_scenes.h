// The thesis's four scenes (thesis §3.2): the worlds the accuracy, sweep, ReSTIR and flythrough
// benches measure when none are named. One list, so that a fifth scene is one line.
#pragma once

#include <string>
#include <vector>

namespace vox {

inline const std::vector<std::string> kThesisScenes{"cornell", "mountain", "letters", "apartments"};

}  // namespace vox

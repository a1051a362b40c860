// One check for every number a user gives — scene and path files, scripts, the command line, the
// HUD and the lighting knobs: finite, in range, a whole number where one is needed, and a message
// that names the key (or option) and states the unit. A range either holds zero or refuses it;
// nothing reads zero as "use the default".
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"

namespace engine {

struct NumberRange {
    double min = 0.0, max = 0.0;
    std::string_view unit;  // "degrees", "voxels", "s"; empty: a plain number
    bool whole = false;     // integers only
    bool minOpen = false;   // min itself is refused: (min, max]
    bool maxOpen = false;   // max itself is refused: [min, max)
};

// closedRange [min, max], aboveRange (min, max], openRange (min, max), wholeRange min..max.
constexpr NumberRange closedRange(double min, double max, std::string_view unit = {}) {
    return NumberRange{min, max, unit, false, false, false};
}
constexpr NumberRange aboveRange(double min, double max, std::string_view unit = {}) {
    return NumberRange{min, max, unit, false, true, false};
}
constexpr NumberRange openRange(double min, double max, std::string_view unit = {}) {
    return NumberRange{min, max, unit, false, true, true};
}
constexpr NumberRange wholeRange(double min, double max, std::string_view unit = {}) {
    return NumberRange{min, max, unit, true, false, false};
}

// "(1, 179) degrees", "1..12", "[0, 1]".
std::string describeRange(const NumberRange& range);

// OK, or one line: "NAME must be positive, not -5; allowed: 1..32768 voxels", "NAME is too large
// (max 8192), not 1e+300; allowed: 1..8192 pixels", "NAME must be a finite number in (1, 179)
// degrees, not nan". An
// empty name starts the message at "must" / "too large" (CLI11 names the option itself).
Status checkNumber(std::string_view name, double value, const NumberRange& range);

// The whole of `text` as a number, or nothing. "nan" and "inf" read as themselves, so that
// checkNumber refuses them with the range rather than a vaguer "not a number".
std::optional<double> readNumber(std::string_view text);
// readNumber then checkNumber; text that is no number: "NAME: expected a number in RANGE, got
// 'TEXT'".
Result<double> parseNumber(std::string_view name, std::string_view text, const NumberRange& range);

}  // namespace engine

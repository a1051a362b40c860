#include "core/number_check.h"

#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "core/quoted_string.h"

namespace engine {

std::string describeRange(const NumberRange& r) {
    std::string unit = r.unit.empty() ? "" : fmt::format(" {}", r.unit);
    if (r.whole) return fmt::format("{}..{}{}", r.min, r.max, unit);
    return fmt::format("{}{}, {}{}{}", r.minOpen ? '(' : '[', r.min, r.max, r.maxOpen ? ')' : ']',
                       unit);
}

Status checkNumber(std::string_view name, double v, const NumberRange& r) {
    // With no name the message starts at the verb: CLI11 puts "--option: " in front of it.
    std::string who = name.empty() ? "" : fmt::format("{} ", name);
    std::string whoIs = name.empty() ? "" : fmt::format("{} is ", name);
    if (!std::isfinite(v))
        return makeError("{}must be a finite number in {}, not {}", who, describeRange(r), v);
    if (r.whole && v != std::floor(v))
        return makeError("{}must be a whole number in {}, not {}", who, describeRange(r), v);
    bool low = r.minOpen ? !(v > r.min) : !(v >= r.min);
    bool high = r.maxOpen ? !(v < r.max) : !(v <= r.max);
    // A range starting at or above zero that refuses zero is "positive": say so for v <= 0.
    bool positive = r.min > 0.0 || (r.min == 0.0 && r.minOpen);
    if (low && positive && v <= 0.0)
        return makeError("{}must be positive, not {}; allowed: {}", who, v, describeRange(r));
    if (low)
        return makeError("{}too small (min {}), not {}; allowed: {}", whoIs, r.min, v,
                         describeRange(r));
    if (high)
        return makeError("{}too large (max {}), not {}; allowed: {}", whoIs, r.max, v,
                         describeRange(r));
    return {};
}

std::optional<double> readNumber(std::string_view text) {
    double v = 0.0;
    const char* end = text.data() + text.size();
    if (!text.empty() && text.front() == '+')
        return std::nullopt;  // from_chars reads no '+' either
    auto [stop, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || stop != end) return std::nullopt;
    return v;
}

Result<double> parseNumber(std::string_view name, std::string_view text, const NumberRange& range) {
    std::optional<double> v = readNumber(text);
    if (!v)
        return makeError("{}: expected a number in {}, got '{}'", name, describeRange(range),
                         printableText(text));
    if (Status ok = checkNumber(name, *v, range); !ok) return ok.error();
    return *v;
}

}  // namespace engine

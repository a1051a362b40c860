#include "number_options.h"

namespace vox {

CLI::Validator numberIn(const engine::NumberRange& range) {
    return CLI::Validator(
        [range](std::string& text) -> std::string {
            auto v = engine::parseNumber("", text, range);
            if (v.ok()) return {};
            // parseNumber's "': expected ..." for text that is no number; drop the empty name's ":
            // ".
            const std::string& m = v.error().message;
            return m.rfind(": ", 0) == 0 ? m.substr(2) : m;
        },
        engine::describeRange(range));
}

void addRenderScaleOption(CLI::App& cmd, float& scale) {
    cmd.add_option("--render-scale", scale,
                   "Render resolution as a fraction of --size; the display's reconstruction "
                   "(--display) resolves it to --size")
        ->capture_default_str()
        ->check(numberIn(kRenderScaleRange));
}

}  // namespace vox

// vox compare A.exr B.exr: error of image A against reference B (thesis §3.3 MAE and MSE, RMAE),
// optionally an error heat map and a JSON record.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "command_files.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "core/quoted_string.h"
#include "io/image_io.h"
#include "metrics/heat_map.h"
#include "metrics/image_metrics.h"
#include "number_options.h"

namespace vox {

namespace {

struct CompareOptions {
    std::string image, reference;
    std::string heatmap, json;
    std::string heatmapError = "abs";
    std::optional<float> heatmapMax;  // absent: the 99th percentile
};

engine::Result<engine::io::ExrImage> loadExr(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return engine::makeError("{}: no such file", path);
    auto image = engine::io::readExr(path);
    if (!image) {
        // OpenEXR's messages can span lines; the command line promises one.
        std::string message = image.error().message;
        for (char& c : message) c = c == '\n' ? ' ' : c;
        return engine::Error{message};
    }
    return image;
}

// JSON has no NaN or infinity; null says "not a number" without breaking parsers.
std::string jsonNumber(double v) { return std::isfinite(v) ? fmt::format("{:.9g}", v) : "null"; }

int runCompare(const CompareOptions& o) {
    using namespace engine::metrics;
    PixelErrorKind kind;
    if (o.heatmapError == "abs")
        kind = PixelErrorKind::Absolute;
    else if (o.heatmapError == "squared")
        kind = PixelErrorKind::Squared;
    else if (o.heatmapError == "relative")
        kind = PixelErrorKind::Relative;
    else
        return fail(engine::makeError(
            "--heatmap-error: expected abs, squared or relative, got '{}'", o.heatmapError));
    if (!o.heatmap.empty() && std::filesystem::path(o.heatmap).extension() != ".png")
        return fail(engine::makeError("--heatmap {}: the file must end in .png", o.heatmap));

    if (engine::Status s =
            checkCommandFiles({{"the image", o.image}, {"the reference", o.reference}},
                              {{"--heatmap", o.heatmap}, {"--json", o.json}});
        !s)
        return fail(s.error());
    auto image = loadExr(o.image);
    if (!image) return fail(image.error());
    auto reference = loadExr(o.reference);
    if (!reference) return fail(reference.error());
    if (image->width != reference->width || image->height != reference->height)
        return fail(engine::makeError("{} is {}x{} but the reference {} is {}x{}", o.image,
                                      image->width, image->height, o.reference, reference->width,
                                      reference->height));
    ImageView a{image->pixels, image->width, image->height};
    ImageView b{reference->pixels, reference->width, reference->height};
    auto errors = compareImages(a, b);
    if (!errors) return fail(engine::makeError("{}: {}", o.image, errors.error().message));

    std::printf("image      %s (%ux%u)\n", o.image.c_str(), image->width, image->height);
    std::printf("reference  %s\n", o.reference.c_str());
    std::printf("MAE        %.6g   (thesis eq. 4)\n", errors->mae);
    std::printf("MSE        %.6g   (thesis eq. 2)\n", errors->mse);
    std::printf("RMAE       %.6g   (mean |a-b| / (|b| + %g))\n", errors->rmae, kRmaeEpsilon);
    if (errors->nonFinitePixels > 0)
        std::printf("warning    %llu pixel(s) hold NaN or infinity\n",
                    static_cast<unsigned long long>(errors->nonFinitePixels));

    HeatMap map;
    if (!o.heatmap.empty()) {
        auto values = perPixelError(a, b, kind);
        if (!values) return fail(values.error());
        std::error_code ec;
        std::filesystem::path out(o.heatmap);
        if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);
        auto written = writeHeatMap(out, *values, a.width, a.height,
                                    HeatMapOptions{o.heatmapMax.value_or(0.0f), true});
        if (!written) return fail(written.error());
        map = std::move(*written);
        std::printf("wrote      %s (%s error per pixel, colour range 0 .. %.3g)\n",
                    o.heatmap.c_str(), o.heatmapError.c_str(), map.maxValue);
    }
    if (!o.json.empty()) {
        std::string text = fmt::format(
            "{{\n  \"image\": {},\n  \"reference\": {},\n  \"width\": {},\n  \"height\": {},\n  "
            "\"mae\": {},\n"
            "  \"mse\": {},\n  \"rmae\": {},\n  \"rmae_epsilon\": {},\n  \"non_finite_pixels\": {}",
            engine::quotedString(o.image), engine::quotedString(o.reference), a.width, a.height,
            jsonNumber(errors->mae), jsonNumber(errors->mse), jsonNumber(errors->rmae),
            kRmaeEpsilon, errors->nonFinitePixels);
        if (!o.heatmap.empty())
            text += fmt::format(",\n  \"heatmap\": {{\"path\": {}, \"error\": {}, \"max\": {}}}",
                                engine::quotedString(o.heatmap),
                                engine::quotedString(o.heatmapError), jsonNumber(map.maxValue));
        text += "\n}\n";
        std::error_code ec;
        std::filesystem::path out(o.json);
        if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);
        if (engine::Status s = engine::writeFileAtomically(out, text); !s) return fail(s.error());
        std::printf("wrote      %s\n", o.json.c_str());
    }
    return 0;
}

}  // namespace

void addCompareCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("compare",
                                   "Error of an EXR image against a reference EXR: MAE, MSE, RMAE");
    auto o = std::make_shared<CompareOptions>();
    cmd->add_option("image", o->image, "Image to measure (linear EXR)")->required();
    cmd->add_option("reference", o->reference,
                    "Reference image (linear EXR), e.g. a converged path trace")
        ->required();
    cmd->add_option("--heatmap", o->heatmap,
                    "Write a per-pixel error heat map (PNG, with a legend strip)");
    cmd->add_option("--heatmap-error", o->heatmapError,
                    "Error shown in the heat map: abs, squared or relative")
        ->capture_default_str();
    cmd->add_option("--heatmap-max", o->heatmapMax,
                    "Error at the top of the colour ramp (default: the 99th percentile)")
        ->check(numberIn(engine::aboveRange(0.0, 1e6)));
    cmd->add_option("--json", o->json, "Also write the results as JSON");
    cmd->callback([o, &exitCode] { exitCode = runCompare(*o); });
}

}  // namespace vox

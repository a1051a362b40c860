// vox bench restir's results as they are written: a JSON of every seed and ratio, a CSV of
// medians per scene and row (for `vox bench recommend --sampling`), a markdown table and the
// lines on stdout.
#pragma once

#include <filesystem>
#include <string>

#include "core/atomic_file.h"
#include "restir_bench.h"

namespace vox {

class RestirReport {
public:
    explicit RestirReport(const RestirSetup& setup) : mSetup(setup) {}

    // Opens the JSON and, beside it, the CSV, and writes their heads.
    engine::Status open(const std::filesystem::path& json, const std::string& device);
    // One scene's rows, in all three and on stdout; `last`: no comma after it in the JSON.
    void addScene(const std::string& scene, const SceneResults& results, bool last);
    engine::Status commit(double wallSeconds);

    const std::filesystem::path& csvPath() const { return mCsvPath; }
    const std::string& table() const { return mTable; }

private:
    void addRow(const std::string& scene, const SceneResults& results, std::size_t i);
    void addVersus(const RowResult& r, std::size_t i, const SceneResults& results);

    const RestirSetup& mSetup;
    engine::AtomicFile mJson, mCsv;
    std::filesystem::path mCsvPath;
    std::string mTable;
};

}  // namespace vox

// MagicaVoxel .vox export (docs/VOX.md): the world's solid voxels as models of at most 256^3
// (MagicaVoxel's limit), placed by a scene graph (one group of transform + shape pairs), with
// the axes of io/vox_import.h reversed so that an import gives the same world back.
//
// Colours: when the world's materials have at most 255 distinct (sRGB 8-bit colour, emission)
// pairs each gets its own palette index, exactly; beyond that the albedos are quantised to 255
// colours (io/colour_quantizer.h, weighted by voxel count) and the error is reported. Emissive
// materials become MATL `_emit` entries whose _emit/_flux give their strength back
// (io/vox_import.h); MagicaVoxel emits the palette colour, so an emission colour that differs
// from the albedo is not kept. The file is written atomically (temporary file, then rename).
#pragma once

#include <cstdint>
#include <filesystem>

#include "core/error.h"
#include "world/scene.h"

namespace engine::io {

struct VoxExportReport {
    std::size_t models = 0;
    std::uint64_t solidVoxels = 0;
    int colours = 0;         // palette indices used
    int emissive = 0;        // of them, with a MATL _emit
    bool quantised = false;  // more than 255 distinct colours: albedos quantised
    std::uint64_t changedVoxels =
        0;                         // voxels whose colour or emission the .vox cannot keep exactly
    double meanColourError = 0.0;  // linear RGB distance, per voxel (quantised exports)
    double maxColourError = 0.0;
    std::uint64_t emissionColourDiffers =
        0;  // emissive voxels whose emission colour is not their albedo
    std::uint64_t fileBytes = 0;
};

Status exportVox(const world::Scene& scene, const std::filesystem::path& path,
                 VoxExportReport* report = nullptr);

}  // namespace engine::io

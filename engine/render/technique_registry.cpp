#include "render/technique_registry.h"

#include "render/accumulation/accumulation.h"
#include "render/baselines/light_sampling.h"
#include "render/denoiser/denoiser.h"
#include "render/dvf_sky/dvf_sky.h"
#include "render/exposure/auto_exposure.h"
#include "render/irradiance_cache/irradiance_cache.h"
#include "render/light_tiles/light_tiles.h"
#include "render/passes/preview_shading.h"
#include "render/path_indirect/path_indirect.h"
#include "render/reference/reference.h"
#include "render/regir/regir_grid.h"
#include "render/restir/restir.h"
#include "render/upsampling/temporal_upsampling.h"
#include "render/vct/voxel_cone_tracing.h"

namespace engine::render {

namespace {

// In the order their passes run: what draws lights first (the tiles and ReGIR's grid feed the
// candidates), then the direct light, then the terms added to it.
const TechniqueEntry kTechniques[] = {
    techniqueEntry<LightTiles>("light_tiles"),
    techniqueEntry<RegirGrid>("regir"),
    techniqueEntry<PreviewShading>("preview"),
    techniqueEntry<Restir>("restir"),
    techniqueEntry<LightSampling>("baselines"),
    techniqueEntry<Reference>("reference"),
    techniqueEntry<DvfSky>("sky"),
    techniqueEntry<PathIndirect>("path"),
    techniqueEntry<VoxelConeTracing>("vct"),
    techniqueEntry<IrradianceCache>("cache"),
    techniqueEntry<Denoiser>("denoiser"),              // the lighting of every term, denoised
    techniqueEntry<Accumulation>("accumulation"),      // the mean of every term
    techniqueEntry<AutoExposure>("exposure"),          // meters what the display shows
    techniqueEntry<TemporalUpsampling>("upsampling"),  // last: resolves it to the display
};

}  // namespace

std::span<const TechniqueEntry> techniqueRegistry() { return kTechniques; }

}  // namespace engine::render

#include "render/shader_features.h"

#include "render/light_tiles/light_tiles.h"
#include "render/regir/regir_grid.h"
#include "render/restir/restir_params.h"

namespace engine::render {

ShaderFeatures shaderFeatures(const lighting::LightingSettings& l, bool dynamicGrid) {
    const shared::RestirParams restir = restirParams(l, 0);
    ShaderFeatures f{};
    f[FEATURE_REGIR] = regirUsed(l) ? 1u : 0u;
    f[FEATURE_LIGHT_TILES] = lightTilesUsed(l) ? 1u : 0u;
    f[FEATURE_UNIFORM_SAMPLING] = restir.byPower ? 0u : 1u;
    f[FEATURE_POINT_LIGHTS] = restir.area ? 0u : 1u;
    f[FEATURE_CANDIDATE_VISIBILITY] = restir.knobs.candidateVisibility;
    f[FEATURE_UNBIASED] = restir.knobs.unbiased;
    f[FEATURE_CACHE_MULTI_BOUNCE] = l.cache.bounces > 1u ? 1u : 0u;
    f[FEATURE_CACHE_FALLBACK] = l.cache.fallbackRadius > 0u ? 1u : 0u;
    f[FEATURE_DYNAMIC_GRID] = dynamicGrid ? 1u : 0u;
    return f;
}

}  // namespace engine::render

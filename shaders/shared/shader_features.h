// Shader features: optional code a frame's shaders contain, as Vulkan specialization constants
// (constant_id = the number below). Lavapipe runs the code of every branch under a lane mask
// whether or not any lane takes it, so a feature switched off by a uniform knob still cost its
// full price (ReGIR's and the light tiles' branches were 30 % of restir_initial's candidate
// loop with both off). The host compiles one pipeline per combination a frame uses
// (render/shader_features.h says which), and the branches of the features that are off are
// compiled out. Each constant defaults to "present": a pipeline nobody specialised runs the
// generic code, which reads the knobs at run time as before.
#ifndef SHARED_SHADER_FEATURES_H
#define SHARED_SHADER_FEATURES_H

#define FEATURE_REGIR 0                 // candidates from ReGIR's grid (regir/regir.glsl)
#define FEATURE_LIGHT_TILES 1           // lights from presampled tiles (light_tiles/light_tiles.glsl)
#define FEATURE_UNIFORM_SAMPLING 2      // emitters drawn uniformly, not only by power (common/emitters.glsl)
#define FEATURE_POINT_LIGHTS 3          // point mode's light samples (common/emitters.glsl)
#define FEATURE_CANDIDATE_VISIBILITY 4  // ReSTIR's shadow test of the chosen candidate
#define FEATURE_UNBIASED 5              // ReSTIR's pairwise MIS (restir-unbiased)
#define FEATURE_CACHE_MULTI_BOUNCE 6    // the cache's bounce reads the cache at its hits
#define FEATURE_CACHE_FALLBACK 7        // the cache's gather searches the plane for pixels without an entry
#define FEATURE_DYNAMIC_GRID 8          // rays and voxel reads see the dynamic grid (the scene has objects)
#define FEATURE_COUNT 9

#endif

// How a frame is lit: the method and its knobs. One struct for the renderer, the command line
// and (later) scene files and the HUD.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.h"
#include "lighting/accumulation_settings.h"
#include "lighting/display_settings.h"
#include "lighting/exposure_settings.h"
#include "lighting/irradiance_cache_settings.h"
#include "lighting/path_indirect_settings.h"
#include "lighting/vct_settings.h"
#include "shared/regir.h"
#include "shared/restir.h"

namespace engine::lighting {

enum class Method {
    Preview,     // sun + sky ambient + emission, no emitter lighting: for looking at worlds
    Restir,      // Voxel ReSTIR: candidates, temporal and spatial reuse (biased or unbiased)
    Ris,         // resampled importance sampling without reuse
    Uniform,     // N light samples with N shadow rays
    BruteForce,  // every light once (small scenes)
    Reference,   // progressive path tracer: the ground truth
};

// The reference's pixel filter. PixelCentre: one ray through each pixel centre, the pixel every
// other method shades (from the G-buffer) — for measuring their estimators, where the box
// filter's edge coverage would count as their error.
enum class ReferenceFilter { Box, PixelCentre };

// Reference test hooks: write, per pixel, the emitter the GPU derives for the voxel seen through
// the pixel centre instead of radiance (shared/reference.h describes the layout).
enum class ReferenceProbe { None, EmitterShape, EmitterPower };

// Sky light for the real-time methods (render/dvf_sky/). Dvf: discrete visibility fields (masks
// per cell and face over 64 sky directions); Reference: brute-force cosine rays per pixel, the
// sky's direct light (the ground truth the DVF term is tested against); None: the sky lights a
// scene only through an indirect method's bounces. Added to every method but Preview (its own
// ambient) and Reference, and only without an indirect method (whose rays already see the sky).
enum class Sky { None, Dvf, Reference };

struct LightingSettings {
    Method method = Method::Restir;
    bool area = true;  // area lights (else point lights at the centres of their exposed surfaces)
    bool byPower = true;  // candidates from the alias table over power (else uniform)
    shared::RegirKnobs
        regir;  // ReGIR's world-space candidates (sampling regir: regir.enabled, by power too)
    // --sampling auto: the renderer chooses power or regir per scene (render/sampling_choice.h)
    // and sets byPower / regir.enabled to the choice; false once chosen or named.
    bool autoSampling = true;
    bool brickLights = true;
    shared::RestirKnobs restir;         // ReSTIR's knobs and their defaults (M also drives RIS)
    std::uint32_t shadowRays = 1;       // Uniform: samples (and shadow rays) per pixel
    std::uint32_t samplesPerFrame = 1;  // Reference: samples per pixel added per frame
    std::uint32_t bounces = 0;          // Reference: 0 = direct light only
    ReferenceFilter referenceFilter = ReferenceFilter::Box;
    bool referenceMis =
        true;  // Reference: MIS of light and cosine sampling (false: light sampling only)
    ReferenceProbe referenceProbe = ReferenceProbe::None;
    // BruteForce and Uniform test hook: shadow rays per pixel per dispatch (0: as many as
    // lavapipe's loop budget allows, render/loop_budget.h); 1 keeps every dispatch far below it.
    std::uint32_t shadowRaysPerDispatch = 0;
    std::uint32_t seed = 1;
    Indirect indirect =
        Indirect::None;  // Cache, Path and Vct add their term to any method but Reference
    IrradianceCacheSettings cache;
    PathIndirectSettings path;
    VctSettings vct;
    Sky sky = Sky::None;
    AccumulationSettings accumulation;
    ExposureSettings exposure;  // the display's: fixed or metered from the lit image
    DisplaySettings display;    // raw, or reconstructed to the display's size

    bool operator==(const LightingSettings&) const = default;
};

// Which techniques a frame lit with `s` runs: the one answer to "is X on?". The knob tables'
// relevance (lighting_knobs.cpp) and the renderer's frame plan (render/frame_plan.h: what runs,
// its shader features, the memory plan) all ask these.
bool resamples(const LightingSettings& s);              // ReSTIR's or RIS's candidates
bool samplesLightsPerPixel(const LightingSettings& s);  // the baselines: uniform, bruteforce
bool usesCache(const LightingSettings& s);
bool usesPath(const LightingSettings& s);
bool usesVct(const LightingSettings& s);
// The lit image averaged over still frames: not the reference (its own running mean) nor the
// noise-free preview.
bool accumulates(const LightingSettings& s);
bool usesAutoExposure(const LightingSettings& s);
// The image resolved over frames to the display's size (jittered primary rays): every method but
// the reference (its own pixel filter and running mean).
bool reconstructs(const LightingSettings& s);
// The lighting denoised before that: not the noise-free preview.
bool denoises(const LightingSettings& s);
bool usesRegir(const LightingSettings& s);  // ReSTIR and RIS with sampling regir
// ReSTIR and RIS with sampling auto, before the renderer has chosen: ReGIR's knobs may matter.
bool mayUseRegir(const LightingSettings& s);
// Lights drawn by power from the alias table: ReSTIR/RIS candidates and the cache's bounce.
bool drawsLightsByPower(const LightingSettings& s);
// Those draws from presampled light tiles instead (the light_tiles knob).
bool usesLightTiles(const LightingSettings& s);
// A sky term (see Sky): added to every method but Preview and Reference, without an indirect one.
bool usesSkyTerm(const LightingSettings& s);

const char* methodName(Method m);
Result<Method> parseMethod(std::string_view name);

}  // namespace engine::lighting

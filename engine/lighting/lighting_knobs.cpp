#include "lighting/lighting_knobs.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <fmt/format.h>
#include <type_traits>

namespace engine::lighting {
namespace {

// Accessors for knobs stored in a field of LightingSettings or of one of its parts.
template <typename T>
double knobValue(T v) {
    if constexpr (std::is_enum_v<T>)
        return static_cast<double>(static_cast<std::underlying_type_t<T>>(v));
    else
        return static_cast<double>(v);
}
template <typename T>
T fromKnobValue(double v) {
    if constexpr (std::is_enum_v<T>)
        return static_cast<T>(static_cast<std::underlying_type_t<T>>(v));
    else if constexpr (std::is_same_v<T, bool>)
        return v != 0.0;
    else
        return static_cast<T>(v);
}
template <auto Field>
double getField(const LightingSettings& s) {
    return knobValue(s.*Field);
}
template <auto Field>
void setField(LightingSettings& s, double v) {
    s.*Field = fromKnobValue<std::remove_cvref_t<decltype(s.*Field)>>(v);
}
// A field of one technique's part of the settings (s.restir, s.cache).
template <auto Part, auto Field>
double getPartField(const LightingSettings& s) {
    return knobValue((s.*Part).*Field);
}
template <auto Part, auto Field>
void setPartField(LightingSettings& s, double v) {
    (s.*Part).*Field = fromKnobValue<std::remove_cvref_t<decltype((s.*Part).*Field)>>(v);
}

// Knob relevance: which techniques run is lighting_settings.h's (usesCache, usesVct, …).
bool isRestir(const LightingSettings& s) { return s.method == Method::Restir; }
bool samplesEmitters(const LightingSettings& s) { return s.method != Method::Preview; }
bool isUniform(const LightingSettings& s) { return s.method == Method::Uniform; }
bool isReference(const LightingSettings& s) { return s.method == Method::Reference; }
bool vctMitigates(const LightingSettings& s) { return usesVct(s) && s.vct.leakMitigation; }

// --sampling: uniform, power (alias table), regir (ReGIR's grid for ReSTIR and RIS, whose cells
// draw by power; the other methods take power) or auto (power or regir, chosen per scene by the
// renderer: render/sampling_choice.h).
double getSampling(const LightingSettings& s) {
    return s.autoSampling ? 3.0 : s.regir.enabled ? 2.0 : s.byPower ? 1.0 : 0.0;
}
void setSampling(LightingSettings& s, double v) {
    s.byPower = v >= 1.0;
    s.regir.enabled = v == 2.0 ? 1u : 0u;
    s.autoSampling = v >= 3.0;
}

// --method: the methods by name, and restir-unbiased for ReSTIR with the unbiased normalisation.
Status parseMethodKnob(LightingSettings& s, std::string_view text) {
    bool unbiased = text == "restir-unbiased";
    auto m = parseMethod(unbiased ? "restir" : text);
    if (!m) return m.error();
    s.method = *m;
    if (unbiased) s.restir.unbiased = true;
    return {};
}
std::string formatMethodKnob(const LightingSettings& s) { return methodName(s.method); }

// --spatial TAPS,RADIUS, or 0 / off.
Status parseSpatialKnob(LightingSettings& s, std::string_view text) {
    if (text == "0" || text == "off") {
        s.restir.spatial = false;
        return {};
    }
    unsigned taps = 0;
    float radius = 0.0f;
    char extra = 0;
    std::string t(text);
    if (std::sscanf(t.c_str(), "%u,%f%c", &taps, &radius, &extra) != 2 || taps > 16 ||
        !(radius > 0.0f && radius <= 256.0f))
        return makeError(
            "spatial: expected TAPS,RADIUS with taps in 0..16 and radius in (0, 256], or 0; got "
            "'{}'",
            text);
    s.restir.spatial = taps > 0;
    s.restir.spatialTaps = taps;
    s.restir.spatialRadius = radius;
    return {};
}
std::string formatSpatialKnob(const LightingSettings& s) {
    return s.restir.spatial ? fmt::format("{},{}", s.restir.spatialTaps, s.restir.spatialRadius)
                            : "0";
}
Status checkSpatialKnob(const LightingSettings& s) {
    if (s.restir.spatial && (s.restir.spatialTaps < 1 || s.restir.spatialTaps > 16 ||
                             !(s.restir.spatialRadius > 0.0f && s.restir.spatialRadius <= 256.0f)))
        return makeError("spatial: taps must be in 1..16 and radius in (0, 256], not {},{}",
                         s.restir.spatialTaps, s.restir.spatialRadius);
    return {};
}

double getBudgetMb(const LightingSettings& s) {
    return static_cast<double>(s.cache.budgetBytes) / 1048576.0;
}
void setBudgetMb(LightingSettings& s, double mb) {
    s.cache.budgetBytes = static_cast<std::uint64_t>(mb * 1048576.0);
}

constexpr std::array<std::string_view, 6> kMethods{"preview", "restir",     "ris",
                                                   "uniform", "bruteforce", "reference"};
// In the order of enum Indirect.
// In the order of enum Sky.
constexpr std::array<std::string_view, 3> kSky{"none", "dvf", "reference"};
constexpr std::array<std::string_view, 5> kIndirect{"none", "cache", "path", "reference", "vct"};
constexpr std::array<std::string_view, 2> kModes{"point", "area"};
constexpr std::array<std::string_view, 4> kSampling{"uniform", "power", "regir", "auto"};
constexpr std::array<std::string_view, 2> kPixelFilters{"box", "centre"};
// In the order of enum Display.
constexpr std::array<std::string_view, 3> kDisplays{"raw", "upsampled", "denoised"};

using S = LightingSettings;
using C = IrradianceCacheSettings;
using R = shared::RestirKnobs;

const Knob kLighting[] = {
    {.name = "method",
     .help = "Lighting: restir | restir-unbiased | ris | uniform | bruteforce | reference | "
             "preview (restir: "
             "M-weighted reuse, unbiased for a still camera; restir-unbiased: pairwise MIS, "
             "unbiased when it moves)",
     .kind = KnobKind::Custom,
     .choices = kMethods,
     .parse = parseMethodKnob,
     .format = formatMethodKnob},
    {.name = "seed",
     .help = "Random seed",
     .kind = KnobKind::Count,
     .min = 0,
     .max = 4294967295.0,
     .get = getField<&S::seed>,
     .set = setField<&S::seed>},
    {.name = "indirect",
     .help = "Indirect light: none | cache (voxel-face irradiance cache) | path (path-traced "
             "bounces from the "
             "G-buffer, accumulated while still) | reference (the path tracer replaces the method) "
             "| vct (voxel cone "
             "tracing: cheap, leaks through thin walls); a scene's [indirect] mode, else none",
     .kind = KnobKind::Choice,
     .choices = kIndirect,
     .get = getField<&S::indirect>,
     .set = setField<&S::indirect>},
    {.name = "sky",
     .help = "Sky light: none | dvf (discrete visibility fields: per-cell masks of the sky "
             "directions) | reference "
             "(cosine rays per pixel, accumulated while still); added without an indirect method, "
             "whose rays see the "
             "sky already, and not to preview or reference",
     .kind = KnobKind::Choice,
     .choices = kSky,
     .get = getField<&S::sky>,
     .set = setField<&S::sky>},
};

const Knob kEmitters[] = {
    {.name = "mode",
     .help = "Emitters as point or area lights",
     .kind = KnobKind::Choice,
     .choices = kModes,
     .get = getField<&S::area>,
     .set = setField<&S::area>,
     .relevant = samplesEmitters},
    {.name = "sampling",
     .help = "Candidate emitters: uniform, by power (alias table), regir (ReSTIR/RIS: from a "
             "world-space grid of lights resampled per cell by power and distance; other methods "
             "by power), or auto (power or regir per scene: regir when 64+ emitters spread over "
             "2+ of its cells with at most 32 in each)",
     .kind = KnobKind::Choice,
     .choices = kSampling,
     .get = getSampling,
     .set = setSampling,
     .relevant = samplesEmitters},
    {.name = "brick_lights",
     .help = "Uniform emissive bricks as one light",
     .kind = KnobKind::Switch,
     .get = getField<&S::brickLights>,
     .set = setField<&S::brickLights>,
     .relevant = samplesEmitters},
};

// Voxel ReSTIR (Bitterli et al.; candidates also drive RIS).
const Knob kRestir[] = {
    {.name = "candidates",
     .help = "ReSTIR/RIS candidates per pixel (M)",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 1024,
     .get = getPartField<&S::restir, &R::candidates>,
     .set = setPartField<&S::restir, &R::candidates>,
     .relevant = resamples},
    {.name = "temporal",
     .help = "Temporal reuse",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::restir, &R::temporal>,
     .set = setPartField<&S::restir, &R::temporal>,
     .relevant = isRestir},
    {.name = "spatial",
     .help = "Spatial reuse taps,radius in pixels (0 = off)",
     .kind = KnobKind::Custom,
     .relevant = isRestir,
     .parse = parseSpatialKnob,
     .format = formatSpatialKnob,
     .check = checkSpatialKnob},
    {.name = "unbiased",
     .help = "Pairwise MIS in spatial reuse, balance heuristic with last frame's visibility in "
             "temporal reuse (restir-unbiased)",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::restir, &R::unbiased>,
     .set = setPartField<&S::restir, &R::unbiased>,
     .relevant = isRestir},
    {.name = "temporal_cap",
     .help = "Last frame's M is capped at this times M",
     .kind = KnobKind::Real,
     .min = 1,
     .max = 1000,
     .get = getPartField<&S::restir, &R::temporalCap>,
     .set = setPartField<&S::restir, &R::temporalCap>,
     .relevant = isRestir},
    {.name = "depth_tolerance",
     .help = "Reuse between pixels whose depths agree within this fraction",
     .kind = KnobKind::Real,
     .min = 0,
     .max = 10,
     .get = getPartField<&S::restir, &R::depthTolerance>,
     .set = setPartField<&S::restir, &R::depthTolerance>,
     .relevant = isRestir},
    {.name = "candidate_visibility",
     .help = "Shadow-test the chosen candidate before reuse",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::restir, &R::candidateVisibility>,
     .set = setPartField<&S::restir, &R::candidateVisibility>,
     .relevant = isRestir},
    {.name = "light_tiles",
     .help = "ReSTIR candidates and cache bounce lights by power from presampled light tiles "
             "(RTXDI) instead of "
             "alias-table draws: same probabilities, cheaper reads",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::restir, &R::lightTiles>,
     .set = setPartField<&S::restir, &R::lightTiles>,
     .relevant = drawsLightsByPower},
};

const Knob kBaselines[] = {
    {.name = "shadow_rays",
     .help = "uniform: light samples (and shadow rays) per pixel",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 4096,
     .get = getField<&S::shadowRays>,
     .set = setField<&S::shadowRays>,
     .relevant = isUniform},
};

const Knob kReference[] = {
    {.name = "bounces",
     .help = "reference: indirect bounces (0 = direct light only)",
     .kind = KnobKind::Count,
     .min = 0,
     .max = 64,
     .get = getField<&S::bounces>,
     .set = setField<&S::bounces>,
     .relevant = isReference},
    {.name = "pixel_filter",
     .help = "reference: box (jittered over the pixel) | centre (one ray through the pixel centre, "
             "the pixel the other "
             "methods shade)",
     .kind = KnobKind::Choice,
     .choices = kPixelFilters,
     .get = getField<&S::referenceFilter>,
     .set = setField<&S::referenceFilter>,
     .relevant = isReference},
};

// The voxel-face irradiance cache (Cosin Ayerbe et al.).
const Knob kCache[] = {
    {.name = "directions",
     .help = "cache: K directions per voxel face",
     .kind = KnobKind::Count,
     .min = 16,
     .max = 256,
     .get = getPartField<&S::cache, &C::directions>,
     .set = setPartField<&S::cache, &C::directions>,
     .relevant = usesCache},
    {.name = "rays",
     .help = "cache: of the K, rays per face per frame, a divisor of K",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 256,
     .get = getPartField<&S::cache, &C::raysPerUpdate>,
     .set = setPartField<&S::cache, &C::raysPerUpdate>,
     .relevant = usesCache},
    {.name = "bounces",
     .help = "cache: 1 = one bounce (the paper); more reads the cache at each hit",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 8,
     .get = getPartField<&S::cache, &C::bounces>,
     .set = setPartField<&S::cache, &C::bounces>,
     .relevant = usesCache},
    {.name = "alpha",
     .help = "cache: temporal blend factor",
     .kind = KnobKind::Real,
     .min = 0.001,
     .max = 1,
     .get = getPartField<&S::cache, &C::alpha>,
     .set = setPartField<&S::cache, &C::alpha>,
     .relevant = usesCache},
    {.name = "neighbourhood",
     .help = "cache: N^3 around visible dynamic voxels: 0, 3 or 5",
     .kind = KnobKind::Count,
     .min = 0,
     .max = 5,
     .get = getPartField<&S::cache, &C::neighbourhood>,
     .set = setPartField<&S::cache, &C::neighbourhood>,
     .relevant = usesCache},
    {.name = "max_ray",
     .help = "cache: ray length in voxels, also an edit's reach",
     .kind = KnobKind::Real,
     .min = 1,
     .max = 500,
     .get = getPartField<&S::cache, &C::maxRayLength>,
     .set = setPartField<&S::cache, &C::maxRayLength>,
     .relevant = usesCache},
    {.name = "filter",
     .help = "cache: 3^3 filter over neighbouring faces",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::cache, &C::filter>,
     .set = setPartField<&S::cache, &C::filter>,
     .relevant = usesCache},
    {.name = "fade",
     .help = "cache: seconds a dynamic entry takes to fade after its last update",
     .kind = KnobKind::Real,
     .min = 0.001,
     .max = 60,
     .get = getPartField<&S::cache, &C::fadeSeconds>,
     .set = setPartField<&S::cache, &C::fadeSeconds>,
     .relevant = usesCache},
    {.name = "budget_mb",
     .help = "cache: memory budget in MiB; least recently seen evicted",
     .kind = KnobKind::Real,
     .min = 1,
     .max = 16384,
     .get = getBudgetMb,
     .set = setBudgetMb,
     .relevant = usesCache},
    {.name = "budget",
     .help = "cache: rays per frame, spent on new, edited, moving and stale entries first; 0 = all "
             "every frame",
     .kind = KnobKind::Count,
     .min = 0,
     .max = 100000000,
     .get = getPartField<&S::cache, &C::rayBudget>,
     .set = setPartField<&S::cache, &C::rayBudget>,
     .relevant = usesCache},
    {.name = "lod_distance",
     .help = "cache: static faces this far (voxels) share an entry per open 2x2 patch; 0 = off",
     .kind = KnobKind::Real,
     .min = 0,
     .max = 100000,
     .get = getPartField<&S::cache, &C::lodDistance>,
     .set = setPartField<&S::cache, &C::lodDistance>,
     .relevant = usesCache},
    {.name = "fallback",
     .help =
         "cache: voxels a pixel without an entry searches in its face's plane for entries; 0 = off",
     .kind = KnobKind::Count,
     .min = 0,
     .max = 16,
     .get = getPartField<&S::cache, &C::fallbackRadius>,
     .set = setPartField<&S::cache, &C::fallbackRadius>,
     .relevant = usesCache},
    {.name = "light_samples",
     .help = "cache: hits per face update that sample direct light (weighted subset); 0 = all",
     .kind = KnobKind::Count,
     .min = 0,
     .max = 256,
     .get = getPartField<&S::cache, &C::lightSamples>,
     .set = setPartField<&S::cache, &C::lightSamples>,
     .relevant = usesCache},
};

// Path-traced indirect light beside the direct method (render/path_indirect/). The names carry
// the prefix themselves: a scene's [indirect] table holds them beside the cache's.
using P = PathIndirectSettings;
const Knob kPath[] = {
    {.name = "path_spp",
     .help = "path: bounce paths per pixel per frame",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 256,
     .get = getPartField<&S::path, &P::samples>,
     .set = setPartField<&S::path, &P::samples>,
     .relevant = usesPath},
    {.name = "path_bounces",
     .help = "path: bounces per path (1 = one bounce, as the cache)",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 16,
     .get = getPartField<&S::path, &P::bounces>,
     .set = setPartField<&S::path, &P::bounces>,
     .relevant = usesPath},
    {.name = "path_accumulate",
     .help = "path: average over frames while camera and world are still",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::path, &P::accumulate>,
     .set = setPartField<&S::path, &P::accumulate>,
     .relevant = usesPath},
};

// ReGIR's world-space grid (render/regir/), with sampling regir.
using G = shared::RegirKnobs;
const Knob kRegir[] = {
    {.name = "regir_cell",
     .help = "regir: smallest cell size in voxels (grown until the world fits in 4096 cells)",
     .kind = KnobKind::Real,
     .min = 1,
     .max = 256,
     .get = getPartField<&S::regir, &G::cellSize>,
     .set = setPartField<&S::regir, &G::cellSize>,
     .relevant = mayUseRegir},
    {.name = "regir_candidates",
     .help = "regir: power-drawn candidates resampled into each cell entry per frame",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 256,
     .get = getPartField<&S::regir, &G::buildCandidates>,
     .set = setPartField<&S::regir, &G::buildCandidates>,
     .relevant = mayUseRegir},
};

// Voxel cone tracing (render/vct/; the Wicked Engine's voxel GI after Crassin et al.), prefixed
// like the path term's knobs.
using V = VctSettings;
const Knob kVct[] = {
    {.name = "vct_levels",
     .help = "vct: clipmap levels of 32^3 texels (2, 4, 8, 16 voxels wide; reach 64..512 voxels)",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 4,
     .get = getPartField<&S::vct, &V::levels>,
     .set = setPartField<&S::vct, &V::levels>,
     .relevant = usesVct},
    {.name = "vct_leak_mitigation",
     .help = "vct: directional texels and a cone start offset (off: isotropic texels, cones from "
             "the surface)",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::vct, &V::leakMitigation>,
     .set = setPartField<&S::vct, &V::leakMitigation>,
     .relevant = usesVct},
    {.name = "vct_offset",
     .help = "vct: cone start along the normal in level-0 texels (with leak mitigation)",
     .kind = KnobKind::Real,
     .min = 0,
     .max = 4,
     .get = getPartField<&S::vct, &V::startOffset>,
     .set = setPartField<&S::vct, &V::startOffset>,
     .relevant = vctMitigates},
    {.name = "vct_bounce",
     .help = "vct: a second bounce, injected from the last frame's volume",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::vct, &V::extraBounce>,
     .set = setPartField<&S::vct, &V::extraBounce>,
     .relevant = usesVct},
    {.name = "vct_refresh",
     .help = "vct: texels staying in view are re-injected every N frames, in turn (1 = all every "
             "frame); edits, light "
             "changes and new texels at once",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 64,
     .get = getPartField<&S::vct, &V::refreshPeriod>,
     .set = setPartField<&S::vct, &V::refreshPeriod>,
     .relevant = usesVct},
    {.name = "vct_classify_all",
     .help = "vct: classify every texel each frame, not only the blocks that may have changed "
             "(the same image; for tests and timing)",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::vct, &V::classifyAll>,
     .set = setPartField<&S::vct, &V::classifyAll>,
     .relevant = usesVct},
};

// Temporal accumulation of the lit image over still frames (render/accumulation/).
using A = AccumulationSettings;
const Knob kAccumulation[] = {
    {.name = "accumulate",
     .help = "Average the lit image over the frames in which camera, world, lights and sky stay "
             "still (not the reference, which averages itself, nor the preview)",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::accumulation, &A::enabled>,
     .set = setPartField<&S::accumulation, &A::enabled>},
    {.name = "accumulate_frames",
     .help = "accumulate: frames in the mean at most; past them an exponential average that "
             "follows slow changes",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 65536,
     .get = getPartField<&S::accumulation, &A::frames>,
     .set = setPartField<&S::accumulation, &A::frames>,
     .relevant = accumulates},
};

// The display's exposure (render/exposure/).
using E = ExposureSettings;
const Knob kExposure[] = {
    {.name = "auto_exposure",
     .help = "Exposure metered from the lit image (a histogram of its luminance), adapting over "
             "frames; off: the fixed exposure (--exposure, the HUD slider)",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::exposure, &E::automatic>,
     .set = setPartField<&S::exposure, &E::automatic>},
    {.name = "exposure_key",
     .help = "auto exposure: the exposure times the metered luminance (brighter image: larger)",
     .kind = KnobKind::Real,
     .min = 0.001,
     .max = 100,
     .get = getPartField<&S::exposure, &E::key>,
     .set = setPartField<&S::exposure, &E::key>,
     .relevant = usesAutoExposure},
    {.name = "exposure_adaptation",
     .help = "auto exposure: fraction of the way (in stops) to the metered exposure per frame "
             "(1: at once)",
     .kind = KnobKind::Real,
     .min = 0.001,
     .max = 1,
     .get = getPartField<&S::exposure, &E::adaptation>,
     .set = setPartField<&S::exposure, &E::adaptation>,
     .relevant = usesAutoExposure},
};

// The displayed image's reconstruction (render/denoiser/, render/upsampling/).
using D = DisplaySettings;
const Knob kDisplay[] = {
    {.name = "display",
     .help = "The image shown: raw (as shaded, one sample per pixel at the render size) | "
             "upsampled (jittered primary rays resolved over frames to the display size) | "
             "denoised (the lighting denoised first; vox play and render default to it; capture "
             "keeps raw so that a split capture equals one run)",
     .kind = KnobKind::Choice,
     .choices = kDisplays,
     .get = getPartField<&S::display, &D::mode>,
     .set = setPartField<&S::display, &D::mode>},
    {.name = "denoise_history",
     .help = "denoised: frames the denoiser's temporal mean holds at most",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 1024,
     .get = getPartField<&S::display, &D::denoiseHistory>,
     .set = setPartField<&S::display, &D::denoiseHistory>,
     .relevant = denoises},
    {.name = "denoise_passes",
     .help = "denoised: edge-stopped a-trous passes (taps 1, 2, 4, ... pixels apart)",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 6,
     .get = getPartField<&S::display, &D::denoisePasses>,
     .set = setPartField<&S::display, &D::denoisePasses>,
     .relevant = denoises},
    {.name = "resolve_history",
     .help = "upsampled, denoised: frames of display history the resolve holds at most",
     .kind = KnobKind::Count,
     .min = 1,
     .max = 1024,
     .get = getPartField<&S::display, &D::resolveHistory>,
     .set = setPartField<&S::display, &D::resolveHistory>,
     .relevant = reconstructs},
    {.name = "jitter",
     .help = "upsampled, denoised: a sub-pixel jitter of the primary rays per frame, which the "
             "resolve turns into anti-aliasing (off: pixel centres)",
     .kind = KnobKind::Switch,
     .get = getPartField<&S::display, &D::jitter>,
     .set = setPartField<&S::display, &D::jitter>,
     .relevant = reconstructs},
};

const KnobGroup kGroups[] = {
    {"lighting", "", kLighting},
    {"emitters", "", kEmitters},
    {"restir", "", kRestir},
    {"baselines", "", kBaselines},
    {"reference", "", kReference},
    {"cache", "cache-", kCache},
    {"path", "", kPath},
    {"regir", "", kRegir},
    {"vct", "", kVct},
    {"accumulation", "", kAccumulation},
    {"exposure", "", kExposure},
    {"display", "", kDisplay},
};

// Rules between knobs that no single range expresses.
Status checkCombinations(const LightingSettings& s) {
    if (s.cache.directions % std::max(s.cache.raysPerUpdate, 1u) != 0)
        return makeError("cache rays ({}) must divide cache directions ({})", s.cache.raysPerUpdate,
                         s.cache.directions);
    if (s.cache.neighbourhood != 0 && s.cache.neighbourhood != 3 && s.cache.neighbourhood != 5)
        return makeError("cache neighbourhood must be 0, 3 or 5, not {}", s.cache.neighbourhood);
    return {};
}

void normalise(LightingSettings& s) {
    if (s.method == Method::Ris) {  // RIS is ReSTIR's first pass alone
        s.restir.temporal = false;
        s.restir.spatial = false;
        s.restir.candidateVisibility = false;
    }
    if (s.indirect == Indirect::Reference) {
        // The path tracer with bounces is the indirect reference; it replaces the direct method.
        s.method = Method::Reference;
        s.bounces = std::max(s.bounces, 1u);
    }
}

Status applyValues(LightingSettings& s, std::span<const KnobValue> values) {
    for (const KnobValue& v : values) {
        if (Status ok = setKnob(*v.knob, s, v.text); !ok)
            return makeError("{}: {}", v.where, ok.error().message);
    }
    return {};
}

}  // namespace

std::span<const KnobGroup> knobGroups() { return kGroups; }

const KnobGroup& knobGroup(std::string_view name) {
    for (const KnobGroup& g : kGroups) {
        if (g.name == name) return g;
    }
    return kGroups[0];
}

std::string knobOption(const KnobGroup& group, const Knob& knob) {
    std::string option = fmt::format("--{}{}", group.cliPrefix, knob.name);
    std::replace(option.begin(), option.end(), '_', '-');
    return option;
}

const Knob* knobForOption(std::string_view option) {
    for (const KnobGroup& g : kGroups) {
        for (const Knob& k : g.knobs) {
            if (knobOption(g, k) == fmt::format("--{}", option)) return &k;
        }
    }
    return nullptr;
}

Status validate(const LightingSettings& s) {
    for (const KnobGroup& g : kGroups) {
        for (const Knob& k : g.knobs) {
            if (Status ok = checkKnob(k, s); !ok) return ok;
        }
    }
    return checkCombinations(s);
}

Result<LightingSettings> mergeLighting(LightingSettings base, std::span<const KnobValue> values) {
    if (Status ok = applyValues(base, values); !ok) return ok.error();
    normalise(base);
    if (Status ok = validate(base); !ok) return ok.error();
    return base;
}

Result<LightingSettings> mergeLighting(std::span<const std::vector<KnobValue>> layers) {
    LightingSettings s;
    for (const std::vector<KnobValue>& layer : layers) {
        if (Status ok = applyValues(s, layer); !ok) return ok.error();
    }
    return mergeLighting(s, {});
}

}  // namespace engine::lighting

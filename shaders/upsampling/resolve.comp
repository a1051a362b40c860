#version 460
// Temporal upsampling's resolve (after Karis 2014, "High Quality Temporal Supersampling", and
// AMD FSR 2's accumulation): per display pixel, this frame's jittered render samples near it and
// last frame's display image at the point the pixel's surface was then, blended by how close the
// samples fell. Over a jitter cycle the samples cover every display pixel, so a still camera
// converges to an anti-aliased image at the display's size from a quarter of its pixels or fewer.
// History is dropped where its surface is not among this frame's nearby surfaces (the exact
// surface keys of common/surface_key.glsl: a disocclusion) and clipped to the neighbourhood's
// colour spread elsewhere (lighting that changed). What it needs of the 3x3 samples around its
// nearest one — their spread, their keys, the sample's motion — it reads from the pre-pass
// (summarize_neighbourhood.comp, once per render pixel); it reads render samples itself only for
// what depends on where the display pixel lies among them. It also writes the shown image,
// tonemapped, so the display image is not read again at the window's size.
#extension GL_GOOGLE_include_directive : require

#include "common/surface_key.glsl"
#include "common/tonemap.glsl"
#include "common/ycocg.glsl"
#include "shared/exposure.h"
#include "shared/frame_params.h"
#include "shared/upsampling.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = UPSAMPLING_BINDING_FRAME, std430) readonly buffer Frame {
    FrameParams gFrame;
};
layout(set = 0, binding = UPSAMPLING_BINDING_PARAMS, std430) readonly buffer Params {
    UpsamplingParams gParams;
};
layout(set = 0, binding = UPSAMPLING_BINDING_NEIGHBOURHOOD) uniform usamplerBuffer gNeighbourhood;
// What it only reads at other pixels' indices it reads as texels (one gather per tap on lavapipe,
// where a storage-buffer read at a lane-varying index is a loop over the lanes).
layout(set = 0, binding = UPSAMPLING_BINDING_RADIANCE) uniform samplerBuffer gRadiance;
layout(set = 0, binding = UPSAMPLING_BINDING_PREV_DISPLAY) uniform samplerBuffer gPrevDisplay;
layout(set = 0, binding = UPSAMPLING_BINDING_DISPLAY, std430) writeonly buffer Display {
    vec4 gDisplay[];
};
layout(set = 0, binding = UPSAMPLING_BINDING_PREV_KEYS) uniform usamplerBuffer gPrevKeys;
layout(set = 0, binding = UPSAMPLING_BINDING_KEYS, std430) writeonly buffer Keys { uint gKeys[]; };
layout(set = 0, binding = UPSAMPLING_BINDING_SURFACE_KEYS) uniform usamplerBuffer gSurfaceKeys;
layout(set = 0, binding = UPSAMPLING_BINDING_EXPOSURE, std430) readonly buffer Exposure {
    ExposureState gExposure;
};
layout(set = 0, binding = UPSAMPLING_BINDING_LDR, std430) writeonly buffer Ldr { uint gLdr[]; };

// exp(-kSharpness d^2): a standard deviation of 0.3 display pixels.
const float kSharpness = 1.0 / (2.0 * 0.3 * 0.3);
// The weight one frame's samples add to a display pixel on average: the render samples' density
// (render pixels per display pixel) times the Gaussian's integral, 2 pi sigma^2. History lengths
// are in frames of that weight, whatever the render scale.
const float kGaussianIntegral = 2.0 * 3.14159265 * 0.3 * 0.3;
// Where the clip had to move the history by more than a tenth of the light here (it disagrees
// with this frame beyond its noise: a light switched, a shadow moved), the history counts as at
// most this many frames, so the display follows a change within about as many.
const float kChangedHistory = 2.0;
// After an edit, a light or the sky changed (FrameChanges: a reactive frame, as FSR 2's reactive
// mask, for the whole view) the history counts as half a frame: a window switched on is
// sub-pixel, the clip box of its neighbourhood holds the dark history, and with 2 frames the
// region reached 0.28, 0.48, 0.60 of its new light over the first frames.
const float kAnnouncedChangeHistory = 0.5;
// The clip's width inside one surface, in standard deviations of the 3x3 samples.
const float kInsideClipGamma = 3.0;

// The render samples per axis that can add to a display pixel: those within a render pixel of its
// centre when a render pixel spans 2 display pixels or more, the nearest alone from 4 (a sample
// left out is 2 display pixels away or more: a weight of exp(-kSharpness 4) = 2e-10 at most).
int addingTaps(float scale) { return scale <= 0.25 ? 1 : scale <= 0.5 ? 2 : 3; }

// Last frame's display at `p` (display pixels), Catmull-Rom over the 4x4 texels around it: a
// bilinear fetch blurs the history a little every frame the camera moves, and the blur adds up
// (Karis 2014 samples the history bicubically for the same reason). The four corner taps are left
// out and the rest renormalised (as Jimenez 2016's 5-tap filter, "Filmic SMAA", does): their
// weights are products of the two small outer lobes (at most 0.0055 each), and each tap is a
// gather on lavapipe. The taps are clamped to the image; the weight channel is read bilinearly,
// and negative lobes cannot make colour negative (the clip and the final max() follow).
vec4 catmullRomHistory(vec2 p, ivec2 display) {
    p -= 0.5;
    ivec2 base = ivec2(floor(p));
    vec2 f = p - vec2(base);
    vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
    vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
    vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
    vec2 w3 = f * f * (-0.5 + 0.5 * f);
    vec2 wx[4] = vec2[4](vec2(w0.x, 0.0), vec2(w1.x, 0.0), vec2(w2.x, 0.0), vec2(w3.x, 0.0));
    float wy[4] = float[4](w0.y, w1.y, w2.y, w3.y);
    ivec2 last = display - 1;
    vec3 rgb = vec3(0.0);
    float weight = 0.0;
    for (int j = 0; j < 4; ++j) {
        int y = clamp(base.y - 1 + j, 0, last.y);
        for (int i = 0; i < 4; ++i) {
            if ((i == 0 || i == 3) && (j == 0 || j == 3)) continue;  // a corner
            int x = clamp(base.x - 1 + i, 0, last.x);
            vec4 h = texelFetch(gPrevDisplay, x + y * display.x);
            rgb += h.rgb * (wx[i].x * wy[j]);
            if (i == 1 || i == 2) {
                if (j == 1 || j == 2)
                    weight += h.w * ((i == 1 ? 1.0 - f.x : f.x) * (j == 1 ? 1.0 - f.y : f.y));
            }
        }
    }
    float corners = (w0.x + w3.x) * (w0.y + w3.y);
    return vec4(max(rgb / (1.0 - corners), vec3(0.0)), weight);
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uvec2 display = gFrame.displaySize.xy;
    if (any(greaterThanEqual(pixel, display))) return;
    uint index = pixel.x + pixel.y * display.x;
    ivec2 render = ivec2(gFrame.imageSize.xy);
    vec2 scale = vec2(render) / vec2(display);  // render pixels per display pixel
    vec2 centre = (vec2(pixel) + 0.5) * scale;  // this pixel's centre in render pixels
    vec2 jitter = gFrame.jitter.xy;
    ivec2 nearest = ivec2(floor(centre - jitter));  // the render sample closest to it

    // The 3x3 samples around the nearest one, summarised once per render pixel (the pre-pass).
    ivec2 nearestTexel = clamp(nearest, ivec2(0), render - 1);
    int summary =
        int(UPSAMPLING_NEIGHBOURHOOD_TEXELS) * (nearestTexel.x + nearestTexel.y * render.x);
    uvec4 own = texelFetch(gNeighbourhood, summary);
    uvec4 moments = texelFetch(gNeighbourhood, summary + 1);
    uvec4 range = texelFetch(gNeighbourhood, summary + 2);
    uvec4 keySet = texelFetch(gNeighbourhood, summary + 3);
    uint keyCount = own.z >> NEIGHBOURHOOD_KEY_COUNT_SHIFT;

    // What the samples near it add to this display pixel: a Gaussian of 0.3 display pixels around
    // its centre, near a box (over a jitter cycle, the samples that fall in it). Both axes'
    // weights are separable: one exponential per row and per tap.
    ivec2 taps = ivec2(addingTaps(scale.x), addingTaps(scale.y));
    ivec2 first = ivec2(floor(centre - jitter - 0.5 * vec2(taps - 1)));
    vec3 added = vec3(0.0);
    float addedWeight = 0.0;
    for (int j = 0; j < taps.y; ++j) {
        int row = clamp(first.y + j, 0, render.y - 1);
        float dy = (float(row) + 0.5 + jitter.y - centre.y) / scale.y;
        float wy = exp(-kSharpness * dy * dy);
        for (int i = 0; i < taps.x; ++i) {
            int column = clamp(first.x + i, 0, render.x - 1);
            float dx = (float(column) + 0.5 + jitter.x - centre.x) / scale.x;
            float w = exp(-kSharpness * dx * dx) * wy;
            added += max(texelFetch(gRadiance, column + row * render.x).rgb, vec3(0.0)) * w;
            addedWeight += w;
        }
    }
    // The nearest sample: its surface and motion.
    uint nearestKey = keySet.x;
    vec4 nearestMotion =
        vec4(uintBitsToFloat(own.xy), 0.0, (own.z & NEIGHBOURHOOD_FLAG_MOTION) != 0u ? 1.0 : 0.0);
    vec2 nearestSample = vec2(nearestTexel) + 0.5 + jitter;
    bool edited = (own.z & NEIGHBOURHOOD_FLAG_EDITED) != 0u;

    // Last frame's display where this pixel's surface was: the nearest sample's motion, from its
    // render position to the display's.
    vec4 history = vec4(0.0);
    bool inside = false;     // all 3x3 samples on the history's surface: no edge near
    bool still = false;      // the history is this very pixel's (a still view of a still surface)
    bool unchanged = false;  // and the world did not change: the history needs no test
    bool worldUnchanged =
        (gParams.flags & (UPSAMPLING_LIGHTING_CHANGED | UPSAMPLING_OBJECTS_MOVED)) == 0u;
    if ((gParams.flags & UPSAMPLING_RESTART) == 0u && !edited) {
        vec2 previous = vec2(pixel) + 0.5;
        if (nearestMotion.w > 0.0) previous += (nearestMotion.xy - nearestSample) / scale;
        ivec2 keyTexel = ivec2(floor(previous));
        if (all(greaterThanEqual(previous, vec2(0.0))) && all(lessThan(previous, vec2(display)))) {
            uint previousKey = texelFetch(gPrevKeys, keyTexel.x + keyTexel.y * int(display.x)).x;
            // The key among the 3x3 samples' (a loop, not a branch: lavapipe runs a loop only
            // as long as a lane needs it, both sides of a branch always).
            bool seen = any(equal(keySet, uvec4(previousKey)));
            // A moving object's history is the object's only where this pixel still sees it. The
            // 3x3 samples span up to 3 display pixels from this one at scale 1/2: at a still
            // surface's silhouette their tolerance keeps the edge's history through the jitter,
            // but where an object moved away it kept the object over the surface it uncovered,
            // clipped only to a range its own samples span (a trail of 3-4 frames).
            bool objectLeft = (gParams.flags & UPSAMPLING_OBJECTS_MOVED) != 0u &&
                              surfaceKeyIsObject(previousKey) && previousKey != nearestKey;
            inside = keyCount == 1u && nearestKey == previousKey;
            int keyTaps = keyCount > 4u ? 9 : 0;  // more keys than the summary holds
            if (objectLeft) keyTaps = 0;
            for (int k = 0; k < keyTaps; ++k) {
                ivec2 q = clamp(nearestTexel + ivec2(k % 3, k / 3) - 1, ivec2(0), render - 1);
                seen = seen || texelFetch(gSurfaceKeys, q.x + q.y * render.x).x == previousKey;
            }
            vec2 moved = abs(previous - (vec2(pixel) + 0.5));  // float noise: 1e-5 of a pixel
            bool here = max(moved.x, moved.y) < 1.0e-3;
            // Nothing in the world changed (no edit, light, sky or object: FrameChanges), and the
            // surface was at this very pixel: the history is the pixel's own and still right,
            // whatever this frame's few samples hit. (At a silhouette a sliver of floor one
            // frame's samples saw and the next's missed dropped it, and the clip pulled it to
            // whatever they did see: the still image flickered along every edge.)
            unchanged = here && worldUnchanged;
            seen = seen && !objectLeft;
            if (seen || unchanged) history = catmullRomHistory(previous, ivec2(display));
            still = (seen || unchanged) && here;
        }
    }

    // Without history and with no sample near: the 3x3 samples interpolated, a Gaussian of a third
    // of a render pixel (a loop, so only the lanes that need it pay for its 9 taps).
    vec3 colour = vec3(0.0);
    float colourWeight = 0.0;
    int colourTaps = history.w > 0.0 || addedWeight > 0.05 ? 0 : 9;
    for (int k = 0; k < colourTaps; ++k) {
        ivec2 q = clamp(nearest + ivec2(k % 3, k / 3) - 1, ivec2(0), render - 1);
        vec2 d = vec2(q) + 0.5 + jitter - centre;
        float w = exp(-4.5 * d.x * d.x) * exp(-4.5 * d.y * d.y);
        colour += max(texelFetch(gRadiance, q.x + q.y * render.x).rgb, vec3(0.0)) * w;
        colourWeight += w;
    }
    vec3 result = addedWeight > 0.05 ? added / addedWeight : colour / max(colourWeight, 1e-30);
    float weight = addedWeight;
    if (history.w > 0.0) {
        // Clip the history to the neighbourhood's spread (in YCoCg): what moved or changed light
        // is pulled to what this frame sees.
        vec3 mean = uintBitsToFloat(moments.xyz);
        vec3 sigma = vec3(unpackHalf2x16(moments.w), unpackHalf2x16(range.x).x);
        vec3 h = toYCoCg(history.rgb);
        // Inside one surface the spread is the lighting's noise and its sub-pixel detail (a lit
        // window on a wall); a tight clip there throws away the history's average of it, and the
        // image darkens. Only edges get the tight clip.
        float gamma = inside ? kInsideClipGamma : gParams.clipGamma;
        vec3 lo = mean - gamma * sigma, hi = mean + gamma * sigma;
        // On a still view the history is this pixel's own average over the jitter cycle: the
        // 3x3 samples of one frame are a few of the points it averaged, so their spread says
        // nothing about whether it is out of date (a sub-pixel window lands in a few of them and
        // a variance clip pulls it to the brick around it: the still image lost windows and
        // light). Only a value beyond all of them is a change the flags did not announce (a
        // moving object's shadow): the box is their range (Salvi 2016, "An Excursion in Temporal
        // Supersampling", for the variance box it widens).
        if (still) {
            lo = vec3(unpackHalf2x16(range.x).y, unpackHalf2x16(range.y));
            hi = vec3(unpackHalf2x16(range.z), unpackHalf2x16(range.w).x);
        }
        if (unchanged) {
            lo = vec3(-1e30);
            hi = vec3(1e30);
        }
        vec3 clipped = clamp(h, lo, hi);
        float frameWeight = scale.x * scale.y * kGaussianIntegral;
        float historyWeight = history.w;
        if ((gParams.flags & UPSAMPLING_LIGHTING_CHANGED) != 0u)
            historyWeight = min(historyWeight, kAnnouncedChangeHistory * frameWeight);
        else if (abs(clipped.x - h.x) > 0.1 * max(mean.x, 1e-4))
            historyWeight = min(historyWeight, kChangedHistory * frameWeight);
        float fullHistory = gParams.maxHistory * frameWeight;
        result = (fromYCoCg(clipped) * historyWeight + added) / (historyWeight + addedWeight);
        weight = min(historyWeight + addedWeight, fullHistory);
        // A still pixel with a full history has averaged the jitter cycle; a running mean would
        // keep moving by the sub-pixel contrast over its length every frame (a flicker 6x raw
        // ReSTIR's, which is frozen on a still view). It stops taking samples until the clip or
        // an announced change shortens its history.
        bool settled = unchanged && (gParams.flags & UPSAMPLING_SETTLED) != 0u;
        if (still && (historyWeight >= 0.999 * fullHistory || settled)) {
            result = fromYCoCg(clipped);
            weight = historyWeight >= 0.999 * fullHistory ? fullHistory : historyWeight;
        }
    }
    result = max(result, vec3(0.0));
    gDisplay[index] = vec4(result, weight);
    gKeys[index] = nearestKey;
    gLdr[index] = tonemapToRgba8(result, shownExposure(gFrame.exposure, gExposure.value.x));
}

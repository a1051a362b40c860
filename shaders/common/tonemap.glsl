// The display's tone mapping: linear radiance -> exposure -> ACES filmic curve (Narkowicz 2015
// fit) -> sRGB, packed RGBA8. One function for the two passes that write the shown image: the
// tonemap (post/tonemap.comp) and the temporal upsampling's resolve, which tonemaps as it writes
// so the display image is not read a second time at the window's size.
#ifndef COMMON_TONEMAP_GLSL
#define COMMON_TONEMAP_GLSL

vec3 acesFilm(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

// The exposure shown: FrameParams.exposure.x, or where .y is set the one auto exposure
// (shaders/exposure/) metered this frame.
float shownExposure(vec4 frameExposure, float metered) {
    return frameExposure.y != 0.0 ? metered : frameExposure.x;
}

uint tonemapToRgba8(vec3 radiance, float exposure) {
    return packUnorm4x8(vec4(linearToSrgb(acesFilm(max(radiance, vec3(0.0)) * exposure)), 1.0));
}

#endif

#version 460
// Visibility update of the cache's dynamic entries, traced from scratch (the comparison mode): see update_visibility.glsl.
#extension GL_GOOGLE_include_directive : require

#define VISIBILITY_SET CACHE_SET_DYNAMIC
#define VISIBILITY_MODE VISIBILITY_FULL
#include "irradiance_cache/update_visibility.glsl"

// YCoCg (luma, orange and green chroma): the space the resolve clips history in, where the
// neighbourhood's box hugs the colours better than in RGB (Karis 2014, "High Quality Temporal
// Supersampling").
#ifndef COMMON_YCOCG_GLSL
#define COMMON_YCOCG_GLSL

vec3 toYCoCg(vec3 c) {
    return vec3(dot(c, vec3(0.25, 0.5, 0.25)), dot(c, vec3(0.5, 0.0, -0.5)),
                dot(c, vec3(-0.25, 0.5, -0.25)));
}
vec3 fromYCoCg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

#endif

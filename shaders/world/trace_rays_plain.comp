#version 460
// Batch ray queries, plain traversal (TRACE_MODE_PLAIN); the body is trace_rays.glsl.
#extension GL_GOOGLE_include_directive : require
#include "shared/trace_rays.h"
#define TRACE_MODE TRACE_MODE_PLAIN
#include "world/trace_rays.glsl"

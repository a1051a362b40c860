#version 460
// Batch ray queries, scene traversal (TRACE_MODE_SCENE); the body is trace_rays.glsl.
#extension GL_GOOGLE_include_directive : require
#include "shared/trace_rays.h"
#define TRACE_MODE TRACE_MODE_SCENE
#include "world/trace_rays.glsl"

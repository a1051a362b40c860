// Compatibility layer so one header can be included by both C++ and GLSL.
// Rules for shared structs: std430, vec4/uvec4-sized members, explicit padding, no vec3/bool.
#ifndef SHARED_INTEROP_H
#define SHARED_INTEROP_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define SHARED_BEGIN namespace shared {
#define SHARED_END }
#define SHARED_CONST inline constexpr
#define SHARED_ASSERT_SIZE(T, n) static_assert(sizeof(T) == (n), #T " layout changed")
// Defaults and equality for structs the host also keeps as settings (C++ only).
#define SHARED_INIT(value) = value
#define SHARED_EQUALITY(T) bool operator==(const T&) const = default;
namespace shared {
using uint = std::uint32_t;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
}  // namespace shared
#else
#define SHARED_BEGIN
#define SHARED_END
#define SHARED_CONST const
#define SHARED_ASSERT_SIZE(T, n)
#define SHARED_INIT(value)
#define SHARED_EQUALITY(T)
#endif

#endif

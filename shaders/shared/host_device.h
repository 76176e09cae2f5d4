// Shared between C++ and GLSL: lets one header declare structs and constants for both.
// In C++ the GLSL vector/matrix names map to glm, whose vec2/vec3 align to 4 bytes where std140
// and std430 align them to 8 and 16: a struct lays out alike on both sides when its members fill
// 16-byte rows in order (a vec3 followed by a scalar, named padding where none fits) and a vec2
// starts at a multiple of 8. Checked by static_assert beside each struct, and the uniform blocks'
// offsets against the GL's by tests/gl/param_block_layout_test.cpp.
#ifndef ISPM_HOST_DEVICE_H
#define ISPM_HOST_DEVICE_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define ISPM_NAMESPACE_BEGIN namespace ispm::gpu {
#define ISPM_NAMESPACE_END }
#define ISPM_CONST inline constexpr
#define ISPM_STATIC_ASSERT_SIZE(T, bytes) static_assert(sizeof(T) == (bytes), #T " layout")
// Functions written once for both languages: parameters passed by reference in C++.
#define ISPM_INLINE inline
#define ISPM_INOUT(T) T&
#define ISPM_OUT(T) T&
// An array parameter the function writes (C++ passes arrays as pointers already).
#define ISPM_INOUT_ARRAY(T, name, n) T name[n]
#define ISPM_OUT_ARRAY(T, name, n) T name[n]
ISPM_NAMESPACE_BEGIN
// The GLSL built-ins shared functions use, from glm.
using glm::abs;
using glm::acos;
using glm::asin;
using glm::atan;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::max;
using glm::min;
using glm::mix;
using glm::mod;
using glm::normalize;
using glm::pow;
using glm::reflect;
using glm::round;
using glm::sin;
using glm::sqrt;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using uvec3 = glm::uvec3;
using uvec4 = glm::uvec4;
using ivec2 = glm::ivec2;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
using uint = uint32_t;
ISPM_NAMESPACE_END
#else
#define ISPM_NAMESPACE_BEGIN
#define ISPM_NAMESPACE_END
#define ISPM_CONST const
#define ISPM_STATIC_ASSERT_SIZE(T, bytes)
#define ISPM_INLINE
#define ISPM_INOUT(T) inout T
#define ISPM_OUT(T) out T
#define ISPM_INOUT_ARRAY(T, name, n) inout T name[n]
#define ISPM_OUT_ARRAY(T, name, n) out T name[n]
#endif

#endif

// Four floats in one register, for the four wavelengths of a spectral path: GCC and Clang
// vector extensions (GCC manual, "Using Vector Instructions through Built-in Functions"),
// which compile to SSE2 on x86-64 (every x86-64 has it) and to NEON or to scalar code on
// other targets, so no intrinsics and no separate fallback are needed. Each operation is the
// scalar IEEE operation in every lane (no fused multiply-add: lamina builds for baseline
// x86-64), so a lane computes exactly what the same scalar expression would.
#pragma once

#include <cstdint>
#include <cstring>

namespace lamina::simd {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

inline Float4 splat(float x) {
    return Float4{x, x, x, x};
}

/// Four floats from (to) memory that need not be aligned.
inline Float4 load(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store(float* p, Float4 v) {
    std::memcpy(p, &v, sizeof v);
}

/// Lane-wise mask ? a : b, for a mask from a lane-wise comparison (all bits set or none).
inline Float4 select(Int4 mask, Float4 a, Float4 b) {
    return mask ? a : b;
}

/// Truncation towards zero in every lane, as static_cast<int>(float) (lanes must be in range).
inline Int4 truncate(Float4 x) {
    return __builtin_convertvector(x, Int4);
}
inline Float4 toFloat(Int4 i) {
    return __builtin_convertvector(i, Float4);
}

}  // namespace lamina::simd

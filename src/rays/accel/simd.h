// Minimal SIMD vocabulary for the triangle BVH: 8-wide floats (wide-node box tests) and 4-wide
// floats (leaf triangle tests). With AVX2+FMA (e.g. -march=native on x86-64) they map to
// __m256 / __m128 intrinsics; otherwise a portable scalar fallback with the same interface is
// selected at compile time (slower, same results up to FMA rounding).
//
// Only the operations the traversal needs are provided; masks are vectors of all-ones/all-zeros
// lanes (as produced by the compares) and `bits()` turns one into an integer bit mask.
#pragma once

#include <cstdint>
#include <cstring>

#if defined(__AVX2__) && defined(__FMA__)
#define RAYS_TRIBVH_AVX2 1
#include <immintrin.h>
#else
#define RAYS_TRIBVH_AVX2 0
#include <algorithm>
#include <cmath>
#endif

#if defined(__GNUC__)
#define RAYS_FORCEINLINE inline __attribute__((always_inline))
#else
#define RAYS_FORCEINLINE inline
#endif

namespace rays::tribvh {

/// Index of the lowest set bit (x != 0).
RAYS_FORCEINLINE unsigned lowestBit(uint32_t x) { return unsigned(__builtin_ctz(x)); }

#if RAYS_TRIBVH_AVX2

// ---------------------------------------------------------------------------------- AVX2 + FMA
struct VFloat8 {
    __m256 v;
    RAYS_FORCEINLINE static VFloat8 load(const float* p) { return {_mm256_load_ps(p)}; }
    RAYS_FORCEINLINE static VFloat8 broadcast(float x) { return {_mm256_set1_ps(x)}; }
    RAYS_FORCEINLINE void store(float* p) const { _mm256_store_ps(p, v); }
};
/// a * b - c with a single rounding.
RAYS_FORCEINLINE VFloat8 fmsub(VFloat8 a, VFloat8 b, VFloat8 c) { return {_mm256_fmsub_ps(a.v, b.v, c.v)}; }
RAYS_FORCEINLINE VFloat8 min(VFloat8 a, VFloat8 b) { return {_mm256_min_ps(a.v, b.v)}; }
RAYS_FORCEINLINE VFloat8 max(VFloat8 a, VFloat8 b) { return {_mm256_max_ps(a.v, b.v)}; }
/// Bit i set when a[i] <= b[i] (false for NaN).
RAYS_FORCEINLINE uint32_t lessEqualBits(VFloat8 a, VFloat8 b) {
    return uint32_t(_mm256_movemask_ps(_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)));
}

struct VFloat4 {
    __m128 v;
    RAYS_FORCEINLINE static VFloat4 load(const float* p) { return {_mm_load_ps(p)}; }
    RAYS_FORCEINLINE static VFloat4 broadcast(float x) { return {_mm_set1_ps(x)}; }
    RAYS_FORCEINLINE static VFloat4 zero() { return {_mm_setzero_ps()}; }
    RAYS_FORCEINLINE void store(float* p) const { _mm_store_ps(p, v); }
};
RAYS_FORCEINLINE VFloat4 operator+(VFloat4 a, VFloat4 b) { return {_mm_add_ps(a.v, b.v)}; }
RAYS_FORCEINLINE VFloat4 operator-(VFloat4 a, VFloat4 b) { return {_mm_sub_ps(a.v, b.v)}; }
RAYS_FORCEINLINE VFloat4 operator*(VFloat4 a, VFloat4 b) { return {_mm_mul_ps(a.v, b.v)}; }
RAYS_FORCEINLINE VFloat4 operator/(VFloat4 a, VFloat4 b) { return {_mm_div_ps(a.v, b.v)}; }
RAYS_FORCEINLINE VFloat4 operator&(VFloat4 a, VFloat4 b) { return {_mm_and_ps(a.v, b.v)}; }
RAYS_FORCEINLINE VFloat4 operator|(VFloat4 a, VFloat4 b) { return {_mm_or_ps(a.v, b.v)}; }
RAYS_FORCEINLINE VFloat4 operator^(VFloat4 a, VFloat4 b) { return {_mm_xor_ps(a.v, b.v)}; }
/// c - a * b with a single rounding.
RAYS_FORCEINLINE VFloat4 fnmadd(VFloat4 a, VFloat4 b, VFloat4 c) { return {_mm_fnmadd_ps(a.v, b.v, c.v)}; }
/// a * b + c with a single rounding.
RAYS_FORCEINLINE VFloat4 fmadd(VFloat4 a, VFloat4 b, VFloat4 c) { return {_mm_fmadd_ps(a.v, b.v, c.v)}; }
RAYS_FORCEINLINE VFloat4 min(VFloat4 a, VFloat4 b) { return {_mm_min_ps(a.v, b.v)}; }
RAYS_FORCEINLINE VFloat4 max(VFloat4 a, VFloat4 b) { return {_mm_max_ps(a.v, b.v)}; }
RAYS_FORCEINLINE VFloat4 cmpGe(VFloat4 a, VFloat4 b) { return {_mm_cmp_ps(a.v, b.v, _CMP_GE_OQ)}; }
RAYS_FORCEINLINE VFloat4 cmpLe(VFloat4 a, VFloat4 b) { return {_mm_cmp_ps(a.v, b.v, _CMP_LE_OQ)}; }
RAYS_FORCEINLINE VFloat4 cmpGt(VFloat4 a, VFloat4 b) { return {_mm_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
RAYS_FORCEINLINE VFloat4 cmpLt(VFloat4 a, VFloat4 b) { return {_mm_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
RAYS_FORCEINLINE VFloat4 cmpNe(VFloat4 a, VFloat4 b) { return {_mm_cmp_ps(a.v, b.v, _CMP_NEQ_UQ)}; }
/// mask ? a : b (per lane).
RAYS_FORCEINLINE VFloat4 select(VFloat4 mask, VFloat4 a, VFloat4 b) { return {_mm_blendv_ps(b.v, a.v, mask.v)}; }
RAYS_FORCEINLINE uint32_t bits(VFloat4 mask) { return uint32_t(_mm_movemask_ps(mask.v)); }
RAYS_FORCEINLINE VFloat4 signMask4() { return {_mm_set1_ps(-0.0f)}; }
/// Smallest lane, broadcast to all lanes.
RAYS_FORCEINLINE VFloat4 horizontalMin(VFloat4 a) {
    __m128 m = _mm_min_ps(a.v, _mm_shuffle_ps(a.v, a.v, _MM_SHUFFLE(2, 3, 0, 1)));
    return {_mm_min_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)))};
}
/// Truncates each lane to an integer and clamps it to [0, hi].
RAYS_FORCEINLINE void truncClamp(VFloat4 a, int hi, int32_t out[4]) {
    __m128i i = _mm_cvttps_epi32(a.v);
    i = _mm_min_epi32(_mm_max_epi32(i, _mm_setzero_si128()), _mm_set1_epi32(hi));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), i);
}
/// Truncation toward zero; INT_MIN for NaN and out-of-range values (like the 4-wide version).
RAYS_FORCEINLINE int32_t truncToInt(float x) { return _mm_cvttss_si32(_mm_set_ss(x)); }
/// Lanes 0..2 of a, lane 3 zero.
RAYS_FORCEINLINE VFloat4 xyz(VFloat4 a) { return {_mm_blend_ps(a.v, _mm_setzero_ps(), 8)}; }
/// Unaligned load.
RAYS_FORCEINLINE VFloat4 loadu4(const float* p) { return {_mm_loadu_ps(p)}; }
/// Forces `a` to be materialised: stops the compiler from fusing the product that produced it
/// into a later add/subtract (the watertight edge test needs plain, separately rounded products).
RAYS_FORCEINLINE VFloat4 materialize(VFloat4 a) {
    __asm__("" : "+x"(a.v));
    return a;
}
RAYS_FORCEINLINE float materialize(float a) {
    __asm__("" : "+x"(a));
    return a;
}

#else

// ----------------------------------------------------------------------- portable scalar fallback
struct VFloat8 {
    float v[8];
    static VFloat8 load(const float* p) {
        VFloat8 r;
        std::memcpy(r.v, p, sizeof r.v);
        return r;
    }
    static VFloat8 broadcast(float x) {
        VFloat8 r;
        for (float& e : r.v) e = x;
        return r;
    }
    void store(float* p) const { std::memcpy(p, v, sizeof v); }
};
inline VFloat8 fmsub(VFloat8 a, VFloat8 b, VFloat8 c) {
    VFloat8 r;
    for (int i = 0; i < 8; ++i) r.v[i] = std::fma(a.v[i], b.v[i], -c.v[i]);
    return r;
}
inline VFloat8 min(VFloat8 a, VFloat8 b) {
    VFloat8 r;
    for (int i = 0; i < 8; ++i) r.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i];
    return r;
}
inline VFloat8 max(VFloat8 a, VFloat8 b) {
    VFloat8 r;
    for (int i = 0; i < 8; ++i) r.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i];
    return r;
}
inline uint32_t lessEqualBits(VFloat8 a, VFloat8 b) {
    uint32_t m = 0;
    for (int i = 0; i < 8; ++i) m |= uint32_t(a.v[i] <= b.v[i]) << i;
    return m;
}

struct VFloat4 {
    float v[4];
    static VFloat4 load(const float* p) {
        VFloat4 r;
        std::memcpy(r.v, p, sizeof r.v);
        return r;
    }
    static VFloat4 broadcast(float x) { return {{x, x, x, x}}; }
    static VFloat4 zero() { return broadcast(0.0f); }
    void store(float* p) const { std::memcpy(p, v, sizeof v); }
};
template <class F>
inline VFloat4 lanewise(VFloat4 a, VFloat4 b, F f) {
    VFloat4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = f(a.v[i], b.v[i]);
    return r;
}
inline uint32_t asBits(float x) {
    uint32_t u;
    std::memcpy(&u, &x, 4);
    return u;
}
inline float fromBits(uint32_t u) {
    float x;
    std::memcpy(&x, &u, 4);
    return x;
}
inline float maskLane(bool b) { return fromBits(b ? 0xFFFFFFFFu : 0u); }
inline VFloat4 operator+(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return x + y; }); }
inline VFloat4 operator-(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return x - y; }); }
inline VFloat4 operator*(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return x * y; }); }
inline VFloat4 operator/(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return x / y; }); }
inline VFloat4 operator&(VFloat4 a, VFloat4 b) {
    return lanewise(a, b, [](float x, float y) { return fromBits(asBits(x) & asBits(y)); });
}
inline VFloat4 operator|(VFloat4 a, VFloat4 b) {
    return lanewise(a, b, [](float x, float y) { return fromBits(asBits(x) | asBits(y)); });
}
inline VFloat4 operator^(VFloat4 a, VFloat4 b) {
    return lanewise(a, b, [](float x, float y) { return fromBits(asBits(x) ^ asBits(y)); });
}
inline VFloat4 fnmadd(VFloat4 a, VFloat4 b, VFloat4 c) {
    VFloat4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = std::fma(-a.v[i], b.v[i], c.v[i]);
    return r;
}
inline VFloat4 fmadd(VFloat4 a, VFloat4 b, VFloat4 c) {
    VFloat4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = std::fma(a.v[i], b.v[i], c.v[i]);
    return r;
}
inline VFloat4 min(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return x < y ? x : y; }); }
inline VFloat4 max(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return x > y ? x : y; }); }
inline VFloat4 cmpGe(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return maskLane(x >= y); }); }
inline VFloat4 cmpLe(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return maskLane(x <= y); }); }
inline VFloat4 cmpGt(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return maskLane(x > y); }); }
inline VFloat4 cmpLt(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return maskLane(x < y); }); }
inline VFloat4 cmpNe(VFloat4 a, VFloat4 b) { return lanewise(a, b, [](float x, float y) { return maskLane(!(x == y)); }); }
inline VFloat4 select(VFloat4 mask, VFloat4 a, VFloat4 b) {
    VFloat4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = (asBits(mask.v[i]) >> 31) ? a.v[i] : b.v[i];
    return r;
}
inline uint32_t bits(VFloat4 mask) {
    uint32_t m = 0;
    for (int i = 0; i < 4; ++i) m |= (asBits(mask.v[i]) >> 31) << i;
    return m;
}
inline VFloat4 signMask4() { return VFloat4::broadcast(-0.0f); }
inline VFloat4 horizontalMin(VFloat4 a) {
    float m = a.v[0];
    for (int i = 1; i < 4; ++i) m = a.v[i] < m ? a.v[i] : m;
    return VFloat4::broadcast(m);
}
inline void truncClamp(VFloat4 a, int hi, int32_t out[4]) {
    for (int k = 0; k < 4; ++k) {
        const float f = a.v[k];
        const int32_t i = f >= float(hi) ? hi : (f > 0.0f ? int32_t(f) : 0);
        out[k] = i;
    }
}
inline VFloat4 xyz(VFloat4 a) { return {{a.v[0], a.v[1], a.v[2], 0.0f}}; }
inline int32_t truncToInt(float x) {
    return (x > -2147483648.0f && x < 2147483648.0f) ? int32_t(x) : INT32_MIN;
}
inline VFloat4 loadu4(const float* p) { return VFloat4::load(p); }
/// Keeps each product a separately rounded value (see the AVX2 version).
inline VFloat4 materialize(VFloat4 a) {
    volatile float keep[4] = {a.v[0], a.v[1], a.v[2], a.v[3]};
    return {{keep[0], keep[1], keep[2], keep[3]}};
}
inline float materialize(float a) {
    volatile float keep = a;
    return keep;
}

#endif

}  // namespace rays::tribvh

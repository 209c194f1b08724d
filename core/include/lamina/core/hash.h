// Integer hashing used to derive independent seeds and scrambles from (seed, pixel, index).
#pragma once

#include <cstdint>
#include <initializer_list>

namespace lamina {

/// A 64-bit bit mixer (the finaliser of Steele et al.'s SplitMix64, with the constants of
/// Stafford's "Mix13"): every input bit affects every output bit.
constexpr std::uint64_t mixBits(std::uint64_t v) {
    v ^= v >> 30u;
    v *= 0xbf58476d1ce4e5b9ULL;
    v ^= v >> 27u;
    v *= 0x94d049bb133111ebULL;
    v ^= v >> 31u;
    return v;
}

/// Hashes several integers into one 64-bit value (order matters).
constexpr std::uint64_t hashValues(std::initializer_list<std::uint64_t> values) {
    std::uint64_t h = 0x6a09e667f3bcc909ULL;
    for (std::uint64_t v : values)
        h = mixBits(h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6u)));
    return h;
}

}  // namespace lamina

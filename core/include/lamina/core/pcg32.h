// PCG32 random number generator: O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient
// Statistically Good Algorithms for Random Number Generation", the PCG-XSH-RR variant with
// 64-bit state and a selectable stream. The constants are the paper's (the multiplier is
// Knuth's MMIX LCG multiplier).
#pragma once

#include <cstdint>

#include "lamina/core/math.h"
#include "lamina/core/vector.h"

namespace lamina {

class Pcg32 {
  public:
    static constexpr std::uint64_t kMultiplier = 6364136223846793005ULL;
    static constexpr std::uint64_t kDefaultState = 0x853c49e6748fea9bULL;
    static constexpr std::uint64_t kDefaultStream = 0xda3e39cb94b95bdbULL;

    Pcg32() = default;
    explicit Pcg32(std::uint64_t seed, std::uint64_t stream = 1) { setSequence(seed, stream); }

    /// Restarts the generator at `seed` on the stream selected by `stream`: distinct streams
    /// give statistically independent sequences for the same seed.
    void setSequence(std::uint64_t seed, std::uint64_t stream) {
        state_ = 0;
        inc_ = (stream << 1u) | 1u;
        nextUint32();
        state_ += seed;
        nextUint32();
    }

    std::uint32_t nextUint32() {
        const std::uint64_t old = state_;
        state_ = old * kMultiplier + inc_;
        const auto xorShifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorShifted >> rot) | (xorShifted << ((~rot + 1u) & 31u));
    }

    /// Uniform integer in [0, bound) without modulo bias.
    std::uint32_t nextUint32(std::uint32_t bound) {
        const std::uint32_t threshold = (~bound + 1u) % bound;
        for (;;) {
            const std::uint32_t r = nextUint32();
            if (r >= threshold) return r % bound;
        }
    }

    /// Uniform float in [0, 1): never returns 1.
    float nextFloat() {
        return std::min(kOneMinusEpsilon<float>, static_cast<float>(nextUint32()) * 0x1p-32f);
    }

    /// Uniform double in [0, 1) with 53 random bits.
    double nextDouble() {
        const std::uint64_t hi = nextUint32();
        const std::uint64_t lo = nextUint32();
        return static_cast<double>(((hi << 32u) | lo) >> 11u) * 0x1p-53;
    }

    template <typename T>
    T next() {
        if constexpr (std::is_same_v<T, double>)
            return nextDouble();
        else
            return nextFloat();
    }

    Vec2f nextFloat2() {
        const float a = nextFloat();
        return {a, nextFloat()};
    }

    /// Moves the state forward (or backward, for negative delta) by `delta` steps in
    /// O(log delta): Brown 1994, "Random Number Generation with Arbitrary Strides".
    void advance(std::int64_t delta) {
        std::uint64_t curMult = kMultiplier, curPlus = inc_, accMult = 1u, accPlus = 0u;
        auto d = static_cast<std::uint64_t>(delta);
        while (d > 0) {
            if (d & 1u) {
                accMult *= curMult;
                accPlus = accPlus * curMult + curPlus;
            }
            curPlus = (curMult + 1u) * curPlus;
            curMult *= curMult;
            d >>= 1u;
        }
        state_ = accMult * state_ + accPlus;
    }

  private:
    std::uint64_t state_ = kDefaultState;
    std::uint64_t inc_ = kDefaultStream;
};

}  // namespace lamina

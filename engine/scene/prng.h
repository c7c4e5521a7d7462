#pragma once
// Deterministic random numbers for procedural scenes. std::uniform_*_distribution
// is implementation-defined, so the same seed could build different scenes on
// different standard libraries; SplitMix64 plus our own float mapping cannot.

#include <cstdint>

namespace eng::scene {

class Prng {
  public:
    explicit Prng(uint64_t seed) : m_state(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}

    uint64_t next() {
        uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }

    // Uniform in [0, 1): the top 24 bits fit a float mantissa exactly.
    float uniform() { return static_cast<float>(next() >> 40) * (1.0f / 16777216.0f); }

    float range(float lo, float hi) { return lo + (hi - lo) * uniform(); }

    // Uniform integer in [0, n); the modulo bias is below 2^-40 for the small n used here.
    uint32_t below(uint32_t n) { return n == 0 ? 0 : static_cast<uint32_t>(next() % n); }

  private:
    uint64_t m_state;
};

} // namespace eng::scene

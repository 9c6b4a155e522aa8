// The bench's random source (edge gaps, pixel stalls): seeded, the same on every harness.
#pragma once

#include <cstdint>

namespace watkins::tb::detail {

// xorshift64*: cheap enough to draw twice per simulated cycle.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    std::uint64_t z = seed + 0x9E3779B97F4A7C15ull;  // splitmix64 of the seed
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    s_ = (z ^ (z >> 31)) | 1;
  }
  std::uint64_t next() {
    s_ ^= s_ >> 12;
    s_ ^= s_ << 25;
    s_ ^= s_ >> 27;
    return s_ * 0x2545F4914F6CDD1Dull;
  }
  // Threshold for "true with probability p" tests against next() >> 11 (53 bits).
  static std::uint64_t threshold(double p) {
    if (!(p > 0)) return 0;
    if (p >= 1) return 1ull << 53;
    return static_cast<std::uint64_t>(p * 9007199254740992.0);
  }
  bool chance(std::uint64_t thr) { return thr != 0 && (next() >> 11) < thr; }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }

 private:
  std::uint64_t s_;
};

}  // namespace watkins::tb::detail

// Twin of rtl/board/tmds_encoder.sv: one DVI 1.0 TMDS lane's encoder, and the matching decoder.
//
// Data (de high): the byte d becomes a transition-minimized word q_m (bits 7:0 an XOR or XNOR chain
// of d, bit 8 set for XOR): XNOR when d has more than four ones, or exactly four with bit 0
// clear, which leaves at most four transitions in q_m[7:0]. Then the DC balance: bit 9 set means
// bits 7:0 are sent inverted. With n = ones(q_m[7:0]) − zeros(q_m[7:0]) and the running
// disparity cnt (ones minus zeros of every bit sent since the last blanking):
//   cnt = 0 or n = 0:           bit 9 = ~q_m[8], bits 7:0 inverted when q_m[8] is clear;
//                               cnt += q_m[8] ? n : −n
//   cnt and n of the same sign: bit 9 = 1 (inverted); cnt += 2·q_m[8] − n
//   else:                       bit 9 = 0;            cnt += n − 2·(1 − q_m[8])
// cnt is exactly the disparity of the symbols sent: every reachable value is even and within
// [−8, 8] (the unit bench proves it by search), so the RTL holds it in 5 signed bits.
// Blanking (de low): the control token of {c1, c0}, and cnt returns to 0.
// Symbols are 10-bit words, bit 0 the first bit on the wire (DVI 1.0 writes them q_out[0:9]).
#pragma once

#include <cstdint>

namespace watkins {

// The control tokens, indexed by {c1, c0}, as 10-bit words (bit 0 sent first).
inline constexpr std::uint16_t TmdsControl[4] = {0b11'0101'0100, 0b00'1010'1011, 0b01'0101'0100, 0b10'1010'1011};
// The running disparity's reachable bound (|cnt| <= 8).
inline constexpr int TmdsDisparityMax = 8;

// The transition-minimized word of a byte: bits 7:0 the chain, bit 8 set for XOR.
inline std::uint16_t tmds_transition_minimized(std::uint8_t d) {
  const int ones = __builtin_popcount(d);
  const bool use_xnor = ones > 4 || (ones == 4 && (d & 1) == 0);
  unsigned q_m = d & 1u;
  for (int i = 1; i < 8; ++i) {
    const unsigned b = ((q_m >> (i - 1)) ^ (d >> i)) & 1u;
    q_m |= (use_xnor ? b ^ 1u : b) << i;
  }
  return static_cast<std::uint16_t>(q_m | (use_xnor ? 0u : 1u << 8));
}

class TmdsEncoder {
 public:
  // One clock of the encoder: the symbol it registers for these inputs.
  std::uint16_t encode(std::uint8_t data, bool de, bool c0, bool c1) {
    if (!de) {
      cnt_ = 0;
      return TmdsControl[(c1 ? 2 : 0) | (c0 ? 1 : 0)];
    }
    const unsigned q_m = tmds_transition_minimized(data);
    const bool q8 = (q_m >> 8) & 1u;
    const unsigned low = q_m & 0xffu, inv = ~q_m & 0xffu;
    const int n = 2 * __builtin_popcount(low) - 8;  // ones minus zeros of q_m[7:0]
    unsigned symbol;
    if (cnt_ == 0 || n == 0) {
      symbol = (q8 ? 0u : 1u << 9) | (q8 ? 1u << 8 : 0u) | (q8 ? low : inv);
      cnt_ += q8 ? n : -n;
    } else if ((cnt_ > 0) == (n > 0)) {
      symbol = (1u << 9) | (q8 ? 1u << 8 : 0u) | inv;
      cnt_ += (q8 ? 2 : 0) - n;
    } else {
      symbol = (q8 ? 1u << 8 : 0u) | low;
      cnt_ += n - (q8 ? 0 : 2);
    }
    return static_cast<std::uint16_t>(symbol);
  }
  int disparity() const { return cnt_; }  // the running disparity after the last symbol
  void reset() { cnt_ = 0; }

 private:
  int cnt_ = 0;
};

struct TmdsDecoded {
  enum class Kind { Data, Control, Invalid };
  Kind kind = Kind::Invalid;
  std::uint8_t data = 0;  // Kind::Data: the byte
  bool c0 = false;        // Kind::Control: the control pair
  bool c1 = false;
};

// A 10-bit symbol back to its byte or control pair. Invalid: a word no encoder state sends
// (the decoded byte's transition-minimized word differs from the symbol's, or a balanced q_m sent
// with bit 9 = q_m[8], which only a nonzero disparity with an unbalanced word can choose).
inline TmdsDecoded tmds_decode(std::uint16_t symbol) {
  TmdsDecoded r;
  symbol &= 0x3ffu;
  for (int k = 0; k < 4; ++k) {
    if (symbol == TmdsControl[k]) {
      r.kind = TmdsDecoded::Kind::Control;
      r.c0 = (k & 1) != 0;
      r.c1 = (k & 2) != 0;
      return r;
    }
  }
  const bool inverted = (symbol >> 9) & 1u;
  const bool q8 = (symbol >> 8) & 1u;
  const unsigned q = (inverted ? ~symbol : symbol) & 0xffu;
  unsigned d = q & 1u;
  for (int i = 1; i < 8; ++i) {
    const unsigned b = ((q >> i) ^ (q >> (i - 1))) & 1u;
    d |= (q8 ? b : b ^ 1u) << i;
  }
  const std::uint8_t data = static_cast<std::uint8_t>(d);
  const unsigned q_m = tmds_transition_minimized(data);
  const bool balanced = __builtin_popcount(q_m & 0xffu) == 4;
  if (q_m != (q | (q8 ? 1u << 8 : 0u)) || (balanced && inverted == q8)) return r;
  r.kind = TmdsDecoded::Kind::Data;
  r.data = data;
  return r;
}

}  // namespace watkins

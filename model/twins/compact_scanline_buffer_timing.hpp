// Cycle twin of rtl/compact_scanline_buffer.sv: its control, clocked once per cycle with the same
// handshake inputs, no values (the pixel values are ScanlineBuffer's, scanline_buffer.hpp). It
// says in which cycles the block takes an input (frag_ready_o) and offers a pixel (pixel_valid_o),
// and the position of the pixel offered, so a bench holds the RTL to it cycle for cycle and a
// cycle model of the compact top composes it.
//
// The clock, as the RTL's header states it: after reset the marks of both banks are cleared, one
// address of every way per clock, clear_clocks() = ceil(max_width / lanes) clocks with
// frag_ready_o low; then a beat (lanes fragments at most) is taken every clock it is offered. A
// marker is taken when the reader is idle, or in the clock the reader loads the previous line's
// last pixel. The reader starts the clock after the marker: one clock reads pixel 0, then each
// clock the output register can take a pixel (empty, or emptied by pixel_ready_i in that clock)
// loads pixel x and reads x + 1. A line read out at full rate takes width + 1 clocks.
#pragma once

namespace watkins {

class CompactScanlineBufferTiming {
 public:
  // The state right after reset (the first clock with rst_ni high is the clear's first). lanes:
  // the RTL's Lanes, 1 or 2 (its RAMs are lanes ways by x, cleared in parallel).
  explicit CompactScanlineBufferTiming(int max_width, int lanes = 1)
      : clear_clocks_((max_width + lanes - 1) / lanes) {}

  // The clear after reset's length in clocks: frag_ready_o is low for the first clear_clocks().
  int clear_clocks() const { return clear_clocks_; }

  // The frame inputs width_i and height_i (stable per frame).
  void set_frame(int width, int height) {
    width_ = width;
    height_ = height;
  }

  // This clock's frag_ready_o with frag_eol_i = eol, and pixel_ready_i = pixel_ready (a marker may
  // be taken in the clock the reader loads its last pixel, which depends on pixel_ready_i).
  bool frag_ready(bool eol, bool pixel_ready) const { return !clear_ && (!eol || eol_ok(pixel_ready)); }
  // This clock's pixel_valid_o and the offered pixel's position and last flag.
  bool pixel_valid() const { return pixel_valid_; }
  int pixel_x() const { return pixel_x_; }
  int pixel_y() const { return pixel_y_; }
  bool pixel_last() const { return pixel_last_; }
  // Whether the reader is reading a line out (from the clock after its marker to its last load).
  bool reading() const { return busy_; }

  // One clock edge with the inputs of the clock: frag_valid_i, frag_eol_i, pixel_ready_i.
  void clock(bool frag_valid, bool frag_eol, bool pixel_ready) {
    const bool load = loads(pixel_ready);
    const bool last = rx_ + 1 == width_;
    const bool read = busy_ && (!pf_ || (load && !last));
    const bool eol_take = frag_valid && frag_eol && eol_ok(pixel_ready);
    if (clear_) {
      ++clear_x_;
      if (clear_x_ == clear_clocks_) clear_ = false;
    }
    if (read) pf_ = true;
    if (load) {
      pixel_x_ = rx_;
      pixel_y_ = line_;
      pixel_last_ = last && line_ + 1 == height_;
      ++rx_;
      if (last) {
        busy_ = false;
        pf_ = false;
        rx_ = 0;
        line_ = line_ + 1 == height_ ? 0 : line_ + 1;
      }
    }
    if (!pixel_valid_ || pixel_ready) pixel_valid_ = load;
    if (eol_take) busy_ = true;
  }

 private:
  // The output register takes the prefetched pixel.
  bool loads(bool pixel_ready) const { return pf_ && (!pixel_valid_ || pixel_ready); }
  bool eol_ok(bool pixel_ready) const { return !clear_ && (!busy_ || (loads(pixel_ready) && rx_ + 1 == width_)); }

  int clear_clocks_;
  int width_ = 1, height_ = 1;
  bool clear_ = true;  // the clear after reset
  int clear_x_ = 0;
  bool busy_ = false;  // a line is being read out
  bool pf_ = false;    // pixel rx_ is in the RAMs' read registers
  int rx_ = 0, line_ = 0;
  bool pixel_valid_ = false;
  int pixel_x_ = 0, pixel_y_ = 0;
  bool pixel_last_ = false;
};

}  // namespace watkins

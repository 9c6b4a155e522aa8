// Per-stage check of the bench (frame_driver.hpp): the four internal valid/ready streams of
// watkins_top (stage_taps.hpp), compared transfer by transfer with the model's stage streams
// (WatkinsTop's PipelineObserver, expectations.hpp). The first difference names its stage, line
// and item, both values, and the pixels it affects; the pixel check stays the last one.
//
// Cost: four valid && ready tests per clock through pointers into the model (inline below), and
// a comparison per transfer against a precomputed stream (stage_checker.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "config.hpp"
#include "edge_packing.hpp"
#include "rtl_bench.hpp"
#include "stage_taps.hpp"

namespace watkins::tb::detail {

class StageChecker {
 public:
  // Starts a run: `streams` holds the expected streams of every frame of the run in order (the
  // checker is off when it is empty or `taps` is null). Items are counted into r.stage_items,
  // mismatches reported into r.stage_mismatches / r.first_mismatch / r.first_stage. `config` and
  // `shading` are the top's: its channel vectors are cut per slot with their layout.
  void begin(const StageTaps* taps, const std::vector<StageStreams>* streams, RtlResult* r, long long start_cycle,
             const Config& config, ShadingMode shading);
  void end() { on_ = false; }

  // Called once per clock after the inputs settled, before the rising edge: checks every stage
  // boundary whose valid && ready is high (a transfer on this edge).
  void clock(long long c) {
    if (!on_) return;
    const StageTaps& t = *taps_;
    if (*t.ae_valid && *t.ae_ready && !ae_.dead) edge(c);
    if (*t.sg_valid && *t.sg_ready && !sg_.dead) segment(c);
    // A beat of two lanes is two transfers, lane 0 first.
    if (*t.fr_valid && *t.fr_ready && !fr_.dead) {
      fragment(c, 0);
      if (*t.fr_pair && !fr_.dead) fragment(c, 1);
    }
    if (*t.sh_valid && *t.sh_ready && !sh_.dead) {
      shaded(c, 0);
      if (*t.sh_pair && !sh_.dead) shaded(c, 1);
    }
  }

 private:
  struct Cursor {
    int frame = 0;
    std::size_t i = 0;
    bool dead = false;
  };

  template <class Item>
  const Item* next(Cursor& k, std::vector<Item> StageStreams::*stream) const;
  std::string where(const char* stage, const char* item, const Cursor& k, int line, int index, bool eol,
                    long long c) const;
  void fail(Cursor& k, const char* stage, const std::string& what);
  std::string past_end() const;
  int width_of(const Cursor& k) const;

  void edge(long long c);
  void segment(long long c);
  template <class Same, class Text, class Diff>
  void fragment_stage(long long c, Cursor& k, std::vector<StageFragment> StageStreams::*stream, const char* stage,
                      bool eol, int rtl_x, Same same, Text text, Diff diff);
  void fragment(long long c, int lane);
  void shaded(long long c, int lane);

  ChannelVector channels(const std::uint32_t* words) const { return channels_.read(words); }

  const StageTaps* taps_ = nullptr;
  ChannelLayout channels_;   // slots of ae_value, sg_e, sg_f
  ChannelFormats formats_;   // the top's slot formats (spans of a mismatching segment, X's pixel)
  const std::vector<StageStreams>* streams_ = nullptr;
  RtlResult* r_ = nullptr;
  long long start_ = 0;
  bool on_ = false;
  Cursor ae_, sg_, fr_, sh_;
};

}  // namespace watkins::tb::detail

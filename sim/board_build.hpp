// The board build's hardware half: the board top at a scene's configuration through the shared
// FPGA flow (fpga_flow.hpp) to a bitstream, with the resources used and every clock's routed Fmax
// against the constraint nextpnr derives for it from the oscillator's frequency and the PLL. The
// ULX3S: yosys synth_ecp5, nextpnr-ecp5 with rtl/board/ulx3s_top.lpf, ecppack (.bit), the scene
// bank initialized from its $readmemh file. The iCEBreaker: yosys synth_ice40 -dsp, nextpnr-ice40
// --up5k --package sg48 with rtl/board/icebreaker_top.pcf, icepack, and the .bin the flash holds:
// the bitstream, then the scene bank at SpramBank::FlashAddress (flash_image.hpp), which the top
// copies into its SPRAMs after configuration.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "config.hpp"
#include "fpga_flow.hpp"
#include "shading_mode.hpp"

namespace watkins::board_command {

struct BitstreamJob {
  std::string board = "ulx3s";          // ulx3s | icebreaker
  Config config;                        // the scene's configuration (watkins_top's parameters)
  ShadingMode shading = ShadingMode::Gouraud;
  int doubling = 2, line_slots = 2;
  int bank_words = 0;                   // the scene bank's words (a power of two)
  std::string bank_file;                // bank 0's $readmemh file (absolute; the ULX3S)
  std::vector<std::uint8_t> flash_scene;  // the bank's flash bytes (flash_image; the iCEBreaker)
  std::string work;                     // yosys and nextpnr's folder (absolute; made)
  std::string rtl_dir;                  // the source tree's rtl/ (absolute)
  int seed = 0;                         // nextpnr --seed; 0: none
  int timeout_s = 3600;                 // per tool
};

struct BitstreamResult {
  bool ok = false;                      // a bitstream, every clock's constraint met
  std::string result;                   // what happened, one phrase
  std::string bit;                      // the bitstream in work (when the flow ran to it; the
                                        // iCEBreaker's with the scene after it)
  flow::SynthesisResult yosys;
  flow::PlaceResult nextpnr;
  double pack_s = 0;                    // ecppack or icepack
};

// The board top's parameters: rtl_parameters(config, shading) and the board's own.
std::vector<std::pair<std::string, std::string>> board_top_parameters(const BitstreamJob& job);
// Runs yosys, nextpnr and ecppack (ULX3S, ECP5-85 CABGA381) or icepack (iCEBreaker, UP5K SG48)
// for `job`.
BitstreamResult build_bitstream(const BitstreamJob& job);
// The report: resources (nextpnr's utilisation) and every clock against its constraint, markdown.
std::string bitstream_report(const BitstreamJob& job, const BitstreamResult& r);

}  // namespace watkins::board_command

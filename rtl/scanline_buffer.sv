// scanline_buffer: per-pixel visibility of one scan line and the raster-order pixel stream.
// Twin: model/twins/scanline_buffer.hpp. Two line buffers (ping-pong): fragments of line y are
// depth-tested into one (kept when the pixel is empty or strictly nearer; at equal depth
// tie_submission_i decides: 0 keeps the first arrival, 1 the smaller polygon id -- GL's
// submission order) while the other streams line y-1 out, pixel x = 0..width-1, clearing each
// pixel as it is read. The end-of-line marker swaps the buffers once the reader has taken the
// previous line's last pixel; the reader starts on the next clock (full mode) or the one after
// (sparse mode: its search registers are handed over in between).
// Latency: a fragment is accepted, read and tested in three consecutive clocks, written at the
// end of the third; a line's pixels stream out after its end-of-line marker swaps the buffers,
// one per clock, each one clock after the reader takes it (from the shade RAM's output register,
// with registered coverage and background).
// Stages (write side): accept (frag_take: the depth RAM read) -> read (a_*_q: the RAM's data
// registered) -> test (t_*_q: the depth test and the RAM write). Read side: take (rd_load) ->
// pixel (pixel_*_o).
// Registered: every pixel output. frag_ready_o is combinational (low only for a marker waiting
// on the reader, or for one clock behind a fragment in the read step) from registers and
// pixel_ready_i only: the reader's decisions come from per-bank counts of written bits and flags
// set a step ahead, never from the search (watkins_top puts a registered-ready queue in front
// all the same); a marker swaps the buffers while its line's last fragment is still being
// tested, which lands before the reader's first read.
// Storage: depth (with the winner's polygon id beside it, PolyIdBits + DepthBits per word) and
// shade in two RAMs of 2 * MaxWidth words with synchronous reads (block RAM: SB_RAM40_4K /
// DP16KD), each with one write port (the writer) and one read port (depth: the writer's depth
// test; shade: the reader), and one written bit per pixel and bank in flops, by x (set by every
// fragment tested, cleared as the reader takes the pixel; unwritten words are never read as
// values). The write side takes one fragment per clock; the depth words (id included) written
// the two clocks before are forwarded, so back-to-back fragments to the same x see each other.
// Sparse mode (sparse_i, stable per frame): the reader emits only the covered pixels of a line,
// in raster order, one per clock: the lowest written bit of the read bank is the next one (those
// below the current x are already cleared), found hierarchically from registers kept per
// 32-pixel word (which words hold one and each one's lowest bit), and the line ends with its
// last covered pixel; a line with no covered pixel costs one cycle and emits nothing. The frame's
// last beat (pixel_last_o) is the last covered pixel of the last line; when the last line has no
// covered pixel (in particular when the frame covers none), a terminating beat with
// pixel_covered_o = 0, background rgb, at (width-1, height-1) carries pixel_last_o instead.
// pixel_x_o / pixel_y_o give every beat's position in both modes.
`include "watkins_assert.svh"

module scanline_buffer #(
  parameter int unsigned MaxWidth   = watkins_pkg::DefaultMaxWidth,  // line-buffer depth in
                                                                     // pixels
  parameter int unsigned DepthBits  = watkins_pkg::DepthBits,   // depth word (the configuration's)
  parameter int unsigned PolyIdBits = watkins_pkg::PolyIdBits   // polygon id (the configuration's)
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  logic [watkins_pkg::LineBits-1:0]  width_i,           // 1..MaxWidth, stable per frame
  input  logic [watkins_pkg::LineBits-1:0]  height_i,          // lines per frame, for
                                                               // pixel_last_o
  input  watkins_pkg::rgb_t                 background_i,      // shade of uncovered pixels
  input  logic                              sparse_i,          // covered pixels only, stable per
                                                               // frame
  input  logic                              tie_submission_i,  // equal depth: smaller id wins;
                                                               // stable per frame
  input  logic [watkins_pkg::LineBits-1:0]  frag_x_i,          // < width_i
  input  logic [DepthBits-1:0]              frag_depth_i,      // smaller is nearer
  input  logic [PolyIdBits-1:0]             frag_poly_i,       // polygon id: submission order
  input  watkins_pkg::rgb_t                 frag_rgb_i,
  input  logic                              frag_eol_i,        // end-of-line marker: the line is
                                                               // complete
  input  logic                              frag_valid_i,
  output logic                              frag_ready_o,
  output watkins_pkg::rgb_t                 pixel_rgb_o,
  output logic                              pixel_covered_o,
  output logic [watkins_pkg::LineBits-1:0]  pixel_x_o,
  output logic [watkins_pkg::LineBits-1:0]  pixel_y_o,
  output logic                              pixel_last_o,      // last pixel of the frame
  output logic                              pixel_valid_o,
  input  logic                              pixel_ready_i
);
  localparam int unsigned LineBits    = watkins_pkg::LineBits;
  localparam int unsigned AddressBits = $clog2(2 * MaxWidth);  // both banks

  // Bank b holds pixel x at address b * MaxWidth + x. Shades as plain vectors, not rgb_t: yosys
  // 0.23 mishandles arrays of structs.
  localparam int unsigned RgbBits = watkins_pkg::RgbBits;
  // Depth word: {polygon id, depth} of the pixel's current winner.
  localparam int unsigned DepthWordBits = PolyIdBits + DepthBits;
  logic [DepthWordBits-1:0] depth_mem [2 * MaxWidth];
  logic [RgbBits-1:0]       rgb_mem   [2 * MaxWidth];
  // Written bits, one per pixel, in flops (cleared by reset and by reading): the read bank's and
  // the write bank's, exchanged at the swap; declared below, by 32-pixel word.

  logic                wsel_q;  // bank being written; the reader uses the other one
  logic                rd_busy_q;
  logic [LineBits-1:0] rx_q, rline_q;

  // x < width_i <= MaxWidth, so its high bits are zero.
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic logic [AddressBits-1:0] addr(logic bank, logic [LineBits-1:0] x);
    addr = bank ? AddressBits'(MaxWidth) + AddressBits'(x) : AddressBits'(x);
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  // ------------------------------------------------------------ written bits
  // Kept by bank, in flops, one flat vector per bank (bank b's word w at bits_q[b][w]): the swap
  // only flips wsel_q, so no bit's next state depends on the marker (kept by role, each of the
  // 2 * MaxWidth bits would choose between keeping and taking the other bank's at the swap: the
  // marker's acceptance, deep and combinational, would fan out to all of them, in series with the
  // indexed write's address arithmetic). A bit is set by the fragment tested in
  // its bank and cleared by the reader's take in its bank, each through one-hot word and bit
  // selects (registered for the writer; compares, not shifts, for the reader), so a bit's next
  // state is one or two LUTs. Readers pick the read bank's words with wsel_q. Stored by 32-pixel
  // word: the sparse search keeps registers per word, and a simulator updates a word, not a bank.
  // Padding bits of the last word (MaxWidth not a multiple of 32) are never set: every x written
  // or read is below width_i <= MaxWidth.
  localparam int unsigned WordBits      = 32;
  localparam int unsigned BitIndexBits  = $clog2(WordBits);  // a bit in a word
  localparam int unsigned Words         = (MaxWidth + WordBits - 1) / WordBits;
  localparam int unsigned WordIndexBits = (Words > 1) ? $clog2(Words) : 1;
  localparam int unsigned BankBits      = Words * WordBits;
  logic [2*BankBits-1:0] bits_q;  // bank b's word w at [(b * Words + w) * WordBits +: WordBits]

  // An x's word and its bit in it (x < MaxWidth: its high bits are zero).
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic logic [WordIndexBits-1:0] word_of(logic [LineBits-1:0] x);
    word_of = WordIndexBits'(x >> BitIndexBits);
  endfunction
  function automatic logic [BitIndexBits-1:0] bit_of(logic [LineBits-1:0] x);
    bit_of = x[BitIndexBits-1:0];
  endfunction
  // Bank b's word w (w a constant: a part select; b picks one of two).
  function automatic logic [WordBits-1:0] bank_word(logic b, int w);
    bank_word = b ? bits_q[(Words + w) * WordBits +: WordBits] : bits_q[w * WordBits +: WordBits];
  endfunction
  // Bank b's word selected by a one-hot vector.
  function automatic logic [WordBits-1:0] word_at_hot(logic b, logic [Words-1:0] hot);
    word_at_hot = '0;
    for (int w = 0; w < Words; w++) word_at_hot |= hot[w] ? bank_word(b, w) : '0;
  endfunction
  // The lowest set bit of a vector of word flags, one-hot.
  function automatic logic [Words-1:0] lowest_word(logic [Words-1:0] occ);
    lowest_word = occ & ~(occ - 1'b1);
  endfunction
  // A word's lowest written bit (0 when it holds none).
  // Two levels, as a tree (a loop over the 32 bits maps to a priority chain of LUTs, far too slow
  // on the ECP5; the lowest one isolated by a carry chain, bits & -bits, and encoded by ORs takes
  // more LUTs and is slower still): each byte's lowest bit and whether it holds one, then the
  // lowest byte's.
  // Single loops, not nested: Verilator 5.006 unrolls a loop whose body holds another loop only
  // below its statement limit, and a loop left rolled indexes the vectors at run time.
  localparam int unsigned Bytes = WordBits / 8;
  function automatic logic [BitIndexBits-1:0] lowest_bit(logic [WordBits-1:0] bits);
    logic [2:0]              in_byte [Bytes];
    logic [Bytes-1:0]        nz;
    logic [BitIndexBits-4:0] byte_ix;
    for (int b = 0; b < Bytes; b++) begin
      nz[b]      = |bits[8 * b +: 8];
      in_byte[b] = '0;
    end
    // Downwards, so each byte keeps its lowest set bit.
    for (int i = WordBits - 1; i >= 0; i--) if (bits[i]) in_byte[i / 8] = 3'(i % 8);
    byte_ix = '0;
    for (int b = Bytes - 1; b >= 0; b--) if (nz[b]) byte_ix = (BitIndexBits - 3)'(b);
    lowest_bit = {byte_ix, in_byte[byte_ix]};
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  // ------------------------------------------------------------ read-side search (sparse)
  // The lowest written bit of the read bank is the next covered pixel. No compare with an x is
  // needed: the reader clears each pixel it takes and takes them lowest first, and the writer
  // never touches the read bank after the swap (its last fragment lands on the swap clock, when
  // the reader's x is 0), so every written bit below the reader's x is already clear
  // (a_sparse_below_clear).
  // Hierarchical and from registers (a search over the written bits themselves would put a
  // 32-bit priority encoder, a word-level borrow chain and a mux between the flops and the RAM's
  // read address: far too slow on the ECP5, the sized Gouraud top's critical path): per
  // 32-pixel word of each bank, whether it holds a written bit (*_occ_q) and its lowest one's
  // index (*_low_q), kept as the bits change. The write bank's word takes a fragment's bit when
  // that is lower; the swap hands the write bank's words to the reader, each with the rest of its
  // bits (rd_rest_q: all but the lowest); the reader's take clears its word's lowest bit (the
  // word becomes its rest), and that word's next lowest is the rest's lowest (each word in
  // parallel, from its registers: a 32-bit encoder, and the next rest by a carry chain; the
  // one-hot first word enables the update). Whether the first word holds
  // another bit after the take -- which decides the next first word -- is a register too
  // (rd_more_q: two or more), kept from a count of each word's written bits (*_wcnt_q: a take
  // leaves two or more when there were three); found from the bits it would be the block's
  // longest path (`rd_low_q` -> decode -> 32-bit OR -> `first_q`). a_rd_words / a_wr_words check
  // them all against the bits.
  // Only sparse mode reads them on the read side: the read search sits inside `if (sparse_i)`
  // (full mode keeps it idle and Verilator skips it), and only sparse mode loads them at the
  // swap (full mode's stay empty).
  logic [Words-1:0]              rd_occ_q, wr_occ_q;
  logic [Words*BitIndexBits-1:0] rd_low_q, wr_low_q;  // word w's at [w * BitIndexBits +:
                                                      // BitIndexBits]
  // The read bank's word w without its lowest written bit (rd_low_q's): what the word holds
  // after the reader's next take there, and where the take after it is found.
  logic [Words*WordBits-1:0]     rd_rest_q;  // word w's at [w * WordBits +: WordBits]
  logic [Words-1:0]              first_q;    // one-hot: the read bank's first occupied word
                                             // (a_first)
  localparam int unsigned WordCountBits = $clog2(WordBits + 1);
  logic [Words*WordCountBits-1:0] rd_wcnt_q, wr_wcnt_q;  // word w's written bits, counted (at
                                                         // w * WordCountBits)
  logic [Words-1:0]              rd_more_q;  // the read bank's word w holds two or more
  logic [WordIndexBits-1:0]      fw;         // that word
  logic [BitIndexBits-1:0]       lb;         // its lowest written bit
  logic [LineBits-1:0]           nx;
  logic [Words*BitIndexBits-1:0] next_low;   // each word's lowest bit once its lowest is taken
  logic [Words*WordBits-1:0]     next_rest;  // and the bits above that one

  always_comb begin
    fw    = '0;
    lb    = '0;
    if (sparse_i) begin
      for (int w = 0; w < Words; w++) begin
        if (first_q[w]) fw = WordIndexBits'(w);
        lb |= first_q[w] ? rd_low_q[w * BitIndexBits +: BitIndexBits] : '0;
      end
    end
    nx = LineBits'({fw, lb});
  end
  // Each word's next lowest, all words in parallel, from its rest register alone: the lowest
  // bit of rd_rest_q is the next lowest, and rd_rest_q with that bit cleared (x & (x - 1): a
  // carry chain) the next rest. (From the bits and rd_low_q, decoded and cleared before the
  // 32-bit encoder, it would be both tops' critical path.)
  // A block per word writing its own slices (a loop over the words holding the loop over the
  // bits is left rolled by Verilator 5.006, every word's vectors then indexed at run time;
  // continuous assigns out of the block would be evaluated on every clock in full mode too).
  for (genvar w = 0; w < Words; w++) begin : g_next
    always_comb begin
      logic [WordBits-1:0] rest;
      rest = '0;
      next_rest[w * WordBits +: WordBits]        = '0;
      next_low[w * BitIndexBits +: BitIndexBits] = '0;
      if (sparse_i) begin
        rest = rd_rest_q[w * WordBits +: WordBits];
        next_rest[w * WordBits +: WordBits]        = rest & (rest - 1'b1);
        next_low[w * BitIndexBits +: BitIndexBits] = lowest_bit(rest);
      end
    end
  end

  // ------------------------------------------------------------ write side
  logic                   frag_take, eol_take, rd_load, rd_step, rd_emit, rd_last, rd_lastline;
  logic                   eol_ok;
  logic [LineBits-1:0]    rd_x;
  logic [AddressBits-1:0] wa, ra;

  // The reader's decisions come from registers, not from the search: frag_ready_o (a marker's
  // acceptance) depends on rd_last, and a search on that path would put the written bits' whole
  // priority logic in front of every stall enable upstream (the tops' critical path). The
  // written bits of each bank are counted as they are set and cleared (rd_cnt_q, wr_cnt_q);
  // whether the read bank holds one (cnt_found_q) and two (cnt_more_q) are registers kept beside
  // its count (a_cnt_found, a_cnt_more: compared from the count, they would be the block's
  // longest path, rd_cnt_q -> rd_last -> rd_step -> last_line_q);
  // the ends of a line and of the frame are flags set a step ahead (rx_end_q: rx_q is
  // width - 1, a_rx_end; last_line_q: rline_q is height - 1, a_last_line).
  // The swap acts in two clocks. The marker's clock (eol_take, from the reader's decisions and
  // the queue in front: deep, and late in the clock) flips the banks' roles (wsel_q) and, in full
  // mode, starts the reader, whose first-word registers follow the write bank while it waits
  // (rx_*); the next clock (swap_q, a register) hands the write bank's counts and words over to
  // the read role and clears the write role's, and in sparse mode starts the reader, which reads
  // them. (Loading them under eol_take would put that signal's fan-out to some 300 flops on its
  // path, a long one in the sized Gouraud top.) The marker leaves the writer's pipeline empty
  // (!a_valid_q), so no fragment is tested on the swap_q clock (a_swap_quiet): the write role's
  // registers are complete then.
  logic                 swap_q;
  localparam int unsigned CountBits = $clog2(MaxWidth + 1);
  logic [CountBits-1:0] rd_cnt_q, wr_cnt_q;
  logic                 rx_end_q, last_line_q;
  logic                 cnt_found_q, cnt_more_q;  // rd_cnt_q > 0, rd_cnt_q > 1
  // width - 1, the frame's last x, in a register: the subtract on the frame constant would be in
  // front of the sparse reader's x pick and the line RAM's read address (the sized Phong top's
  // longest path). width_i is stable per frame and the reader starts long after it
  // changes (a line's fragments first cross the pipeline), so the register is always current
  // while the reader runs (a_wlast).
  logic [LineBits-1:0] wlast_q;
  always_ff @(posedge clk_i) wlast_q <= width_i - 1'b1;

  assign rd_lastline = last_line_q;
  // Full mode: every x. Sparse: the next covered x; an empty line emits nothing unless it is the
  // frame's last (then the terminating beat at width-1).
  assign rd_x      = sparse_i ? (cnt_found_q ? nx : wlast_q) : rx_q;
  assign rd_emit   = !sparse_i || cnt_found_q || rd_lastline;
  assign wa        = addr(wsel_q, frag_x_i);
  assign ra        = addr(!wsel_q, rd_x);
  assign rd_step   = rd_busy_q && (!rd_emit || !pixel_valid_o || pixel_ready_i);
  assign rd_load   = rd_step && rd_emit;
  assign rd_last   = sparse_i ? !cnt_more_q : rx_end_q;
  // The marker may swap in the cycle the reader takes its last pixel (it reads the old bank),
  // once its line's last fragment has left the read step (it is tested on the swap clock at the
  // latest, so it lands before the reader's first read of the bank).
  // In sparse mode the reader waits a clock after the swap for its registers (swap_q, below),
  // and no marker is taken in that clock.
  assign eol_ok       = !a_valid_q && !(sparse_i && swap_q)
                     && (!rd_busy_q || (rd_step && rd_last));
  assign frag_ready_o = !frag_eol_i || eol_ok;
  // A fragment is always taken (not through frag_ready_o: that waits on the search's last).
  assign frag_take    = frag_valid_i && !frag_eol_i;
  assign eol_take     = frag_valid_i && frag_eol_i && eol_ok;

  // Three steps, one fragment per clock. Accept: read the depth word (the RAM's read register),
  // and decode the pixel's word and bit one-hot. Read (a_*): the RAM's data into a register (the
  // block RAM's clock-to-out alone in the clock: on the ECP5 too slow to feed the test as well),
  // and the write bank's word holding the pixel, picked by the one-hot word register, with the
  // bit of the fragment tested in this clock when it is in the same word (decided at the
  // accept). Test (t_*): the pixel's written bit from that word (a 32-bit AND-OR of registers,
  // not a 2 * MaxWidth-way mux); the depth word -- or the word written one or two clocks before
  // at the same address, which the RAM read did not see yet (compared a step ahead) -- and write;
  // the fragment sets its written bit. (The word picked at the accept, from frag_x_i's compares,
  // would be both tops' path: the queue's x -> a_wword_q. The bit picked in the read step too,
  // into a register, would put the word pick and the bit pick in one clock with the written
  // bits' long routes: a_whot_q -> t_written_q, a long path in the sized Gouraud top.)
  logic                     a_valid_q, t_valid_q, lw_valid_q;
  logic [AddressBits-1:0]   a_addr_q, t_addr_q, lw_addr_q, llw_addr_q;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [LineBits-1:0]      a_x_q, t_x_q;  // their x (bank wsel_q's: a marker waits for the read
                                           // step); < MaxWidth
  /* verilator lint_on UNUSEDSIGNAL */
  logic                     t_bank_q;   // the tested fragment's bank: wsel_q while it is tested
                                        // (a marker is never accepted before it is; a copy, so
                                        // the set and the reader's clear have separate selects)
  logic [Words-1:0]         a_whot_q, t_whot_q;  // the pixel's word, one-hot
  logic [WordBits-1:0]      a_bhot_q, t_bhot_q;  // its bit in the word, one-hot
  logic                     a_ahead_q;  // the fragment ahead (tested while this one is read) is
                                        // in its word
  logic [WordBits-1:0]      t_wword_q;  // its bank's word as the test sees it
  logic                     t_fw1_q, t_fw2_q;  // the tested address is lw_addr_q's / llw_addr_q's
  logic                     t_written;  // the pixel already has a fragment
  logic [DepthWordBits-1:0] a_word_q, t_word_q, lw_word_q, llw_word_q, mem_word_q, t_mem_q;
  logic [RgbBits-1:0]       a_rgb_q, t_rgb_q;
  logic                     wins;

  always_ff @(posedge clk_i) begin
    if (frag_take) mem_word_q <= depth_mem[wa];
    if (frag_take) begin
      a_addr_q <= wa;
      a_x_q    <= frag_x_i;
      for (int w = 0; w < Words; w++) a_whot_q[w] <= word_of(frag_x_i) == WordIndexBits'(w);
      for (int i = 0; i < WordBits; i++) a_bhot_q[i] <= bit_of(frag_x_i) == BitIndexBits'(i);
      a_word_q <= {frag_poly_i, frag_depth_i};
      a_rgb_q  <= frag_rgb_i;
      // The fragment read now is tested next clock, and sets its bit after that one: seen in the
      // read step if in the same word. (The one tested now has set its bit by then.)
      a_ahead_q <= a_valid_q && word_of(a_x_q) == word_of(frag_x_i);
    end
    if (a_valid_q) begin
      t_addr_q  <= a_addr_q;
      t_x_q     <= a_x_q;
      t_bank_q  <= wsel_q;
      t_whot_q  <= a_whot_q;
      t_bhot_q  <= a_bhot_q;
      t_word_q  <= a_word_q;
      t_rgb_q   <= a_rgb_q;
      t_mem_q   <= mem_word_q;
      // The fragment tested now sets its bit after this clock: seen here if in the same word.
      t_wword_q <= word_at_hot(wsel_q, a_whot_q) | (a_ahead_q ? t_bhot_q : '0);
      // Which earlier writes the RAM read missed: the one tested now (lw next clock, if it
      // wins) and the one written at the end of the last clock (llw next clock).
      t_fw1_q   <= t_valid_q && t_addr_q == a_addr_q;
      t_fw2_q   <= lw_valid_q && lw_addr_q == a_addr_q;
    end
    lw_addr_q  <= t_addr_q;
    lw_word_q  <= t_word_q;
    llw_addr_q <= lw_addr_q;
    llw_word_q <= lw_word_q;
  end

  assign t_written = |(t_wword_q & t_bhot_q);
  // Whether the tested word beats an old one: nearer, or at equal depth by the tie rule (a tie
  // goes to a strictly smaller id only: equal ids, one polygon's own spans, keep the first
  // arrival, as the model does).
  function automatic logic beats(input logic [DepthWordBits-1:0] t,
                                 input logic [DepthWordBits-1:0] o, input logic tie);
    beats = t[DepthBits-1:0] < o[DepthBits-1:0]
         || (tie && t[DepthBits-1:0] == o[DepthBits-1:0]
             && t[DepthWordBits-1:DepthBits] < o[DepthWordBits-1:DepthBits]);
  endfunction
  // The test against each candidate old word in parallel (the last word written, the one before,
  // the RAM's), picked after the compares: lw_valid_q (the last clock's wins) only picks, so the
  // compare is not in the loop from wins back to wins (the old word's pick, then the compare,
  // would be a critical path of both tops).
  logic beats_lw, beats_llw, beats_mem;
  assign beats_lw  = beats(t_word_q, lw_word_q, tie_submission_i);
  assign beats_llw = beats(t_word_q, llw_word_q, tie_submission_i);
  assign beats_mem = beats(t_word_q, t_mem_q, tie_submission_i);
  assign wins      = t_valid_q && (!t_written || ((lw_valid_q && t_fw1_q) ? beats_lw
                                                  : t_fw2_q ? beats_llw : beats_mem));

  always_ff @(posedge clk_i) begin
    if (wins) begin
      depth_mem[t_addr_q] <= t_word_q;
      rgb_mem[t_addr_q]   <= t_rgb_q;
    end
  end

  // The written bits' update. Every fragment tested sets its pixel's bit in its bank, winner or
  // not (a loser found the bit set already), so the depth test is not on this path. The pixel
  // the reader takes is cleared in the read bank: full mode x = rx_q; sparse, the first occupied
  // word's lowest bit. Both only when the reader takes a pixel: take is rd_load without the
  // search (full mode emits every step; sparse mode emits when it found one, or for the
  // terminating beat, which clears nothing). The tested fragment and the reader are never in
  // one bank (a_tested_in_write_bank). Only the words touched change (a simulator skips the
  // rest).
  logic take;
  assign take = rd_busy_q && (!pixel_valid_o || pixel_ready_i);

  // Full mode's reader, a step ahead (the covered bit from a MaxWidth-way read of the written
  // bits would be the block's critical path): rx_q's bit and word one-hot, stepped
  // with it, and the read bank's word holding rx_q, loaded as the reader enters the word. The
  // read bank does not change under the reader but for the bits it clears behind it: the writer
  // never touches it after the swap, whose clock's tested fragment is forwarded into word 0.
  logic [WordBits-1:0] rx_hot_q;   // rx_q's bit in its word, one-hot (a_rx_hot)
  logic [Words-1:0]    rx_whot_q;  // rx_q's word, one-hot
  logic [WordBits-1:0] rx_word_q;  // that word of the read bank, from x = rx_q up
                                   // (a_covered_is_written)
  // Not loaded by the marker (its fan-out is kept small: see swap_q): x = 0's selects are set
  // at reset and as the reader takes a line's last pixel, and while the reader is idle or taking
  // its last pixel the word follows word 0 of the write bank, the next read bank (with the bit
  // of the fragment tested in this clock), so it holds that word when a marker swaps.
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      rx_hot_q  <= WordBits'(1);
      rx_whot_q <= Words'(1);
    end else if (rd_step) begin
      if (rd_last) begin
        rx_hot_q  <= WordBits'(1);
        rx_whot_q <= Words'(1);
      end else begin
        rx_hot_q <= {rx_hot_q[WordBits-2:0], rx_hot_q[WordBits-1]};
        if (rx_hot_q[WordBits-1]) rx_whot_q <= rx_whot_q << 1;
      end
    end
  end
  always_ff @(posedge clk_i) begin
    if (!rd_busy_q || (rd_step && rd_last))
      rx_word_q <= bank_word(wsel_q, 0) | ((t_valid_q && t_whot_q[0]) ? t_bhot_q : '0);
    else if (rd_step && rx_hot_q[WordBits-1])
      rx_word_q <= word_at_hot(!wsel_q, rx_whot_q << 1);
  end

  // The counts: a fragment tested on an unwritten pixel adds one to the write bank's (the swap
  // clock's lands in the bank it makes the read bank); the reader's take of a covered pixel
  // removes one from the read bank's in sparse mode. Full mode reads no count: its bank is empty
  // at each line's end, and the count is cleared then (counting its takes would put the
  // MaxWidth-way written-bit mux on the count's path).
  logic t_new;
  assign t_new = t_valid_q && !t_written;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      rd_cnt_q  <= '0;
      wr_cnt_q  <= '0;
      cnt_found_q <= 1'b0;
      cnt_more_q  <= 1'b0;
    end else if (swap_q) begin
      // Full mode never loads the read role's (it stays empty).
      if (sparse_i) begin
        rd_cnt_q  <= wr_cnt_q;
        cnt_found_q <= wr_cnt_q != '0;
        cnt_more_q  <= wr_cnt_q > CountBits'(1);
      end
      wr_cnt_q  <= '0;
    end else begin
      // t_new as the enable, not the increment's carry-in: the adder then runs from the register
      // alone, and the written bit's AND-OR reaches only the enable (t_wword_q -> t_new -> the
      // adder's carry chain -> wr_cnt_q would be a long path on the ECP5).
      if (t_new) wr_cnt_q <= wr_cnt_q + 1'b1;
      if (take && sparse_i && cnt_found_q) begin
        rd_cnt_q  <= rd_cnt_q - 1'b1;
        cnt_found_q <= cnt_more_q;
        cnt_more_q  <= rd_cnt_q > CountBits'(2);
      end
    end
  end

  // Written as the set and the clear of one word each, under their enables (a simulator
  // evaluates neither on the clocks without them).
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      bits_q <= '0;
    end else begin
      if (t_valid_q)
        for (int w = 0; w < Words; w++)
          if (t_whot_q[w]) begin
            if (t_bank_q)
              bits_q[(Words + w) * WordBits +: WordBits] <= bank_word(1'b1, w) | t_bhot_q;
            else
              bits_q[w * WordBits +: WordBits]           <= bank_word(1'b0, w) | t_bhot_q;
          end
      if (take)
        for (int w = 0; w < Words; w++)
          if (sparse_i ? first_q[w] : rx_whot_q[w]) begin
            // Sparse: the word's rest (its bits but the lowest, which is taken).
            if (wsel_q)
              bits_q[w * WordBits +: WordBits] <= sparse_i ? rd_rest_q[w * WordBits +: WordBits]
                                                           : bank_word(1'b0, w) & ~rx_hot_q;
            else
              bits_q[(Words + w) * WordBits +: WordBits] <=
                  sparse_i ? rd_rest_q[w * WordBits +: WordBits] : bank_word(1'b1, w) & ~rx_hot_q;
          end
    end
  end

  // The words' occupancy and lowest bits (the search's registers), kept by role, following the
  // bits above: a fragment's bit becomes its word's lowest when lower (each word compares its
  // own; the one-hot word select picks). The swap hands the write bank's words to the reader.
  logic [BitIndexBits-1:0] tb;     // the tested fragment's bit
  logic [Words-1:0]        t_low;  // it becomes that word's lowest in the write bank
  assign tb = bit_of(t_x_q);
  always_comb begin
    t_low = '0;
    if (t_valid_q)
      for (int w = 0; w < Words; w++)
        t_low[w] = t_whot_q[w]
                && (!wr_occ_q[w] || tb < wr_low_q[w * BitIndexBits +: BitIndexBits]);
  end
  // first_q follows rd_occ_q's lowest word: the swap's, or when the reader's take empties the
  // first word (it held one bit: !rd_more_q), the next occupied one (a borrow over the words from
  // registers into one register; computed where it is used, it would be the block's other long
  // path). A fragment tested on an unwritten pixel (t_new) adds one to its word's count.
  logic [Words-1:0] t_inc;  // the tested fragment's word gains a bit
  assign t_inc = t_new ? t_whot_q : '0;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      rd_occ_q  <= '0;
      wr_occ_q  <= '0;
      first_q   <= '0;
      rd_more_q <= '0;
      rd_wcnt_q <= '0;
      wr_wcnt_q <= '0;
      rd_rest_q <= '0;
    end else if (swap_q) begin
      // The old write bank is the read bank now (!wsel_q): its words, each but its lowest bit.
      // Full mode reads the words only through the bits, and never loads the read role's (they
      // stay empty; the sparse reader empties them by each line's end).
      if (sparse_i) begin
        rd_occ_q <= wr_occ_q;
        first_q  <= lowest_word(wr_occ_q);
        for (int w = 0; w < Words; w++) begin
          logic [WordBits-1:0] low_hot;
          for (int i = 0; i < WordBits; i++)
            low_hot[i] = wr_low_q[w * BitIndexBits +: BitIndexBits] == BitIndexBits'(i);
          rd_low_q[w * BitIndexBits +: BitIndexBits] <=
              wr_low_q[w * BitIndexBits +: BitIndexBits];
          rd_rest_q[w * WordBits +: WordBits]           <= bank_word(!wsel_q, w) & ~low_hot;
          rd_wcnt_q[w * WordCountBits +: WordCountBits] <=
              wr_wcnt_q[w * WordCountBits +: WordCountBits];
          rd_more_q[w] <= wr_wcnt_q[w * WordCountBits +: WordCountBits] > WordCountBits'(1);
        end
      end
      wr_occ_q  <= '0;
      wr_wcnt_q <= '0;
    end else begin
      if (t_valid_q) begin
        wr_occ_q <= wr_occ_q | t_whot_q;
        for (int w = 0; w < Words; w++) begin
          if (t_low[w]) wr_low_q[w * BitIndexBits +: BitIndexBits] <= tb;
          if (t_inc[w])
            wr_wcnt_q[w * WordCountBits +: WordCountBits] <=
                wr_wcnt_q[w * WordCountBits +: WordCountBits] + 1'b1;
        end
      end
      if (take && sparse_i) begin
        if (!(|(first_q & rd_more_q))) first_q <= lowest_word(rd_occ_q & ~first_q);
        for (int w = 0; w < Words; w++) begin
          if (first_q[w]) begin
            rd_occ_q[w]  <= rd_more_q[w];
            rd_more_q[w] <= rd_wcnt_q[w * WordCountBits +: WordCountBits] > WordCountBits'(2);
            rd_wcnt_q[w * WordCountBits +: WordCountBits] <=
                rd_wcnt_q[w * WordCountBits +: WordCountBits] - 1'b1;
            rd_low_q[w * BitIndexBits +: BitIndexBits] <=
                next_low[w * BitIndexBits +: BitIndexBits];
            rd_rest_q[w * WordBits +: WordBits] <= next_rest[w * WordBits +: WordBits];
          end
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      a_valid_q     <= 1'b0;
      t_valid_q     <= 1'b0;
      lw_valid_q    <= 1'b0;
      wsel_q        <= 1'b0;
      rd_busy_q     <= 1'b0;
      rx_q          <= '0;
      rline_q       <= '0;
      rx_end_q      <= 1'b0;
      last_line_q   <= height_i == LineBits'(1);  // rline_q 0 (then refreshed while the reader
                                                  // idles)
      swap_q        <= 1'b0;
      pixel_valid_o <= 1'b0;
    end else begin
      a_valid_q   <= frag_take;
      t_valid_q   <= a_valid_q;
      lw_valid_q  <= wins;
      swap_q      <= eol_take;
      // Between lines rline_q holds: the flags follow it and the frame (height_i, width_i).
      if (!rd_busy_q) begin
        last_line_q <= rline_q + 1'b1 == height_i;
        rx_end_q    <= width_i == LineBits'(1);
      end
      if (rd_step) begin
        // Full mode's x (rd_x = rx_q); sparse mode reads neither it nor the flag (an increment
        // of rd_x would put the sparse search on rx_q's path). The next is the line's last when
        // this one is its last but one; after the last, x = 0.
        rx_q     <= rx_q + 1'b1;
        rx_end_q <= rx_q + LineBits'(2) == width_i;
        if (rd_last) begin
          rd_busy_q   <= 1'b0;
          rx_q        <= '0;
          rx_end_q    <= width_i == LineBits'(1);
          rline_q     <= rd_lastline ? '0 : rline_q + 1'b1;
          last_line_q <= rd_lastline ? height_i == LineBits'(1)
                                     : rline_q + LineBits'(2) == height_i;
        end
      end
      if (!pixel_valid_o || pixel_ready_i) pixel_valid_o <= rd_load;
      if (eol_take) wsel_q <= !wsel_q;
      if (sparse_i ? swap_q : eol_take) rd_busy_q <= 1'b1;
    end
  end

  // Read side: the shade RAM's output register is the pixel's shade when covered.
  logic [RgbBits-1:0] rgb_rd_q;
  watkins_pkg::rgb_t background_q;
  always_ff @(posedge clk_i) begin
    if (rd_load) begin
      rgb_rd_q        <= rgb_mem[ra];
      background_q    <= background_i;
      // Sparse: the pixel found is written (none found: the terminating beat is not).
      pixel_covered_o <= sparse_i ? cnt_found_q : |(rx_word_q & rx_hot_q);
      pixel_x_o       <= rd_x;
      pixel_y_o       <= rline_q;
      pixel_last_o    <= rd_last && rd_lastline;
    end
  end
  assign pixel_rgb_o = pixel_covered_o ? rgb_rd_q : background_q;

  `WATKINS_ASSERT_HOLD(a_in_hold, frag_valid_i, frag_ready_o, {frag_x_i, frag_depth_i, frag_poly_i,
    frag_rgb_i, frag_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, pixel_valid_o, pixel_ready_i, {pixel_rgb_o, pixel_covered_o,
    pixel_last_o, pixel_x_o, pixel_y_o})
  `WATKINS_ASSERT(a_wlast, rd_busy_q |-> wlast_q == width_i - 1'b1)
  `WATKINS_ASSERT(a_rx_end, rd_busy_q && !sparse_i |-> rx_end_q == (rx_q == width_i - 1'b1))
  `WATKINS_ASSERT(a_last_line, rd_busy_q |-> last_line_q == (rline_q == height_i - 1'b1))
`ifdef WATKINS_ASSERT_ON
  // One-bit probes: the properties sample them, not the whole written vector (Verilator 5.006
  // emits an undeclared loop variable for a sampled vector this wide).
  // Public, so that Verilator keeps them as variables instead of inlining the vector back in.
  // Only where the assertions are compiled: the speed build would compute them every clock.
  logic below_dirty /* verilator public_flat_rd */;
  logic ra_written /* verilator public_flat_rd */;
  logic t_addr_ok /* verilator public_flat_rd */;
  logic rd_left /* verilator public_flat_rd */;
  logic t_written_p /* verilator public_flat_rd */;
  logic t_written_ref /* verilator public_flat_rd */;  // the tested pixel's bit in its bank
  // The covers' tie: the old word the test sees, and an equal depth won by the smaller id.
  logic [DepthWordBits-1:0] old_word;
  logic tie_wins /* verilator public_flat_rd */;
  assign old_word = (lw_valid_q && t_fw1_q) ? lw_word_q : t_fw2_q ? llw_word_q : t_mem_q;
  assign tie_wins = t_word_q[DepthBits-1:0] == old_word[DepthBits-1:0]
                 && beats(t_word_q, old_word, tie_submission_i);
  logic covered_p /* verilator public_flat_rd */;
  // The search's reference, from the bits themselves (sparse mode): whether the read bank holds
  // a written bit (found) or two (more), and whether every word's registers match its bits;
  // the write bank's words at the swap, when the reader takes them over.
  logic found /* verilator public_flat_rd */;
  logic more /* verilator public_flat_rd */;
  logic rd_words_ok /* verilator public_flat_rd */;
  logic wr_words_ok /* verilator public_flat_rd */;
  // A word's registers against its bits.
  function automatic logic word_ok(logic occ, logic [BitIndexBits-1:0] low,
                                   logic [WordCountBits-1:0] cnt, logic [WordBits-1:0] bits);
    word_ok = occ == |bits && (!(|bits) || low == lowest_bit(bits))
           && 32'(cnt) == 32'($countones(bits));
  endfunction
  always_comb begin
    int n;
    found       = 1'b0;
    more        = 1'b0;
    rd_words_ok = 1'b1;
    wr_words_ok = 1'b1;
    n           = 0;
    if (sparse_i) begin
      for (int w = 0; w < Words; w++) begin
        if (!word_ok(rd_occ_q[w], rd_low_q[w * BitIndexBits +: BitIndexBits],
                     rd_wcnt_q[w * WordCountBits +: WordCountBits], bank_word(!wsel_q, w))
            || rd_more_q[w] != ($countones(bank_word(!wsel_q, w)) > 1)
            || rd_rest_q[w * WordBits +: WordBits] != (bank_word(!wsel_q, w)
                 & ~(rd_occ_q[w] ? WordBits'(1) << rd_low_q[w * BitIndexBits +: BitIndexBits]
                                 : '0)))
          rd_words_ok = 1'b0;
        n += $countones(bank_word(!wsel_q, w));
      end
      found = n != 0;
      more  = n > 1;
    end
    if (swap_q) begin  // the old write bank, now the read bank
      for (int w = 0; w < Words; w++)
        if (!word_ok(wr_occ_q[w], wr_low_q[w * BitIndexBits +: BitIndexBits],
                     wr_wcnt_q[w * WordCountBits +: WordCountBits], bank_word(!wsel_q, w)))
          wr_words_ok = 1'b0;
    end
  end
  localparam int unsigned PaddedIndexBits = $clog2(Words * WordBits);  // an x in the padded words
  // Word by word, not as one MaxWidth-bit vector (a simulator would rebuild and shift that vector
  // on every evaluation of the input-driven logic); only rd_left and ra_written read inputs. A
  // bit past MaxWidth is never written (x < width_i), so the counts below need no mask.
  logic any_set, rest_rx;  // the read bank holds a written bit; one other than rx_q's
  // Sparse mode: the x after the reader's last (rx_q counts steps only).
  logic [LineBits-1:0] sx_q;
  always_ff @(posedge clk_i) begin
    if (eol_take) sx_q <= '0;
    else if (rd_step) sx_q <= rd_x + 1'b1;
  end
  always_comb begin
    int rxw, rxb, rpw, rpb;
    logic [WordBits-1:0] below;
    rxw = int'(sx_q) / WordBits;           // below_dirty: the bits below sx_q (all, past the line)
    rxb = int'(sx_q) % WordBits;
    rpw = int'(PaddedIndexBits'(rx_q)) / WordBits;      // the bit a dense take clears
    rpb = int'(PaddedIndexBits'(rx_q)) % WordBits;
    below_dirty = 1'b0;
    any_set     = 1'b0;
    rest_rx     = 1'b0;
    for (int w = 0; w < Words; w++) begin
      below = (rxw > w) ? '1 : (rxw == w) ? ~({WordBits{1'b1}} << rxb) : '0;
      below_dirty |= |(bank_word(!wsel_q, w) & below);
      any_set     |= |bank_word(!wsel_q, w);
      rest_rx     |= |(bank_word(!wsel_q, w) & ~((rpw == w) ? (WordBits'(1) << rpb) : '0));
    end
  end
  // After this clock's take: a sparse take clears the lowest written bit, so bits are left iff
  // there were two (more); a dense take clears rx_q's.
  assign rd_left = !take ? any_set : sparse_i ? more : rest_rx;
  // Pixel x's written bit in bank b (a MaxWidth-way pick: probes only).
  function automatic logic written_at(logic b, logic [LineBits-1:0] x);
    logic [WordBits-1:0] word;
    word = '0;
    for (int w = 0; w < Words; w++) if (word_of(x) == WordIndexBits'(w)) word = bank_word(b, w);
    written_at = word[bit_of(x)];
  endfunction
  assign ra_written    = written_at(!wsel_q, rd_x);
  assign t_written_p   = t_written;
  assign t_written_ref = written_at(t_bank_q, t_x_q);
  assign covered_p   = sparse_i ? cnt_found_q : |(rx_word_q & rx_hot_q);
  assign t_addr_ok   = t_addr_q == addr(wsel_q, t_x_q) && t_bank_q == wsel_q;
`endif
  `WATKINS_ASSERT(a_sparse_covered, rd_load && sparse_i && !(rd_last && rd_lastline) |-> found)
  // The registered decisions equal what they stand for.
  // (Not on the swap_q clock: the counts and words are handed over at its end.)
  `WATKINS_ASSERT(a_cnt_found, sparse_i && !swap_q |-> cnt_found_q == found)
  `WATKINS_ASSERT(a_first, first_q == (rd_occ_q & ~(rd_occ_q - 1'b1)))
  `WATKINS_ASSERT(a_rx_hot, rd_busy_q && !sparse_i |->
    rx_hot_q == (WordBits'(1) << bit_of(rx_q)) && rx_whot_q == (Words'(1) << word_of(rx_q)))
  `WATKINS_ASSERT(a_cnt_more, sparse_i && !swap_q |-> cnt_more_q == more)
  `WATKINS_ASSERT(a_rd_words, sparse_i && !swap_q |-> rd_words_ok)
  `WATKINS_ASSERT(a_wr_words, swap_q |-> wr_words_ok)
  // Why the write role's registers are complete on the swap_q clock.
  `WATKINS_ASSERT(a_swap_quiet, swap_q |-> !t_valid_q && !rd_busy_q == sparse_i)
  // Why the sparse search needs no rx_q compare, and why covered needs no read at ra.
  `WATKINS_ASSERT(a_sparse_below_clear, rd_busy_q && sparse_i |-> !below_dirty)
  `WATKINS_ASSERT(a_covered_is_written, rd_load |-> covered_p == ra_written)
  // Why the written bits can be kept by role: the tested fragment is in the write bank, and the
  // read bank is empty when the swap makes it the write bank.
  `WATKINS_ASSERT(a_tested_in_write_bank, t_valid_q |-> t_addr_ok)
  `WATKINS_ASSERT(a_swap_read_clear, eol_take |-> !rd_left)
  `WATKINS_ASSERT(a_banks_apart, t_valid_q && rd_load |-> t_addr_q != ra)
  `WATKINS_COVER(c_sparse_empty_line, rd_step && !rd_emit)
  `WATKINS_ASSERT(a_x_in_line, frag_valid_i && !frag_eol_i |-> frag_x_i < width_i)
  `WATKINS_COVER(c_same_x_back_to_back,
    frag_take && $past(frag_take) && frag_x_i == $past(frag_x_i))
  // The forwarding flags, set a step ahead, are the address compares they stand for.
  `WATKINS_ASSERT(a_fw1, t_valid_q |-> t_fw1_q == ($past(t_valid_q) && lw_addr_q == t_addr_q))
  `WATKINS_ASSERT(a_fw2, t_valid_q |-> t_fw2_q == ($past(lw_valid_q) && llw_addr_q == t_addr_q))
  `WATKINS_COVER(c_forwarded, t_valid_q && lw_valid_q && t_fw1_q)
  `WATKINS_COVER(c_forwarded2, t_valid_q && t_fw2_q && !(lw_valid_q && t_fw1_q))
  `WATKINS_COVER(c_eol_waits, frag_valid_i && !frag_ready_o)
  `WATKINS_COVER(c_tie_won, t_valid_q && t_written_p && tie_wins)
  // The test's written bit (the read step's word, the bit picked now) is the pixel's bit in its
  // bank.
  `WATKINS_ASSERT(a_t_written, t_valid_q |-> t_written_p == t_written_ref)
  `WATKINS_COVER(c_tie_forwarded, t_valid_q && lw_valid_q && t_fw1_q && tie_wins)
endmodule

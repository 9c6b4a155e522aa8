// compact_active_edge_list: active_edge_list's streams (the edges crossing each scan line in
// (X, edge id) order, then an end-of-line marker, lines 0..height-1) from one block RAM and a
// sequential insertion sort, no parallel comparators: the compact micro-architecture's list.
// Ports, parameters, streams, edge ids, the skipped late records and the sticky overflow_o are
// active_edge_list's (model/twins/active_edge_list.hpp; the cycle twin
// model/twins/compact_active_edge_list_timing.hpp).
//
// Storage: one array A[0..Entries-1] of entries {remaining, id, polygon, material, value, slope}
// in (X, id) order, plus a scratch word at index Entries, in a RAM with one write port and one
// synchronous read port with an enable (block RAM). The sort key is {X with its sign bit
// inverted, id}: unsigned order is (X, id) order, total since ids are unique. Each line runs
// three phases in turn, one RAM access of each port per clock:
//   INS   the records with y0 == y join the list: each from the end of A, every entry whose key
//         is greater moves up one word (read, then written one word higher) until the record's
//         place is found; the record is written there from edge_i itself (held: not ready yet).
//   OUT   A streams out from the RAM's read register (out_* are its fields), one edge per
//         accepted beat; each accepted edge is stepped (value += slope, remaining -= 1, at edge
//         order 3 by forward differences, as edge_incrementer) on the way back to the RAM's write
//         port and, unless it retires, written at A[kept], kept += 1 (in place: kept <= read).
//         The running maximum of the kept keys (compared a clock after each write) finds the
//         first one that sorts before an earlier one (a crossing), at position D. Then the
//         end-of-line marker.
//   FIX   (only a line with a crossing, not the last) an insertion sort over A[D..K-1]: each entry
//         below the maximum before it goes to the scratch word, the greater ones move up one
//         word each, and it is copied back from the scratch word into its place.
// Then the next line's INS. After the last line's marker the block reads the input up to its
// EOF beat (records past the last line); busy_o falls on the clock after that beat.
// Latency: data-dependent, by phase (clocks when the input is valid and the output ready; input
// gaps and output stalls add their clocks):
//   INS   1 clock per record with y0 below the line (skipped) or at the line with the list full
//         (dropped, overflow_o set); a record placed into a list of L entries, m of them greater
//         than it: 1 clock when L == 0, else m + 2; 1 clock for the head beat past the line
//         (y0 > y, or EOF), which ends the phase and reads A[0].
//   OUT   K edges, one per clock from the clock after INS ends; the marker on the next clock.
//   FIX   from the clock after the marker is taken: 1 + K' - D clocks (the first read, then one
//         per scanned entry of the K' kept), plus m + 2 for each entry that moves back past m
//         others (m + 1 when it goes to the front).
// So a line other than the last takes I + K + 1 + F clocks from its INS's first clock to the
// next line's: I the sum of its INS costs (at least 1), F = 0 without a crossing.
// Ready: edge_ready_o is combinational (state, the head's y0, the count, and in the shift the key
// compare of the read register); out_valid_o and out_eol_o decode the state register; out_* are
// the RAM's read register, which holds while a beat waits.
// Paths: each compare is one carry chain from flops (the key compare from ram_q and cmp_q, the
// crossing's from pend_key_q and max_q, the head's from edge_i and line_q); the next count, pos
// and rd, the read address and enable, the record select and edge_ready_o are pairs from
// registers that the key compare picks between as their last logic; the next state is a pair
// that the key compare picks, or in SEol the crossing compare (eol_q, a flip-flop, says which).
`include "watkins_assert.svh"

module compact_active_edge_list #(
  parameter int unsigned MaxActiveEdges = watkins_pkg::MaxActiveEdges,
  parameter int unsigned XBits          = watkins_pkg::ChannelBits,
  parameter int unsigned ZBits          = watkins_pkg::ChannelBits,
  parameter int unsigned AttrBits       = watkins_pkg::ChannelBits,
  parameter int unsigned PolyIdBits     = watkins_pkg::PolyIdBits,
  parameter int unsigned MaterialIdBits = watkins_pkg::MaterialIdBits,
  parameter int unsigned EdgeIdBits     = watkins_pkg::EdgeIdBits,
  parameter int unsigned EdgeOrder      = 1,  // forward differences per edge: 1 (slope) or 3
                                              // (cubic)
  localparam int unsigned VectorBits = watkins_pkg::vector_bits(XBits, ZBits, AttrBits),
  // the slope field: {d3, d2, d1} at order 3
  localparam int unsigned SlopeBits = EdgeOrder * VectorBits,
  localparam int unsigned EdgeBits = watkins_pkg::edge_bits(XBits, ZBits, AttrBits, PolyIdBits,
                                                            MaterialIdBits, EdgeOrder)
) (
  input  logic                             clk_i,
  input  logic                             rst_ni,
  input  logic                             start_i,         // begin a frame (when !busy_o)
  input  logic [watkins_pkg::LineBits-1:0] height_i,        // lines of the frame, stable while
                                                            // busy_o
  output logic                             busy_o,          // a frame is in progress (until its
                                                            // EOF beat is read)
  input  logic [EdgeBits-1:0]              edge_i,          // y-sorted edge records
  input  logic                             edge_eof_i,      // this beat ends the frame's stream
  input  logic                             edge_valid_i,
  output logic                             edge_ready_o,
  output logic [PolyIdBits-1:0]            out_poly_o,      // polygon of the edge
  output logic [MaterialIdBits-1:0]        out_material_o,  // its material
  output logic [VectorBits-1:0]            out_value_o,     // channels on this line
  output logic                             out_eol_o,       // end-of-line marker, no edge
  output logic                             out_valid_o,
  input  logic                             out_ready_i,
  output logic                             overflow_o       // sticky: an edge was dropped
);
  localparam int unsigned Entries   = MaxActiveEdges;
  localparam int unsigned AddrBits  = $clog2(Entries + 1);  // A[0..Entries-1] and the scratch
  localparam int unsigned CountBits = $clog2(Entries + 1);
  localparam int unsigned LineBits  = watkins_pkg::LineBits;
  localparam int unsigned XLow      = watkins_pkg::slot_lo(watkins_pkg::ChanX, XBits, ZBits,
                                                           AttrBits);
  localparam logic [AddrBits-1:0] Scratch = AddrBits'(Entries);

  // The record's fields (watkins_pkg::edge_bits): {y0, n, poly, material, value, slope}.
  typedef struct packed {
    logic [LineBits-1:0]       y0;
    logic [LineBits-1:0]       n;
    logic [PolyIdBits-1:0]     poly;
    logic [MaterialIdBits-1:0] material;
    logic [VectorBits-1:0]     value;
    logic [SlopeBits-1:0]      slope;
  } record_t;
  record_t rec;
  assign rec = edge_i;

  typedef struct packed {
    logic [LineBits-1:0]       remaining;  // lines left including the current one
    logic [EdgeIdBits-1:0]     id;
    logic [PolyIdBits-1:0]     poly;
    logic [MaterialIdBits-1:0] material;
    logic [VectorBits-1:0]     value;
    logic [SlopeBits-1:0]      slope;
  } entry_t;
  localparam int unsigned BodyBits = LineBits + EdgeIdBits + PolyIdBits + MaterialIdBits
                                     + VectorBits + SlopeBits;  // $bits(entry_t)

  localparam int unsigned KeyBits = XBits + EdgeIdBits;
  localparam logic [XBits-1:0] XSign = XBits'(1) << (XBits - 1);

  typedef enum logic [3:0] {
    SIdle,    // no frame
    SIns,     // INS: look at the input's head
    SShift,   // INS: ram_q = A[pos_q]; move it up or place the record above it
    SPlace,   // INS: every entry moved up: the record goes to A[0]
    SOut,     // OUT: ram_q = A[rd_q], presented
    SEol,     // OUT: the end-of-line marker
    SFix,     // FIX: read A[first_q]
    SScan,    // FIX: ram_q = A[rd_q]; below the maximum before it?
    SFShift,  // FIX: ram_q = A[pos_q]; move it up or stop
    SFPlace,  // FIX: ram_q = the scratch word: write it to A[pos_q]
    SDrain    // after the last line: read the input up to EOF
  } state_t;
  // Plain words so the next state can be picked by AND and OR (yosys 0.23 has no enum casts).
  logic [3:0] state_q, state_d;

  // no_rw_check: no clock reads the word it writes (a_no_ram_collision), so yosys need not
  // emulate either read-during-write behaviour around the block RAM.
  (* no_rw_check *) logic [BodyBits-1:0] mem [2 ** AddrBits];
  entry_t                ram_q;  // the read register: the outputs and the stepper read it
  logic                  re, we;
  logic [AddrBits-1:0]   ra, wa;
  logic                  w_rec, w_step;  // write the record / the stepped ram_q (else ram_q)

  logic                  frame_q;
  logic [LineBits-1:0]   line_q;
  logic [CountBits-1:0]  cnt_q, cnt_d;  // entries in A
  logic [CountBits-1:0]  kept_q, kept_d;  // OUT: stepped entries written back
  logic [AddrBits-1:0]   rd_q, rd_d;    // OUT / FIX: the entry ram_q holds (SOut, SScan)
  logic [AddrBits-1:0]   pos_q, pos_d;  // SShift / SFShift: the entry ram_q holds; SFPlace: place
  logic [AddrBits-1:0]   first_q, first_d;  // D: the first crossing's position
  logic                  cross_q, cross_d;  // this line has a crossing
  logic [KeyBits-1:0]    max_q, max_d;  // OUT / FIX: the greatest key of the entries before
  // The key ram_q's is compared with: in the shifts the key of the entry being placed, in the
  // scan the maximum. Loaded from registers and ram_q only, so no compare's result reaches the
  // comparator.
  logic [KeyBits-1:0]    cmp_q, cmp_d;
  // OUT: the key of the entry written back on the clock before (at A[pend_pos_q]), compared with
  // max_q one clock later: the step's adders and the compare are then not in one clock.
  logic                  pend_q, pend_d;
  logic                  eol_q, eol_d;  // state_q == SEol, a flip-flop of its own for the pick
  logic [KeyBits-1:0]    pend_key_q, pend_key_d;
  logic [AddrBits-1:0]   pend_pos_q, pend_pos_d;
  logic [EdgeIdBits-1:0] id_q;
  logic                  take, ov_set;  // the input's head beat is taken; a record dropped full

  // ------------------------------------------------------------ the step (edge_incrementer's)
  // value += d1 in every slot (order 3 also d1 += d2, d2 += d3, from this line's values; d3 is
  // constant), each slot wrapping at its own word; remaining -= 1. Straight from the read
  // register to the write port: the adders need no register of their own.
  logic [VectorBits-1:0] value_s;
  logic [SlopeBits-1:0]  slope_s;
  logic                  retire;
  for (genvar c = 0; c < watkins_pkg::NumChannels; c++) begin : g_slot
    localparam int unsigned Lo = watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits);
    localparam int unsigned W  = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    assign value_s[Lo +: W] = ram_q.value[Lo +: W] + ram_q.slope[Lo +: W];
    if (EdgeOrder == 3) begin : g_cubic
      assign slope_s[Lo +: W] = ram_q.slope[Lo +: W] + ram_q.slope[VectorBits + Lo +: W];
      assign slope_s[VectorBits + Lo +: W] = ram_q.slope[VectorBits + Lo +: W]
                                             + ram_q.slope[2 * VectorBits + Lo +: W];
      assign slope_s[2 * VectorBits + Lo +: W] = ram_q.slope[2 * VectorBits + Lo +: W];
    end else begin : g_linear
      assign slope_s[Lo +: W] = ram_q.slope[Lo +: W];
    end
  end
  // The model retires when the decremented count is <= 0; n = 0 (malformed) retires too.
  assign retire = ram_q.remaining <= LineBits'(1);

  // ------------------------------------------------------------ keys
  logic [KeyBits-1:0] key_ram, key_step, key_rec;
  logic               ram_below, pend_below;
  assign key_ram  = {ram_q.value[XLow +: XBits] ^ XSign, ram_q.id};
  assign key_step = {value_s[XLow +: XBits] ^ XSign, ram_q.id};
  assign key_rec  = {rec.value[XLow +: XBits] ^ XSign, id_q};
  // Every compare is the borrow of a subtraction: one carry chain and nothing after it (yosys
  // builds a < b of its own as a carry chain and an equality tree, one more LUT level deep).
  /* verilator lint_off UNUSEDSIGNAL */
  logic [KeyBits:0]  key_diff, pend_diff;
  logic [LineBits:0] late_diff, past_diff;
  /* verilator lint_on UNUSEDSIGNAL */
  // One comparator for ram_q: below the maximum (SScan), or, in the shifts, not above the key
  // being placed (keys are unique: not below is above).
  assign key_diff   = {1'b0, key_ram} - {1'b0, cmp_q};
  assign ram_below  = key_diff[KeyBits];
  assign pend_diff  = {1'b0, pend_key_q} - {1'b0, max_q};
  assign pend_below = pend_diff[KeyBits];

  // ------------------------------------------------------------ control
  logic head_late, head_past, full, empty, scan_last, last_line;
  assign late_diff = {1'b0, rec.y0} - {1'b0, line_q};  // y0 < y
  assign past_diff = {1'b0, line_q} - {1'b0, rec.y0};  // y0 > y
  assign head_late = !edge_eof_i && late_diff[LineBits];
  assign head_past = edge_eof_i || past_diff[LineBits];
  assign full      = cnt_q == CountBits'(Entries);
  assign empty     = cnt_q == '0;
  assign scan_last = CountBits'(rd_q) + 1'b1 == cnt_q;  // ram_q is A's last entry (FIX)
  assign out_valid_o = state_q == SOut || state_q == SEol;
  assign out_eol_o   = state_q != SOut;
  assign last_line   = line_q + 1'b1 == height_i;
  assign out_poly_o     = ram_q.poly;
  assign out_material_o = ram_q.material;
  assign out_value_o    = ram_q.value;

  // The registers the key compare decides (state, count, pos, rd) get their next value for
  // either outcome (c1: ram_q below cmp_q, c0: not), from registers and the head's and the
  // crossing's compares; the key compare picks one as their last logic (below), as it does the
  // RAM's ports. Every state that does not compare gives both the same value. The pairs are kept
  // as nets and picked by AND and OR rather than a multiplexer, so synthesis neither folds the
  // compare into their earlier levels nor makes it a flip-flop enable.
  (* keep *) logic [3:0]           state_c0, state_c1;
  (* keep *) logic [CountBits-1:0] cnt_c0, cnt_c1;
  (* keep *) logic [AddrBits-1:0]  pos_c0, pos_c1, rd_c0, rd_c1;
  always_comb begin
    {state_c1, state_c0} = {2{state_q}};
    {cnt_c1, cnt_c0}     = {2{cnt_q}};
    {rd_c1, rd_c0}       = {2{rd_q}};
    {pos_c1, pos_c0}     = {2{pos_q}};
    kept_d  = kept_q;
    first_d = first_q;
    cross_d = cross_q;
    max_d   = max_q;
    pend_d     = 1'b0;
    pend_key_d = key_step;
    pend_pos_d = AddrBits'(kept_q);
    // The running maximum of the kept keys, until the first one below it (a crossing, D).
    if (pend_q) begin
      if (pend_pos_q == '0 || (!cross_q && !pend_below)) begin
        max_d = pend_key_q;
      end else if (!cross_q) begin
        cross_d = 1'b1;  // max_q stays the greatest key before A[first]
        first_d = pend_pos_q;
      end
    end
    ov_set  = 1'b0;
    unique case (state_q)
      SIdle: ;
      SIns: if (edge_valid_i) begin
        if (head_past) begin
          // The line is complete: stream it, its first entry read now.
          {rd_c1, rd_c0} = '0;
          kept_d  = '0;
          cross_d = 1'b0;
          {state_c1, state_c0} = {2{empty ? SEol : SOut}};
        end else if (head_late || full) begin
          ov_set = !head_late;  // taken, skipped or dropped
        end else if (empty) begin
          {cnt_c1, cnt_c0} = {2{CountBits'(1)}};  // taken, written at A[0]
        end else begin
          {pos_c1, pos_c0} = {2{AddrBits'(cnt_q - 1'b1)}};
          {state_c1, state_c0} = {2{SShift}};
        end
      end
      SShift: begin
        // c1: ram_q sorts before the record: its place is above ram_q.
        cnt_c1   = cnt_q + 1'b1;
        state_c1 = SIns;
        if (pos_q == '0) begin
          state_c0 = SPlace;
        end else begin
          pos_c0 = pos_q - 1'b1;
        end
      end
      SPlace: begin
        {cnt_c1, cnt_c0} = {2{cnt_q + 1'b1}};
        {state_c1, state_c0} = {2{SIns}};
      end
      SOut: if (out_ready_i) begin
        // The edge leaves, steps and, unless it retires, is written back at A[kept].
        {rd_c1, rd_c0} = {2{rd_q + 1'b1}};
        if (!retire) begin
          kept_d = kept_q + 1'b1;
          pend_d = 1'b1;
        end
        if (CountBits'(rd_q) + 1'b1 == cnt_q) {state_c1, state_c0} = {2{SEol}};
      end
      SEol: if (out_ready_i) begin
        {cnt_c1, cnt_c0} = {2{kept_q}};
        // The next state's pair is the crossing compare's here (c1: the last edge, if pending,
        // sorts below the maximum): FIX when the line has a crossing.
        if (last_line) begin
          {state_c1, state_c0} = {2{SDrain}};
        end else begin
          state_c1 = (cross_q || (pend_q && pend_pos_q != '0)) ? SFix : SIns;
          state_c0 = cross_q ? SFix : SIns;
        end
      end
      SFix: begin
        {rd_c1, rd_c0} = {2{first_q}};
        {state_c1, state_c0} = {2{SScan}};
      end
      SScan: begin
        // c1: out of order: the entries above its place move up; c0: the greatest so far.
        pos_c1   = rd_q - 1'b1;
        state_c1 = SFShift;
        if (!ram_below) max_d = key_ram;
        rd_c0 = rd_q + 1'b1;
        if (scan_last) state_c0 = SIns;
      end
      SFShift: begin
        // c1: its place is above ram_q.
        pos_c1   = pos_q + 1'b1;
        state_c1 = SFPlace;
        if (pos_q == '0) begin
          state_c0 = SFPlace;
        end else begin
          pos_c0 = pos_q - 1'b1;
        end
      end
      SFPlace: begin
        if (!scan_last) begin
          {rd_c1, rd_c0} = {2{rd_q + 1'b1}};
          {state_c1, state_c0} = {2{SScan}};
        end else begin
          {state_c1, state_c0} = {2{SIns}};
        end
      end
      SDrain: if (edge_valid_i && edge_eof_i) {state_c1, state_c0} = {2{SIdle}};
      default: ;
    endcase
  end
  // The state's pair is picked by the crossing compare in SEol (eol_q), by the key compare in
  // every other state: each is a don't-care where the other decides.
  logic state_below;
  assign state_below = eol_q ? pend_below : ram_below;
  assign state_d = ({4{state_below}} & state_c1) | ({4{!state_below}} & state_c0);
  // No compare state goes to SEol, so c0 alone says whether the next state is SEol.
  assign eol_d   = state_c0 == SEol;
  assign cnt_d   = ({CountBits{ram_below}} & cnt_c1) | ({CountBits{!ram_below}} & cnt_c0);
  assign pos_d   = ({AddrBits{ram_below}} & pos_c1) | ({AddrBits{!ram_below}} & pos_c0);
  assign rd_d    = ({AddrBits{ram_below}} & rd_c1) | ({AddrBits{!ram_below}} & rd_c0);

  // The compared key for the next clock, whichever way this clock's compares go: the record's
  // (INS, for the shift); the scanned entry's (the greatest so far, or the one moving back); the
  // maximum before A[first] (the scan's first entry, and its entry after a move). A shift keeps
  // its key; no other state compares next.
  always_comb begin
    unique case (state_q)
      SIns:           cmp_d = key_rec;
      SScan:          cmp_d = key_ram;
      SFix, SFPlace:  cmp_d = max_q;
      default:        cmp_d = cmp_q;
    endcase
  end

  // ------------------------------------------------------------ the RAM's ports, the take
  // Per state, the read enable and address, the record select and the take for either outcome
  // of ram_q's key compare (1: ram_q below cmp_q, 0: not), from registers and the head's
  // compare; the key compare picks one as the last logic before the RAM and the input (the pairs
  // are kept as nets, so synthesis does not fold the compare into their earlier levels). No port
  // waits for a decision it does not need: ram_q is not read in INS, so INS reads whenever the
  // list has entries, and an empty list's A[0] is unused, so INS writes the record there
  // whenever the list is empty (it is kept if the count grows).
  (* keep *) logic [1:0]          re_c, w_rec_c, take_c;
  (* keep *) logic [AddrBits-1:0] ra_c0, ra_c1;
  logic                           take_ins;  // INS takes the head: skipped, dropped or placed
  assign take_ins = edge_valid_i && !head_past && (head_late || full || empty);
  always_comb begin
    re_c    = '0;
    ra_c0 = rd_q + 1'b1;
    we      = 1'b0;
    wa      = pos_q + 1'b1;
    w_rec_c = '0;
    w_step  = 1'b0;
    take_c  = '0;
    unique case (state_q)
      SIdle: ;
      SIns: begin
        // A[0] for the stream (the head is past the line), else A[L-1] for the shift.
        re_c    = {2{!empty}};
        ra_c0 = head_past ? '0 : AddrBits'(cnt_q - 1'b1);
        we      = empty;
        wa      = '0;
        w_rec_c = 2'b11;
        take_c  = {2{take_ins}};
      end
      SShift: begin
        // A[pos] moves up, or the record goes above it (and is taken); A[pos - 1] is read on
        // every clock (unused when the record's place is found).
        re_c    = 2'b11;
        ra_c0 = pos_q - 1'b1;
        we      = 1'b1;
        w_rec_c = 2'b10;
        take_c  = 2'b10;
      end
      SPlace: begin
        we      = 1'b1;
        wa      = '0;
        w_rec_c = 2'b11;
        take_c  = 2'b11;
      end
      SOut: begin
        re_c   = {2{out_ready_i}};
        we     = out_ready_i && !retire;
        wa     = AddrBits'(kept_q);
        w_step = 1'b1;
      end
      SEol: ;
      SFix: begin
        re_c    = 2'b11;
        ra_c0 = first_q;
      end
      SScan: begin
        // ram_q goes to the scratch word on every scan clock (only an entry out of order is read
        // back from there). The read does not wait for the compare but on the last entry, which
        // may be next to the scratch word.
        re_c    = {1'b1, !scan_last};
        we      = 1'b1;
        wa      = Scratch;
      end
      SFShift: begin
        // ram_q moves up one word on every clock: when its place is above ram_q, that word is
        // the place, which SFPlace writes next.
        re_c    = 2'b11;
        ra_c0 = (pos_q == '0) ? Scratch : pos_q - 1'b1;
        we      = 1'b1;
      end
      SFPlace: begin
        re_c = {2{!scan_last}};
        we   = 1'b1;
        wa   = pos_q;
      end
      SDrain: take_c = {2{edge_valid_i}};
      default: ;
    endcase
    // Below: the scan reads the entry before (the place is searched downwards), the shift the
    // scratch word; every other state reads what it reads either way.
    unique case (state_q)
      SScan:   ra_c1 = rd_q - 1'b1;
      SFShift: ra_c1 = Scratch;
      default: ra_c1 = ra_c0;
    endcase
  end
  assign re           = re_c[ram_below];
  assign ra           = ram_below ? ra_c1 : ra_c0;
  assign w_rec        = w_rec_c[ram_below];
  assign take         = take_c[ram_below];
  assign edge_ready_o = take;

  // ------------------------------------------------------------ the RAM
  logic [BodyBits-1:0] wdata;
  always_comb begin
    if (w_rec) wdata = {rec.n, id_q, rec.poly, rec.material, rec.value, rec.slope};
    else if (w_step) wdata = {ram_q.remaining - 1'b1, ram_q.id, ram_q.poly, ram_q.material, value_s,
                              slope_s};
    else             wdata = ram_q;
  end
  always_ff @(posedge clk_i) begin
    if (we) mem[wa] <= wdata;
  end
  always_ff @(posedge clk_i) begin
    if (re) ram_q <= mem[ra];
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni || (start_i && !frame_q)) begin
      // Reset and frame start clear the same per-frame state; only reset also clears the sticky
      // overflow flag, and a frame start leaves frame_q set.
      frame_q <= rst_ni;
      state_q <= rst_ni ? SIns : SIdle;
      eol_q   <= 1'b0;
      pend_q  <= 1'b0;
      line_q  <= '0;
      cnt_q   <= '0;
      id_q    <= '0;
      if (!rst_ni) overflow_o <= 1'b0;
    end else begin
      state_q <= state_d;
      eol_q   <= eol_d;
      pend_q  <= pend_d;
      cnt_q   <= cnt_d;
      if (state_q == SEol && out_ready_i && !last_line) line_q <= line_q + 1'b1;
      if (take && !edge_eof_i) id_q <= id_q + 1'b1;
      if (ov_set) overflow_o <= 1'b1;
      if (take && edge_eof_i) frame_q <= 1'b0;
    end
  end
  always_ff @(posedge clk_i) begin
    kept_q  <= kept_d;
    rd_q    <= rd_d;
    pos_q   <= pos_d;
    first_q <= first_d;
    cross_q <= cross_d;
    max_q   <= max_d;
    cmp_q   <= cmp_d;
    pend_key_q <= pend_key_d;
    pend_pos_q <= pend_pos_d;
  end

  assign busy_o = frame_q;

  `WATKINS_ASSERT_HOLD(a_in_hold, edge_valid_i, edge_ready_o, {edge_i, edge_eof_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, out_valid_o, out_ready_i, {out_poly_o, out_material_o,
    out_value_o, out_eol_o})
  `WATKINS_ASSERT(a_no_ram_collision, (we && re) |-> wa != ra)
  `WATKINS_ASSERT(a_count, CountBits'(Entries) >= cnt_q)
  `WATKINS_ASSERT(a_kept, (state_q == SOut) |-> kept_q <= CountBits'(rd_q))
  `WATKINS_ASSERT(a_busy, frame_q == (state_q != SIdle))
  `WATKINS_ASSERT(a_pend, pend_q |-> (state_q == SOut || state_q == SEol))
  `WATKINS_ASSERT(a_eol, eol_q == (state_q == SEol))
  `WATKINS_COVER(c_overflow, ov_set)
  `WATKINS_COVER(c_crossing, state_q == SFPlace)
endmodule

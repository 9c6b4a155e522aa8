// active_edge_list: the edges crossing each scan line, in (X, edge id) order, line by line.
// For lines 0..height-1 of a frame, each line's edges stream out followed by an end-of-line
// marker (model/twins/active_edge_list.hpp and the frame loop of model/twins/watkins_top.cpp).
// Two banks (ping-pong): while line y's sorted list streams out of one bank, every streamed edge
// is also stepped by the edge_incrementer and, unless it retires, inserted into the other bank
// for line y+1, as are the new edge records with y0 == y+1 from the y-sorted input stream. One
// sorted insertion per clock (stepped edges first). Edge ids count the records of the frame's
// stream from 0.
// Latency: a line takes about (active + new edges + 7) cycles when nothing stalls: the swap is
// decided a clock before it acts, and it waits for the incrementer's stage and the insertion's
// three (the last three are not waited for on a line that inserts nothing). The first edge of a
// line is presented on the clock after the swap.
// Stages (insertion): body write (body_mem) -> ord1 (key1_q) -> ord2 (lt_q) -> ord3 (below_q)
// -> shift (order_q); the key's multiplexer, the compares, their correction and the shift are
// in separate clocks, still one insertion per clock.
// Registered: out_poly_o, out_material_o, out_value_o are out_q, which the incrementer also
// takes; out_valid_o and out_eol_o come from registers through a little logic; ready is
// combinational. An insertion into a full bank drops the edge and sets the sticky overflow_o.
// Storage: each entry's body (remaining, id, polygon, material, value, slope) is written once,
// into a RAM of two halves (one per bank, 2^(log2 MaxActiveEdges + 1) words; one write port, one
// synchronous read port: block RAM), at the filling bank's append address, and never moved. The
// order is a list of MaxActiveEdges small keys (X, id) with each entry's RAM index, for the
// filling bank only: the insertion compares the key against every entry in parallel and shifts
// keys and indices. At the swap (which waits for the insertion pipeline to empty) the indices
// are copied to the streaming bank's index list (the keys of a streaming bank are never compared
// again), which shifts down by one as each edge leaves. The stream reads the RAM one entry
// ahead: out_q (a fabric register) holds the entry presented, the RAM's read register the one
// after it, so every path from the RAM (whose clock-to-out is a large part of the clock on the
// ECP5) ends at out_q, through at most its enable's multiplexer (one LUT4 on the ECP5).
// Widths from the configuration (model/twins/config.hpp): channel vectors of slot words XBits,
// ZBits, AttrBits (watkins_pkg::slot_lo); polygon, material and edge ids of PolyIdBits,
// MaterialIdBits and EdgeIdBits; the edge record laid out as watkins_pkg::edge_bits says.
// EdgeOrder 3 (curved edges): each record and entry carries the forward differences {d3, d2, d1}
// in place of the slope (three times its bits), stepped by the edge_incrementer; the order,
// streaming and timing are the same.
`include "watkins_assert.svh"

module active_edge_list #(
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
  localparam int unsigned Entries   = MaxActiveEdges;  // per bank
  localparam int unsigned IndexBits = (Entries > 1) ? $clog2(Entries) : 1;  // an entry's index in
                                                                            // its bank's RAM half
  localparam int unsigned CountBits = $clog2(Entries + 1);
  localparam int unsigned LineBits  = watkins_pkg::LineBits;
  localparam int unsigned XLow      = watkins_pkg::slot_lo(watkins_pkg::ChanX, XBits, ZBits,
                                                           AttrBits);

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

  // The sort key: (X, id) order is the unsigned order of {X with its sign bit inverted, id}
  // (ids are unique, so the order is total), one comparator per entry.
  localparam int unsigned KeyBits = XBits + EdgeIdBits;
  localparam logic [XBits-1:0] XSign = XBits'(1) << (XBits - 1);

  // Entry bodies: bank b's entry with index i at {b, i} (plain vectors: yosys 0.23 mishandles
  // arrays of structs).
  localparam int unsigned PayloadBits     = EdgeIdBits + PolyIdBits + MaterialIdBits;  // id,
                                                                                    // polygon,
                                                                                    // material
  localparam int unsigned BodyBits        = LineBits + PayloadBits + VectorBits + SlopeBits;
  localparam int unsigned BodyAddressBits = IndexBits + 1;
  // no_rw_check: no read that reaches out_q meets a write (a_no_ram_collision, below), so yosys
  // need not emulate read-first behaviour around the block RAM (a mux and a register per bit of
  // the record, about 185 of each, and an address compare in front of ram_q).
  (* no_rw_check *) logic [BodyBits-1:0] body_mem [2 ** BodyAddressBits];
  // The filling bank's order: entry i's {sort key, body index} in one word (past the count:
  // don't care).
  logic [KeyBits+IndexBits-1:0] order_q [Entries];
  // The streaming bank's order from the entry at rd_q on: g_sidx[i].q below.
  logic [IndexBits-1:0]  rd_head;       // the body index the RAM reads this clock (bank: rd_addr)
  logic [CountBits-1:0]  cnt_stream_q, cnt_fill_q;
  logic                  sel_q, sel_d;  // bank (RAM half) streamed for line line_q - 1; the other
                                        // fills
  logic                  frame_q, drain_q;
  logic [LineBits-1:0]   line_q;        // line being filled, 0..height
  // line_q == height_i as a register (a_last), set at the swap that moves line_q onto the
  // height: compares of line_q with the frame's height would be in front of the insertion's
  // enables (take_new) and the swap (height_q -> cnt_fill_q: a long path in the sized Gouraud
  // top). line_q only counts up to the height (a_line_le), so line_q < height_i is !last_q.
  logic                  last_q;
  logic [CountBits-1:0]  rd_q, rd_d;
  logic                  out_done_q, inc_done_q, eol_sent_q;
  logic [EdgeIdBits-1:0] id_q;
  // The sorted insertion's pipeline (below).
  logic [KeyBits+IndexBits-1:0] key1_q, key2_q, key3_q;  // {sort key, body index} in ord1 / ord2
                                                         // / ord3
  logic                         ord1_q, ord2_q, ord3_q;
  logic [Entries-1:0]           valid_q;  // entry i of order_q exists (a thermometer: i < its
                                          // entries)
  logic [KeyBits-1:0]           key1_inv_q, key1_free_q, key1_free_inv_q;  // copies of key1_q's
                                                                           // key (below)
  logic [Entries-1:0]           lt_q;     // ord2: entry i of order_q as ord1 saw it sorts before
                                          // key2_q
  logic                         k2_lt_q, k3_lt_q;  // ord2: the keys then in ord2 / ord3 sort
                                                   // before key2_q
  logic [Entries-1:0]           below_q;  // ord3: entry i of order_q sorts before key3_q

  // ------------------------------------------------------------ stream out line line_q - 1
  logic   streaming, have_edge, out_fire, inc_valid, inc_ready, inc_fire, advance;
  // streaming and have_edge as registers (their compares of line_q and of rd_q with the count
  // would be in front of advance, whose fan-out is the index list's, rd_q's and out_q's enables):
  // streaming_q = frame_q && !drain_q && line_q != 0, have_edge_q = streaming_q && rd_q <
  // cnt_stream_q (a_streaming, a_have_edge).
  logic   streaming_q, have_edge_q;
  entry_t out_q;  // the entry at rd_q of the streaming bank (a fabric register)
  entry_t ram_q;  // the RAM's read register: the entry at rd_q + 1 (past the count: don't care)
  logic   pre;    // the stream is done (or not begun): the RAM reads the filling bank's head

  assign streaming = streaming_q;
  assign have_edge = have_edge_q;

  assign out_valid_o = (have_edge && !out_done_q) || (streaming && !have_edge && !eol_sent_q);
  assign out_eol_o   = !have_edge;
  assign out_poly_o  = out_q.poly;
  assign out_material_o = out_q.material;
  assign out_value_o = out_q.value;
  assign out_fire    = out_valid_o && out_ready_i;

  // Fork to the segment former and the incrementer: each side takes the edge once.
  assign inc_valid = have_edge && !inc_done_q;
  assign inc_fire  = inc_valid && inc_ready;
  assign advance   = have_edge && (out_done_q || out_fire) && (inc_done_q || inc_fire);

  // ------------------------------------------------------------ step to the next line
  // The incrementer takes out_q, a fabric register (the RAM's clock-to-out, a large part of the
  // clock on the ECP5, leaves no room for its adders in the same clock), and is always ready
  // (its ready_i is high).
  logic                   st_valid, st_retire;
  logic [VectorBits-1:0]  st_value;
  logic [SlopeBits-1:0]   st_slope;
  logic [LineBits-1:0]    st_remaining;
  logic [PayloadBits-1:0] st_payload;

  edge_incrementer #(
    .XBits      (XBits),
    .ZBits      (ZBits),
    .AttrBits   (AttrBits),
    .PayloadBits(PayloadBits),
    .EdgeOrder  (EdgeOrder)
  ) u_inc (
    .clk_i, .rst_ni,
    .value_i    (out_q.value),
    .slope_i    (out_q.slope),
    .remaining_i(out_q.remaining),
    .payload_i  ({out_q.id, out_q.poly, out_q.material}),
    .valid_i    (inc_valid),
    .ready_o    (inc_ready),
    .value_o    (st_value),
    .slope_o    (st_slope),
    .remaining_o(st_remaining),
    .retire_o   (st_retire),
    .payload_o  (st_payload),
    .valid_o    (st_valid),
    .ready_i    (1'b1)          // an insertion is always possible (or an overflow)
  );


  // ------------------------------------------------------------ insertion into the other bank
  logic   nsel, ins_step, take_new, drop_late, ins_valid, ins_write, src_done, swap, next_line;
  logic               swap_now, swap_q, next_line_q;
  logic [KeyBits-1:0] ins_key;
  logic               head_edge;

  assign nsel      = !sel_q;
  assign head_edge = edge_valid_i && !edge_eof_i;
  assign ins_step  = st_valid && !st_retire;
  assign take_new  = frame_q && !drain_q && head_edge && !last_q
                     && (rec.y0 == line_q) && !ins_step;
  // A record behind the line being filled (unsorted stream) cannot be placed: skip it.
  assign drop_late = frame_q && !drain_q && head_edge && (rec.y0 < line_q);
  assign edge_ready_o = take_new || drop_late || (drain_q && edge_valid_i);
  assign ins_valid = ins_step || take_new;
  assign ins_write = ins_valid && (cnt_fill_q != CountBits'(Entries));

  // The inserted entry (entry_t's layout: {remaining, id, poly, material, value, slope}): the
  // stepped edge, else the new record. Assembled inside the RAM write below, only its key is a
  // signal: the same multiplexer, but a simulator then builds the wide body only on the clocks
  // that insert, not on every evaluation of the input-driven logic.
  assign ins_key = ins_step
      ? {st_value[XLow +: XBits] ^ XSign, st_payload[PayloadBits-1 -: EdgeIdBits]}
      : {rec.value[XLow +: XBits] ^ XSign, id_q};

  // Line line_q is complete when line_q - 1 has streamed out (marker sent), its stepped edges
  // are in, and the input holds no more records for line_q.
  assign src_done = last_q
                 || (edge_valid_i && (edge_eof_i || rec.y0 > line_q));
  // The swap is decided a clock before it acts (swap_q, next_line_q: the compares with line_q
  // and the input's y0 are then not in front of the swap's fan-out). The condition holds until
  // then: the stream has sent its marker, nothing is being stepped or inserted, and the input's
  // head (held, as it is not taken) still belongs to a later line.
  assign swap_now = frame_q && !drain_q && pre && !st_valid && !ord1_q && !ord2_q && !ord3_q
                    && src_done && !swap_q;
  assign swap = swap_q;
  assign next_line = next_line_q;  // the filling bank starts to stream

  // The stream reads one entry ahead of out_q. While it streams, the RAM reads the entry after
  // the next clock's out_q: rd_q + 2 on an advance (out_q takes the read register's rd_q + 1),
  // else rd_q + 1 again. Once the line has sent its marker (pre, registered), the RAM reads the
  // filling bank's head instead: the first entry on every clock, so on the clock the swap is
  // decided (no insertion pending then: order_q is final) it reads the new line's first entry,
  // which out_q takes on the swap; the swap's clock reads the second. So the first edge of a
  // line is presented on the clock after the swap, the same cycle as a RAM read straight onto
  // the outputs. (Reset and frame start need no case: nothing streams before the frame's first
  // swap.) Only the index read is combinational; the index list itself is updated in its
  // register's always_ff, so a simulator neither copies nor shifts the Entries-long list on
  // every evaluation.
  logic [IndexBits-1:0] sidx1, sidx2, order1;  // g_sidx[1], g_sidx[2], order_q[1] (zero past the
                                               // list)
  if (Entries > 1) begin : g_one
    assign sidx1  = g_sidx[1].q;
    assign order1 = order_q[1][IndexBits-1:0];
  end else begin : g_no_one
    assign sidx1  = '0;
    assign order1 = '0;
  end
  if (Entries > 2) begin : g_two
    assign sidx2 = g_sidx[2].q;
  end else begin : g_no_two
    assign sidx2 = '0;
  end
  assign pre = !streaming_q || eol_sent_q;  // in a live frame: line_q == 0 or the marker sent
  always_comb begin
    sel_d = sel_q;
    rd_d  = rd_q;
    if (next_line) begin
      sel_d = nsel;
      rd_d  = '0;
    end else if (advance) begin
      rd_d  = rd_q + 1'b1;
    end
    if (pre) rd_head = swap_q ? order1 : order_q[0][IndexBits-1:0];
    else     rd_head = advance ? sidx2 : sidx1;
  end

  // A read whose word reaches out_q never meets a write: while the stream is on (!pre) reads go
  // to the streaming half (sel_q), writes to the filling half (!sel_q). With pre, reads go to
  // the filling half too, and may meet an insertion's write; but the reads out_q takes are the
  // ones on the clock the swap is decided (swap_now) and on the swap's own clock (swap_q), and
  // neither inserts (a_no_insert_on_swap: the swap waits for the incrementer to be empty,
  // !st_valid, and for the input to hold no record of line_q, which take_new needs). An entry
  // written on the clock before is in the RAM when that read happens. So the read port needs
  // neither read-first nor write-first behaviour, and no forwarding.
  logic [BodyAddressBits-1:0] rd_addr, wr_addr;
  assign rd_addr = {sel_q ^ pre, rd_head};
  assign wr_addr = {nsel, IndexBits'(cnt_fill_q)};

  always_ff @(posedge clk_i) begin
    if (ins_write)
      body_mem[wr_addr] <= ins_step
          ? {st_remaining, st_payload, st_value, st_slope}
          : {rec.n, id_q, rec.poly, rec.material, rec.value, rec.slope};
  end
  always_ff @(posedge clk_i) begin
    ram_q <= body_mem[rd_addr];
  end
  // out_q takes the read register only: the RAM's clock-to-out ends here, behind the enable.
  always_ff @(posedge clk_i) begin
    if (advance || swap_q) out_q <= ram_q;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni || (start_i && !frame_q)) begin
      // Reset and frame start clear the same per-frame state; only reset also clears the bank
      // select and the sticky overflow flag, and a frame start leaves frame_q set.
      frame_q      <= rst_ni;
      drain_q      <= 1'b0;
      line_q       <= '0;
      last_q       <= 1'b0;  // height_i >= 1 (the top's a_frame_size)
      rd_q         <= '0;
      cnt_stream_q <= '0;
      cnt_fill_q   <= '0;
      out_done_q   <= 1'b0;
      inc_done_q   <= 1'b0;
      eol_sent_q   <= 1'b0;
      id_q         <= '0;
      swap_q       <= 1'b0;
      next_line_q  <= 1'b0;
      streaming_q  <= 1'b0;
      have_edge_q  <= 1'b0;
      if (!rst_ni) begin
        sel_q      <= 1'b0;
        overflow_o <= 1'b0;
      end
    end else begin
      sel_q  <= sel_d;
      rd_q   <= rd_d;
      swap_q      <= swap_now;
      next_line_q <= swap_now && !last_q;
      if (advance) begin
        out_done_q <= 1'b0;
        inc_done_q <= 1'b0;
      end else begin
        if (out_fire && have_edge) out_done_q <= 1'b1;
        if (inc_fire) inc_done_q <= 1'b1;
      end
      if (out_fire && !have_edge) eol_sent_q <= 1'b1;
      if (edge_valid_i && edge_ready_o && !edge_eof_i) id_q <= id_q + 1'b1;
      if (ins_valid) begin
        if (!ins_write) overflow_o <= 1'b1;
        else cnt_fill_q <= cnt_fill_q + 1'b1;
      end
      // The stream's last edge leaves; a swap (no edge streams then) starts the next line, whose
      // count is the filling bank's, or the drain.
      if (advance && rd_q + 1'b1 == cnt_stream_q) have_edge_q <= 1'b0;
      if (swap) begin
        streaming_q <= next_line;
        have_edge_q <= next_line && (cnt_fill_q != '0);
        if (!next_line) begin
          drain_q <= 1'b1;  // read the rest of the stream up to its EOF beat
        end else begin
          cnt_stream_q <= cnt_fill_q;
          cnt_fill_q   <= '0;
          line_q       <= line_q + 1'b1;
          last_q       <= (line_q + 1'b1 == height_i);
          eol_sent_q   <= 1'b0;
        end
      end
      if (drain_q && edge_valid_i && edge_eof_i) begin
        frame_q <= 1'b0;
        drain_q <= 1'b0;
      end
    end
  end

  // The streaming bank's index list, one variable per entry (a simulator then neither copies nor
  // shifts a packed Entries-long list on every clock): entry i is the body index of the entry at
  // rd_q + i; the swap loads the filling bank's order, each advance moves the list down by one.
  for (genvar i = 0; i < Entries; i++) begin : g_sidx
    logic [IndexBits-1:0] q;
    logic [IndexBits-1:0] next;  // what it takes when the stream advances
    if (i + 1 < Entries) begin : g_shift
      assign next = g_sidx[i+1].q;
    end else begin : g_last
      assign next = '0;
    end
    always_ff @(posedge clk_i) begin
      if (next_line) q <= order_q[i][IndexBits-1:0];
      else if (advance) q <= next;
    end
  end

  // Sorted insertion of the key and the body's index, pipelined over three clocks after the
  // insertion is accepted (its body is written then, at index cnt_fill_q), so that no clock holds
  // the key's multiplexer, a KeyBits-bit compare, the correction for the keys in flight or the
  // shift together; still one insertion per clock:
  //   ord1: the key is registered (key1_q);
  //   ord2: every entry's "sorts before key1_q" flag against order_q as it is in that clock (lt_q,
  //         no entry past order_q's count: valid_q), and whether each key then in ord2 and ord3
  //         (not yet in order_q) sorts before it (k2_lt_q, k3_lt_q);
  //   ord3: the flags for order_q as it will be after those two insertions (below_q);
  //   then: entries before the new one stay, the one at its place takes it, the tail moves up.
  // A swap waits until the three stages are empty (the stream reads order_q's indices), so a line
  // that inserts takes three cycles more than it would with the insertion in one clock.
  // The correction is a shift: order_q is sorted and keys are unique ((X, id): "not before" means
  // after), so lt_q is a thermometer (entries 0 .. L-1 before the key), and the s keys in flight
  // that sort before it land among those: the key's place is L + s, below_q[i] = (i < L + s) =
  // (i < s) || lt_q[i - s]. (The compare and this correction in one clock, order_q -> compare ->
  // below_q, would limit the Phong top and the block alone.)

  // key1's key reaches Entries comparators; four copies, each for a quarter of the entries,
  // shorten that net (on the ECP5 its routing is a large part of the clock). The copies differ in
  // structure (loaded on insertion or on every clock, true or inverted), or yosys merges them
  // back into one: a free-running copy holds the key on the clocks ord1 is set, as the others do;
  // an inverted copy compares the other way round (k < K is ~K < ~k).
  localparam int unsigned Quarter = (Entries + 3) / 4;
  function automatic logic entry_before_key1(input logic [KeyBits-1:0] key, input int unsigned i);
    case (i / Quarter)
      0:       entry_before_key1 = key < key1_q[IndexBits +: KeyBits];
      1:       entry_before_key1 = key1_inv_q < ~key;
      2:       entry_before_key1 = key < key1_free_q;
      default: entry_before_key1 = key1_free_inv_q < ~key;
    endcase
  endfunction

  // Each flag in its own block (a generate loop, not a procedural loop: Verilator 5.006 does not
  // unroll a loop of more than 64 iterations, and its non-blocking writes to the vector inside
  // such a loop go wrong beyond that: the curved-edge top has 68 entries), compared only on the
  // clocks ord1 holds a key (a simulator skips the Entries comparators otherwise).
  for (genvar i = 0; i < Entries; i++) begin : g_lt
    always_ff @(posedge clk_i) begin
      if (ord1_q) lt_q[i] <= valid_q[i] && entry_before_key1(order_q[i][IndexBits +: KeyBits], i);
    end
  end
  always_ff @(posedge clk_i) begin
    if (ord1_q) begin
      k2_lt_q <= ord2_q && key2_q[IndexBits +: KeyBits] < key1_q[IndexBits +: KeyBits];
      k3_lt_q <= ord3_q && key3_q[IndexBits +: KeyBits] < key1_q[IndexBits +: KeyBits];
    end
  end
  // below_q[i] = lt_q[i - s] with s = k2_lt_q + k3_lt_q, and 1 below s.
  for (genvar i = 0; i < Entries; i++) begin : g_below
    logic lt1, lt2;  // lt_q[i - 1], lt_q[i - 2]; 1 below entry 0 (every key in flight is before)
    if (i >= 1) begin : g_lt1
      assign lt1 = lt_q[(i >= 1) ? i - 1 : 0];
    end else begin : g_lt1_none
      assign lt1 = 1'b1;
    end
    if (i >= 2) begin : g_lt2
      assign lt2 = lt_q[(i >= 2) ? i - 2 : 0];
    end else begin : g_lt2_none
      assign lt2 = 1'b1;
    end
    always_ff @(posedge clk_i) begin
      if (ord2_q) begin
        unique case ({k3_lt_q, k2_lt_q})
          2'b00:   below_q[i] <= lt_q[i];
          2'b11:   below_q[i] <= lt2;
          default: below_q[i] <= lt1;
        endcase
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (ins_write) begin
      key1_q     <= {ins_key, IndexBits'(cnt_fill_q)};
      key1_inv_q <= ~ins_key;
    end
    key1_free_q     <= ins_key;
    key1_free_inv_q <= ~ins_key;
    if (ord1_q) key2_q <= key1_q;
    if (ord2_q) key3_q <= key2_q;
  end
  always_ff @(posedge clk_i) begin
    if (!rst_ni || (start_i && !frame_q)) begin
      ord1_q <= 1'b0;
      ord2_q <= 1'b0;
      ord3_q <= 1'b0;
    end else begin
      ord1_q <= ins_write;
      ord2_q <= ord1_q;
      ord3_q <= ord2_q;
    end
  end
  // order_q's entries: one more with each insertion, none after the swap (which the filling
  // bank's count restarts at; no insertion is in flight then).
  for (genvar i = 0; i < Entries; i++) begin : g_valid
    always_ff @(posedge clk_i) begin
      if (!rst_ni || (start_i && !frame_q) || next_line) valid_q[i] <= 1'b0;
      else if (ord3_q) valid_q[i] <= (i == 0) || valid_q[(i == 0) ? 0 : i - 1];
    end
  end

  // Each entry is assigned in its own block from its own and its lower neighbour's old value, no
  // loop writes the array: so the simulator unrolls nothing (Verilator's BLKLOOPINIT at any
  // size). (One array rather than a variable per entry: Verilator keeps a pending-write flag per
  // written element of an array, but copies a separate variable in and out of a shadow on every
  // clock, about twice the instructions.)
  // The enable tested on its own (if (ord3_q) if (...)), not in one condition with the entry's
  // flag: a simulator merges the Entries blocks' identical tests into one and skips them all on
  // the clocks without an insertion (as g_lt's; in one condition, about 10 instructions a clock
  // for each entry).
  for (genvar i = 0; i < Entries; i++) begin : g_order
    if (i > 0) begin : g_above
      always_ff @(posedge clk_i) begin
        if (ord3_q) begin
          if (!below_q[i]) order_q[i] <= below_q[i-1] ? key3_q : order_q[i-1];
        end
      end
    end else begin : g_bottom
      always_ff @(posedge clk_i) begin
        if (ord3_q) begin
          if (!below_q[0]) order_q[0] <= key3_q;
        end
      end
    end
  end

  assign busy_o = frame_q;

  `WATKINS_ASSERT_HOLD(a_in_hold, edge_valid_i, edge_ready_o, {edge_i, edge_eof_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, out_valid_o, out_ready_i, {out_poly_o, out_material_o,
    out_value_o, out_eol_o})
  `WATKINS_ASSERT(a_no_insert_on_swap, (swap || swap_now) |-> !ins_valid)
  // Reads that reach out_q: every read while streaming, the reads on swap_now and swap.
  `WATKINS_ASSERT(a_no_ram_collision,
    (ins_write && rd_addr == wr_addr) |-> (pre && !swap_now && !swap))
  // The read ahead: out_q holds the entry at rd_q, the RAM's read register the one after it.
`ifdef WATKINS_ASSERT_ON
  logic [BodyAddressBits-1:0] chk_out_addr, chk_ram_addr;
  logic [BodyBits-1:0] chk_out_word, chk_ram_word;
  assign chk_out_addr = {sel_q, g_sidx[0].q};
  assign chk_ram_addr = {sel_q, sidx1};
  assign chk_out_word = body_mem[chk_out_addr];
  assign chk_ram_word = body_mem[chk_ram_addr];
`endif
  `WATKINS_ASSERT(a_last, frame_q |-> last_q == (line_q == height_i))
  `WATKINS_ASSERT(a_line_le, frame_q |-> line_q <= height_i)
  `WATKINS_ASSERT(a_streaming, streaming_q == (frame_q && !drain_q && (line_q != '0)))
  `WATKINS_ASSERT(a_have_edge, have_edge_q == (streaming_q && (rd_q < cnt_stream_q)))
  `WATKINS_ASSERT(a_out_entry, have_edge |-> (out_q == chk_out_word))
  `WATKINS_ASSERT(a_ram_entry,
    (have_edge && !pre && rd_q + 1'b1 < cnt_stream_q) |-> (ram_q == chk_ram_word))
  // The order pipeline's keys carry consecutive body indices, and valid_q counts order_q's
  // entries: the filling bank's count less the keys in flight.
  `WATKINS_ASSERT(a_order_index,
    ord1_q |-> (CountBits'(key1_q[IndexBits-1:0]) == cnt_fill_q - CountBits'(1)))
  `WATKINS_ASSERT(a_order_index2,
    (ord1_q && ord2_q) |-> (key1_q[IndexBits-1:0] == key2_q[IndexBits-1:0] + IndexBits'(1)))
  `WATKINS_ASSERT(a_order_index3,
    (ord2_q && ord3_q) |-> (key2_q[IndexBits-1:0] == key3_q[IndexBits-1:0] + IndexBits'(1)))
  `WATKINS_ASSERT(a_valid_count, (frame_q && !drain_q) |->
    ($countones(valid_q) == 32'(cnt_fill_q) - 32'(ord1_q) - 32'(ord2_q) - 32'(ord3_q)))
  `WATKINS_ASSERT(a_valid_thermometer, ((valid_q + 1'b1) & valid_q) == '0)
  // The shift's flags are a thermometer ending at the new key's index in the order.
  `WATKINS_ASSERT(a_below, ord3_q |-> (((below_q + 1'b1) & below_q) == '0
    && $countones(below_q) <= $countones(valid_q)))
  `WATKINS_COVER(c_overflow, $rose(overflow_o))
  `WATKINS_COVER(c_new_and_stepped, ins_step && frame_q && head_edge && rec.y0 == line_q)
endmodule

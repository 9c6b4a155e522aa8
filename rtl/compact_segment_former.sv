// compact_segment_former: segment_former's pairing of the X-ordered active edges of one scan line
// into segments per polygon, with the open table in block RAM indexed by polygon id, for small
// parts. Drop-in for rtl/segment_former.sv (the same ports, parameters and streams; values twin:
// model/twins/segment_former.cpp; cycle twin: model/twins/compact_segment_former_timing.hpp).
// The first edge of a polygon opens a segment, the next edge of the same polygon closes it;
// segments leave in closing order, the end-of-line marker follows them and clears the table (an
// edge left open draws nothing). A segment's material is its closing edge's.
// The table: one word per polygon id, {open, line tag, the opening edge's channel vector}, in a RAM
// with a synchronous read (EBR). An entry is open when its open bit is set and its tag is the
// current line's (line_q, counted modulo 2^PolyIdBits over every line since reset), so the
// marker's clear is the tag's increment. An entry left open by a line keeps its old tag; so that
// it is never taken for open when line_q comes round to that tag again, each marker also clears
// entry line_q (the table's every entry once in 2^PolyIdBits lines, before its tag can recur).
// Timing (cycle twin): after reset the block clears the table, one entry per clock, 2^PolyIdBits
// clocks with edge_ready_o low. Then two clocks per edge: the accept clock reads the edge's entry,
// the next clock (decide) pairs it and writes the entry; the segment or the marker is offered from
// the clock after that. An edge is taken when the block is not deciding and the output is empty
// or taken in that clock: edge_ready_o = !clear && !deciding && (!seg_valid_o || seg_ready_i).
// Latency 2 cycles: a segment or marker is offered two clocks after its edge is taken. At full
// rate an edge every other clock (0.5 edges per clock).
// Registered: every output (seg_e_o is the RAM's read register, the rest the edge's input
// register, held until the output is taken). edge_ready_o is combinational from registers and
// seg_ready_i.
`include "watkins_assert.svh"

module compact_segment_former #(
  /* verilator lint_off UNUSEDPARAM */
  parameter int unsigned MaxActiveEdges = watkins_pkg::MaxActiveEdges,  // unused: the table holds
                                                                        // every polygon id
  /* verilator lint_on UNUSEDPARAM */
  parameter int unsigned VectorBits     = watkins_pkg::NumChannels * watkins_pkg::ChannelBits,  // channel vector
  parameter int unsigned PolyIdBits     = watkins_pkg::PolyIdBits,
  parameter int unsigned MaterialIdBits = watkins_pkg::MaterialIdBits
) (
  input  logic                      clk_i,
  input  logic                      rst_ni,
  input  logic [PolyIdBits-1:0]     edge_poly_i,     // polygon of the edge
  input  logic [MaterialIdBits-1:0] edge_material_i, // its material
  input  logic [VectorBits-1:0]     edge_value_i,    // channels on this line
  input  logic                      edge_eol_i,      // end-of-line marker
  input  logic                      edge_valid_i,
  output logic                      edge_ready_o,
  output logic [VectorBits-1:0]     seg_e_o,         // opening edge
  output logic [VectorBits-1:0]     seg_f_o,         // closing edge
  output logic [PolyIdBits-1:0]     seg_poly_o,
  output logic [MaterialIdBits-1:0] seg_material_o,  // the closing edge's
  output logic                      seg_eol_o,
  output logic                      seg_valid_o,
  input  logic                      seg_ready_i
);
  localparam int unsigned Entries  = 1 << PolyIdBits;
  localparam int unsigned WordBits = 1 + PolyIdBits + VectorBits;  // {open, tag, value}

  logic [WordBits-1:0]   table_mem [Entries];
  logic [WordBits-1:0]   rd_q;       // the accepted edge's entry (the RAM's read register)
  logic                  clear_q;    // the clear after reset runs (line_q is its entry)
  logic                  decide_q;   // the accepted edge is paired in this clock
  logic [PolyIdBits-1:0] line_q;     // the line's tag

  logic take, opens, closes, we;
  logic [PolyIdBits-1:0] wa;
  logic [WordBits-1:0]   wd;

  assign edge_ready_o = !clear_q && !decide_q && (!seg_valid_o || seg_ready_i);
  assign take         = edge_valid_i && edge_ready_o;
  // The accepted edge's polygon has an edge open on this line.
  assign opens  = decide_q && !seg_eol_o && !closes;
  assign closes = decide_q && !seg_eol_o && rd_q[WordBits-1]
               && rd_q[WordBits-2:VectorBits] == line_q;

  // One write per clock: the clear after reset, the decided edge's entry (opened: its tag and
  // value; closed: the open bit cleared), or the marker's clear of entry line_q.
  assign we = clear_q || decide_q;
  assign wa = (clear_q || seg_eol_o) ? line_q : seg_poly_o;
  assign wd = {opens, line_q, seg_f_o};

  always_ff @(posedge clk_i) begin
    if (take) rd_q <= table_mem[edge_poly_i];
    if (we) table_mem[wa] <= wd;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      clear_q     <= 1'b1;
      decide_q    <= 1'b0;
      line_q      <= '0;
      seg_valid_o <= 1'b0;
    end else begin
      if (clear_q && line_q == PolyIdBits'(Entries - 1)) clear_q <= 1'b0;
      if (clear_q) line_q <= line_q + 1'b1;
      decide_q <= take;
      if (seg_ready_i) seg_valid_o <= 1'b0;
      if (decide_q) begin
        seg_valid_o <= seg_eol_o || closes;
        if (seg_eol_o) line_q <= line_q + 1'b1;
      end
    end
  end

  // The edge's register is the output: it holds until the segment is taken (no edge is taken
  // before), and the opening edge's value stays in the RAM's read register (no read before).
  always_ff @(posedge clk_i) begin
    if (take) begin
      seg_f_o        <= edge_value_i;
      seg_poly_o     <= edge_poly_i;
      seg_material_o <= edge_material_i;
      seg_eol_o      <= edge_eol_i;
    end
  end
  assign seg_e_o = rd_q[VectorBits-1:0];

  `WATKINS_ASSERT_HOLD(a_in_hold, edge_valid_i, edge_ready_o, {edge_poly_i, edge_material_i,
    edge_value_i, edge_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, seg_valid_o, seg_ready_i, {seg_e_o, seg_f_o, seg_poly_o,
    seg_material_o, seg_eol_o})
  `WATKINS_ASSERT(a_decide_empty, decide_q |-> !seg_valid_o)
  `WATKINS_COVER(c_opens, opens)
  `WATKINS_COVER(c_closes, closes)
endmodule

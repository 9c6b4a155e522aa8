// segment_former: pairs the X-ordered active edges of one scan line into segments per polygon
// (model/twins/segment_former.cpp): the first edge of a polygon opens a segment, the next edge of the
// same polygon closes it; segments leave in closing order, the end-of-line marker follows them
// and clears the table (an edge left open draws nothing). A segment's material is its closing
// edge's (both edges belong to one polygon, so one material).
// Latency 1: output registered; ready_o = ready_i || !valid_o (combinational).
// The open table has MaxActiveEdges entries, so it cannot fill: a line carries at most that
// many edges, so an edge that opens a segment takes the next entry never used on this line (a
// counter, no search for a free one), and the closing edge's entry index is the OR of the
// matching entries' indices (one matches at most: no priority search). The channel vector passes through
// untouched, so only its width matters here.
`include "watkins_assert.svh"

module segment_former #(
  parameter int unsigned MaxActiveEdges = watkins_pkg::MaxActiveEdges,
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
  localparam int unsigned N  = MaxActiveEdges;
  localparam int unsigned IB = (N > 1) ? $clog2(N) : 1;
  localparam int unsigned CntB = $clog2(N + 1);
  typedef logic [VectorBits-1:0] chans_t;

  logic [N-1:0]          open_q;       // entry holds an unpaired edge
  logic [PolyIdBits-1:0] open_poly_q [N];
  chans_t                            open_value_q [N];
  logic [CntB-1:0]       used_q;       // entries taken on this line (0 .. N), cleared by the marker

  logic          fire, has_free;
  logic [IB-1:0] free_idx;

  assign edge_ready_o = seg_ready_i || !seg_valid_o;
  assign fire         = edge_valid_i && edge_ready_o;

  // The open entries of polygon `poly` (one-hot: polygon ids are unique among open entries) and
  // the entry's index, the OR of the matching entries' indices (0 when none matches). Functions
  // called inside the `if (fire)` of the registers they feed, not kept as signals: the same
  // comparators in hardware (the calls share them), but a simulator then searches only on the
  // clocks that take an edge, not on every evaluation.
  function automatic logic [N-1:0] open_match(input logic [PolyIdBits-1:0] poly);
    for (int i = 0; i < N; i++) open_match[i] = open_q[i] && open_poly_q[i] == poly;
  endfunction
  function automatic logic [IB-1:0] open_index(input logic [PolyIdBits-1:0] poly);
    logic [N-1:0] match;
    match = open_match(poly);
    open_index = '0;
    for (int i = 0; i < N; i++) open_index = open_index | (IB'(i) & {IB{match[i]}});
  endfunction
  assign has_free = used_q != CntB'(N);
  assign free_idx = IB'(used_q);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      open_q      <= '0;
      used_q      <= '0;
      seg_valid_o <= 1'b0;
    end else begin
      // seg_valid_o <= fire && (edge_eol_i || open_match(edge_poly_i) != '0) whenever edge_ready_o.
      if (edge_ready_o) seg_valid_o <= 1'b0;
      if (fire) begin
        if (edge_eol_i) begin
          seg_valid_o <= 1'b1;
          open_q <= '0;
          used_q <= '0;
        end else if (open_match(edge_poly_i) != '0) begin
          seg_valid_o <= 1'b1;
          open_q <= open_q & ~open_match(edge_poly_i);
        end else if (has_free) begin
          open_q[free_idx] <= 1'b1;
          used_q <= used_q + 1'b1;
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (fire) begin
      if (!edge_eol_i && open_match(edge_poly_i) == '0 && has_free) begin
        open_poly_q[free_idx]  <= edge_poly_i;
        open_value_q[free_idx] <= edge_value_i;
      end
      if (edge_eol_i || open_match(edge_poly_i) != '0) begin
        seg_e_o    <= open_value_q[open_index(edge_poly_i)];
        seg_f_o    <= edge_value_i;
        seg_poly_o <= edge_poly_i;
        seg_material_o <= edge_material_i;
        seg_eol_o  <= edge_eol_i;
      end
    end
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, edge_valid_i, edge_ready_o, {edge_poly_i, edge_material_i,
    edge_value_i, edge_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, seg_valid_o, seg_ready_i, {seg_e_o, seg_f_o, seg_poly_o,
    seg_material_o, seg_eol_o})
  `WATKINS_ASSERT(a_table_room, fire && !edge_eol_i && open_match(edge_poly_i) == '0 |-> has_free)
  `WATKINS_COVER(c_two_open, $countones(open_q) >= 2)
endmodule

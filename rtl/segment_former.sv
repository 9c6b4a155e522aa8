// segment_former: pairs the X-ordered active edges of one scan line into segments per polygon
// (model/twins/segment_former.cpp): the first edge of a polygon opens a segment, the next edge of the
// same polygon closes it; segments leave in closing order, the end-of-line marker follows them
// and clears the table (an edge left open draws nothing). A segment's material is its closing
// edge's (both edges belong to one polygon, so one material).
// Latency 2: an input register, then the output register; both register valid and data;
// edge_ready_o = !in_valid_q || seg_ready_i || !seg_valid_o (combinational). The input register
// keeps, beside the edge, which table entries hold its polygon (one comparator per entry, on the
// edge as it arrives): so neither the active-edge list's RAM read nor the comparators sit on the
// path that pairs the edge and updates the table. The table an arriving edge is compared with is
// the one the edge in the input register leaves behind: that edge writes its polygon into the
// entry used_q (always, whether it opens or not: only an open entry is ever matched), so for that
// entry the comparison is with the registered edge's polygon instead.
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

  // The input register: the edge and which entries hold its polygon when it is paired.
  logic                      in_valid_q, in_eol_q;
  logic [PolyIdBits-1:0]     in_poly_q;
  logic [MaterialIdBits-1:0] in_material_q;
  chans_t                    in_value_q;
  logic [N-1:0]              in_same_q;

  logic          out_en, pair, has_free;
  logic [N-1:0]  match;
  logic [IB-1:0] free_idx;

  assign out_en       = seg_ready_i || !seg_valid_o;
  assign pair         = in_valid_q && out_en;    // the registered edge is paired this clock
  assign edge_ready_o = out_en || !in_valid_q;
  assign match        = in_same_q & open_q;      // its open entry (one-hot or none)
  assign has_free = used_q != CntB'(N);
  assign free_idx = IB'(used_q);

  // Which entries hold `poly` once the registered edge is paired: entry used_q takes the
  // registered edge's polygon. Entries past the line's used ones compare with stale polygons,
  // but they are not open, and `match` masks them. A function called inside the input
  // register's `if`, not kept as a signal: the same comparators in hardware, but a simulator
  // compares only on the clocks that take an edge.
  function automatic logic [N-1:0] holds(input logic [PolyIdBits-1:0] poly);
    for (int i = 0; i < N; i++)
      holds[i] = (CntB'(i) == used_q) ? (in_poly_q == poly) : (open_poly_q[i] == poly);
  endfunction
  // The matching entry's index, the OR of the matching entries' indices (0 when none matches).
  function automatic logic [IB-1:0] match_index(input logic [N-1:0] m);
    match_index = '0;
    for (int i = 0; i < N; i++) match_index = match_index | (IB'(i) & {IB{m[i]}});
  endfunction

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_valid_q  <= 1'b0;
      open_q      <= '0;
      used_q      <= '0;
      seg_valid_o <= 1'b0;
    end else begin
      if (edge_ready_o) in_valid_q <= edge_valid_i;
      if (out_en) seg_valid_o <= pair && (in_eol_q || match != '0);
      if (pair) begin
        if (in_eol_q) begin
          open_q <= '0;
          used_q <= '0;
        end else if (match != '0) begin
          open_q <= open_q & ~match;
        end else if (has_free) begin
          open_q[free_idx] <= 1'b1;
          used_q <= used_q + 1'b1;
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (edge_valid_i && edge_ready_o) begin
      in_poly_q     <= edge_poly_i;
      in_material_q <= edge_material_i;
      in_value_q    <= edge_value_i;
      in_eol_q      <= edge_eol_i;
      in_same_q     <= holds(edge_poly_i);
    end
  end

  always_ff @(posedge clk_i) begin
    if (pair) begin
      // Written whether the edge opens or not (an entry past the open ones): the write enable
      // waits for no comparison.
      if (!in_eol_q && has_free) begin
        open_poly_q[free_idx]  <= in_poly_q;
        open_value_q[free_idx] <= in_value_q;
      end
      if (in_eol_q || match != '0) begin
        seg_e_o    <= open_value_q[match_index(match)];
        seg_f_o    <= in_value_q;
        seg_poly_o <= in_poly_q;
        seg_material_o <= in_material_q;
        seg_eol_o  <= in_eol_q;
      end
    end
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, edge_valid_i, edge_ready_o, {edge_poly_i, edge_material_i,
    edge_value_i, edge_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, seg_valid_o, seg_ready_i, {seg_e_o, seg_f_o, seg_poly_o,
    seg_material_o, seg_eol_o})
  `WATKINS_ASSERT(a_table_room, pair && !in_eol_q && match == '0 |-> has_free)
`ifdef WATKINS_ASSERT_ON
  // The entries found on arrival are those a search at pairing time would find.
  function automatic logic [N-1:0] open_now(input logic [PolyIdBits-1:0] poly);
    for (int i = 0; i < N; i++) open_now[i] = open_q[i] && open_poly_q[i] == poly;
  endfunction
  `WATKINS_ASSERT(a_match_forwarded, pair && !in_eol_q |-> match == open_now(in_poly_q))
`endif
  `WATKINS_COVER(c_two_open, $countones(open_q) >= 2)
endmodule

// segment_former: pairs the X-ordered active edges of one scan line into segments, per polygon.
// Twin: model/twins/segment_former.cpp. The first edge of a polygon opens a segment, the next
// edge of the same polygon closes it; segments leave in closing order, the end-of-line marker
// follows them and clears the table (an edge left open draws nothing). A segment's material is
// its closing edge's (both edges belong to one polygon, so one material).
// Latency 3 cycles: an input register, a pairing register, then the output register; each
// registers valid and data, and all three move on one enable: edge_ready_o = seg_ready_i ||
// !seg_valid_o (combinational; a bubble inside is not squeezed out while the output is stalled).
// Stages: in (in_*_q) -> pr (pr_*_q) -> seg (seg_*_o).
// Each step keeps its clock short (the target: 125 MHz on the ECP5):
// - in: the edge and which table entries hold its polygon (one comparator per entry) and whether
//   it has the polygon of the edge ahead of it. The table it is compared with is the one the
//   edge in the pairing register leaves behind (that edge pairs on this clock and writes its
//   polygon into entry used_q), so for that entry the comparison is with the pairing register's
//   polygon instead; the edge now in the input register, one ahead, has no entry yet: its effect
//   is forwarded a step later through the same-polygon flag.
// - pr: the edge's open entry (one-hot or none), whether it closes (the OR of the entries'
//   matches) and the entry's index, all formed from registered compares as the edge moves up:
//   so the pairing itself (setting or clearing an open bit, the entry counter, the output's valid
//   and the value RAM's read address) reads only flip-flops.
// - seg: the opening edge's value read from the table (distributed RAM, index registered) and
//   the closing edge's.
// The open table has MaxActiveEdges entries, so it cannot fill: a line carries at most that
// many edges, so an edge that opens a segment takes the next entry never used on this line (a
// counter, kept binary for the RAM's write address and one-hot for the open bits and compares),
// and the closing edge's entry index is the OR of the matching entries' indices (one matches at
// most: no priority search). Every non-marker edge writes its polygon and value into that entry
// whether it opens or not (only an open entry is ever matched). The channel vector passes
// through untouched, so only its width matters here.
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
  localparam int unsigned Entries   = MaxActiveEdges;  // the open table's
  localparam int unsigned IndexBits = (Entries > 1) ? $clog2(Entries) : 1;
  localparam int unsigned CountBits = $clog2(Entries + 1);
  localparam logic [Entries:0] FirstEntry = {{Entries{1'b0}}, 1'b1};  // used_oh_q on an empty line
  typedef logic [VectorBits-1:0] chans_t;

  logic [Entries-1:0]    open_q;        // entry holds an unpaired edge
  logic [PolyIdBits-1:0] open_poly_q [Entries];
  chans_t                open_value_q [Entries];
  logic [CountBits-1:0]  used_q;        // entries taken on this line (0 .. Entries), cleared by
                                        // the marker
  logic [Entries:0]      used_oh_q;     // the same count one-hot (bit Entries: the table is full)

  // The input register: the edge, which entries hold its polygon, and whether the edge ahead of
  // it (in the pairing register once this one moves up) is a non-marker of the same polygon.
  logic                      in_valid_q, in_eol_q, in_prev_q;
  logic [PolyIdBits-1:0]     in_poly_q;
  logic [MaterialIdBits-1:0] in_material_q;
  chans_t                    in_value_q;
  logic [Entries-1:0]        in_same_q;

  // The pairing register: the edge, its open entry (one-hot or none), whether it has one, and
  // that entry's index.
  logic                      pr_valid_q, pr_eol_q, pr_closes_q;
  logic [PolyIdBits-1:0]     pr_poly_q;
  logic [MaterialIdBits-1:0] pr_material_q;
  chans_t                    pr_value_q;
  logic [Entries-1:0]        pr_match_q;
  logic [IndexBits-1:0]      pr_idx_q;

  logic               en, pair, has_free;
  logic [Entries-1:0] found;  // the input register's open entries, the edge ahead aside

  assign en           = seg_ready_i || !seg_valid_o;
  assign pair         = pr_valid_q && en;        // the pairing register's edge is paired this clock
  assign edge_ready_o = en;
  assign has_free     = !used_oh_q[Entries];
  assign found        = in_same_q & open_q;

  // Which entries hold `poly` once the pairing register's edge is paired: entry used_q takes
  // that edge's polygon. Entries past the line's used ones compare with stale polygons, but they
  // are not open, and `found` masks them. A function called inside the input register's `if`,
  // not kept as a signal: the same comparators in hardware, but a simulator compares only on the
  // clocks that take an edge.
  function automatic logic [Entries-1:0] holds(input logic [PolyIdBits-1:0] poly);
    for (int i = 0; i < Entries; i++)
      holds[i] = used_oh_q[i] ? (pr_poly_q == poly) : (open_poly_q[i] == poly);
  endfunction
  // The matching entry's index, the OR of the matching entries' indices (0 when none matches).
  function automatic logic [IndexBits-1:0] match_index(input logic [Entries-1:0] m);
    match_index = '0;
    for (int i = 0; i < Entries; i++)
      match_index = match_index | (IndexBits'(i) & {IndexBits{m[i]}});
  endfunction

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_valid_q  <= 1'b0;
      pr_valid_q  <= 1'b0;
      open_q      <= '0;
      used_q      <= '0;
      used_oh_q   <= FirstEntry;
      seg_valid_o <= 1'b0;
    end else begin
      if (en) begin
        in_valid_q  <= edge_valid_i;
        pr_valid_q  <= in_valid_q;
        seg_valid_o <= pr_valid_q && (pr_eol_q || pr_closes_q);
      end
      if (pair) begin
        if (pr_eol_q) begin
          open_q    <= '0;
          used_q    <= '0;
          used_oh_q <= FirstEntry;
        end else if (pr_closes_q) begin
          open_q <= open_q & ~pr_match_q;
        end else if (has_free) begin
          open_q    <= open_q | used_oh_q[Entries-1:0];
          used_q    <= used_q + 1'b1;
          used_oh_q <= used_oh_q << 1;
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (edge_valid_i && en) begin
      in_poly_q     <= edge_poly_i;
      in_material_q <= edge_material_i;
      in_value_q    <= edge_value_i;
      in_eol_q      <= edge_eol_i;
      in_same_q     <= holds(edge_poly_i);
      in_prev_q     <= in_valid_q && !in_eol_q && in_poly_q == edge_poly_i;
    end
  end

  // The edge moves up as the pairing register's edge pairs. That edge only opens or closes an
  // entry of its own polygon, so: after a marker nothing is open; with the same polygon (it was
  // one ahead on arrival, so no compare saw its entry) the edge closes exactly when that one
  // opens, in the entry that one takes (used_q); otherwise the entries found on arrival.
  always_ff @(posedge clk_i) begin
    if (in_valid_q && en) begin
      pr_poly_q     <= in_poly_q;
      pr_material_q <= in_material_q;
      pr_value_q    <= in_value_q;
      pr_eol_q      <= in_eol_q;
      if (pr_valid_q && pr_eol_q) begin
        pr_match_q  <= '0;
        pr_closes_q <= 1'b0;
      end else if (in_prev_q) begin
        pr_match_q  <= pr_closes_q ? '0 : used_oh_q[Entries-1:0];
        pr_closes_q <= !pr_closes_q;
      end else begin
        pr_match_q  <= found;
        pr_closes_q <= found != '0;
      end
      pr_idx_q <= in_prev_q ? IndexBits'(used_q) : match_index(found);
    end
  end

  always_ff @(posedge clk_i) begin
    // Written whether the edge opens or not (an entry past the open ones): the write enable
    // waits for no comparison. Nor for the pairing: while the output stalls, the pairing
    // register's edge and used_q hold, so the same word goes to the same unused entry on every
    // clock until the edge pairs (entry used_q is not open, so no read and no match sees it: the
    // compares take its polygon from pr_poly_q). The write enable is then flip-flops only, not
    // the output's handshake: seg_valid_o -> en -> pair -> the distributed RAM's write enables
    // across the die would be the sized Phong top's longest path.
    if (pr_valid_q && !pr_eol_q && has_free) begin
      open_poly_q[IndexBits'(used_q)]  <= pr_poly_q;
      open_value_q[IndexBits'(used_q)] <= pr_value_q;
    end
    if (pair) begin
      // Loaded on every pairing: the output's valid says whether it is a segment.
      seg_e_o        <= open_value_q[pr_idx_q];
      seg_f_o        <= pr_value_q;
      seg_poly_o     <= pr_poly_q;
      seg_material_o <= pr_material_q;
      seg_eol_o      <= pr_eol_q;
    end
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, edge_valid_i, edge_ready_o, {edge_poly_i, edge_material_i,
    edge_value_i, edge_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, seg_valid_o, seg_ready_i, {seg_e_o, seg_f_o, seg_poly_o,
    seg_material_o, seg_eol_o})
  `WATKINS_ASSERT(a_table_room, pair && !pr_eol_q && !pr_closes_q |-> has_free)
  `WATKINS_ASSERT(a_used_onehot, used_oh_q == FirstEntry << used_q)
  `WATKINS_ASSERT(a_prev, in_valid_q && in_prev_q |-> pr_valid_q && !pr_eol_q && pr_poly_q == in_poly_q)
`ifdef WATKINS_ASSERT_ON
  // The entries found as the edge moved up are those a search at pairing time would find.
  function automatic logic [Entries-1:0] open_now(input logic [PolyIdBits-1:0] poly);
    for (int i = 0; i < Entries; i++) open_now[i] = open_q[i] && open_poly_q[i] == poly;
  endfunction
  `WATKINS_ASSERT(a_match_forwarded, pair && !pr_eol_q |-> pr_match_q == open_now(pr_poly_q) &&
    pr_closes_q == (pr_match_q != '0) && (!pr_closes_q || pr_match_q[pr_idx_q]))
`endif
  `WATKINS_COVER(c_two_open, $countones(open_q) >= 2)
  `WATKINS_COVER(c_prev_closes, in_valid_q && in_prev_q && !pr_closes_q)
endmodule

// segment_former_formal: proves rtl/segment_former.sv (3 table entries, 4 polygon ids, 3-bit
// channel vector) holds valid and its whole output until ready, and emits exactly the segments a
// reference pairing says, once each, in order. Its input and pairing registers hold the last two
// edges taken until each is paired, once; what they carry about the table (the entries found
// holding the polygon on arrival, the same-polygon flag for the edge ahead, the open entry, its
// index and whether it closes) is what a search would find when the edge is paired. The harness
// keeps which polygons are open on the line and the vector of each one's opening edge, and pairs
// the pairing register's edge when the DUT does: an edge of an open polygon (or the end-of-line
// marker) must come out as the next segment, with the opening edge's vector as e, its own as f
// (each input edge carries its sequence number as its vector), its polygon, material and marker;
// any other edge opens its polygon and emits nothing. Segments due minus segments out is
// seg_valid_o. The environment opens at most 3 segments per line (the table's capacity: a line
// carries at most MaxActiveEdges edges, and an opening edge takes the next entry never used on
// the line). Induction invariants tie every table entry to the reference: it holds an open
// polygon with its opening vector, no two entries hold one polygon, as many entries are open as
// polygons, the entries used on the line are the segments opened on it (binary and one-hot) and
// no later entry is open.
`include "formal_stream.svh"

module segment_former_formal #(
  localparam int unsigned Entries        = 3,  // MaxActiveEdges: the entries probed below
  localparam int unsigned VectorBits     = 3,  // the tag
  localparam int unsigned PolyIdBits     = 2,
  localparam int unsigned MaterialIdBits = 1,
  localparam int unsigned Polys          = 2 ** PolyIdBits
) (
  input  logic                      clk_i,
  input  logic                      rst_ni,
  input  logic [PolyIdBits-1:0]     edge_poly_i,
  input  logic [MaterialIdBits-1:0] edge_material_i,
  input  logic [VectorBits-1:0]     edge_value_i,
  input  logic                      edge_eol_i,
  input  logic                      edge_valid_i,
  input  logic                      seg_ready_i
);
  logic                      edge_ready_o, seg_eol_o, seg_valid_o;
  logic [VectorBits-1:0]     seg_e_o, seg_f_o;
  logic [PolyIdBits-1:0]     seg_poly_o;
  logic [MaterialIdBits-1:0] seg_material_o;
  segment_former #(
    .MaxActiveEdges(Entries), .VectorBits(VectorBits), .PolyIdBits(PolyIdBits),
    .MaterialIdBits(MaterialIdBits)
  ) u_dut (.*);

  `FORMAL_PAST
  `FORMAL_ASSUME_HOLD(in, edge_valid_i, edge_ready_o, {edge_poly_i, edge_material_i, edge_value_i,
    edge_eol_i})
  `FORMAL_ASSERT_HOLD(out, seg_valid_o, seg_ready_i, {seg_e_o, seg_f_o, seg_poly_o, seg_material_o,
    seg_eol_o})

  // The DUT's input and pairing registers (hierconn wires: flatten connects them to u_dut's
  // registers). They must hold the last two edges taken, once each; the reference pairs the
  // pairing register's edge when the DUT does.
  (* hierconn *) logic                      \u_dut.in_valid_q ;
  (* hierconn *) logic                      \u_dut.in_eol_q ;
  (* hierconn *) logic                      \u_dut.in_prev_q ;
  (* hierconn *) logic [PolyIdBits-1:0]     \u_dut.in_poly_q ;
  (* hierconn *) logic [MaterialIdBits-1:0] \u_dut.in_material_q ;
  (* hierconn *) logic [VectorBits-1:0]     \u_dut.in_value_q ;
  (* hierconn *) logic [Entries-1:0]              \u_dut.in_same_q ;
  (* hierconn *) logic                      \u_dut.pr_valid_q ;
  (* hierconn *) logic                      \u_dut.pr_eol_q ;
  (* hierconn *) logic                      \u_dut.pr_closes_q ;
  (* hierconn *) logic [PolyIdBits-1:0]     \u_dut.pr_poly_q ;
  (* hierconn *) logic [MaterialIdBits-1:0] \u_dut.pr_material_q ;
  (* hierconn *) logic [VectorBits-1:0]     \u_dut.pr_value_q ;
  (* hierconn *) logic [Entries-1:0]              \u_dut.pr_match_q ;
  (* hierconn *) logic [1:0]                \u_dut.pr_idx_q ;
  logic                      a_valid, a_eol;      // the input register's edge
  logic [PolyIdBits-1:0]     a_poly;
  logic                      in_valid, in_eol;    // the pairing register's edge (paired next)
  logic [PolyIdBits-1:0]     in_poly;
  logic [MaterialIdBits-1:0] in_material;
  logic [VectorBits-1:0]     in_value;
  assign a_valid     = \u_dut.in_valid_q ;
  assign a_eol       = \u_dut.in_eol_q ;
  assign a_poly      = \u_dut.in_poly_q ;
  assign in_valid    = \u_dut.pr_valid_q ;
  assign in_eol      = \u_dut.pr_eol_q ;
  assign in_poly     = \u_dut.pr_poly_q ;
  assign in_material = \u_dut.pr_material_q ;
  assign in_value    = \u_dut.pr_value_q ;

  // The last two edges taken.
  logic                      taken_eol_q, taken2_eol_q;
  logic [PolyIdBits-1:0]     taken_poly_q, taken2_poly_q;
  logic [MaterialIdBits-1:0] taken_material_q, taken2_material_q;
  logic [VectorBits-1:0]     taken_value_q, taken2_value_q;
  always_ff @(posedge clk_i) begin
    if (edge_valid_i && edge_ready_o) begin
      taken_eol_q       <= edge_eol_i;
      taken_poly_q      <= edge_poly_i;
      taken_material_q  <= edge_material_i;
      taken_value_q     <= edge_value_i;
      taken2_eol_q      <= taken_eol_q;
      taken2_poly_q     <= taken_poly_q;
      taken2_material_q <= taken_material_q;
      taken2_value_q    <= taken_value_q;
    end
  end

  // The reference: open polygons and their opening vectors; the segment due next. It pairs the
  // registered edge on the clock the DUT pairs it (pair).
  logic                  pair, closes;
  logic [Polys-1:0]      open_q;
  logic [VectorBits-1:0] opened_q [Polys];
  logic [VectorBits-1:0] exp_e_q, exp_f_q;
  logic [PolyIdBits-1:0] exp_poly_q;
  logic [MaterialIdBits-1:0] exp_material_q;
  logic                  exp_eol_q;
  assign pair   = in_valid && (seg_ready_i || !seg_valid_o);
  assign closes = in_eol || open_q[in_poly];
  `FORMAL_COUNT(n_in_q, VectorBits, edge_valid_i, edge_ready_o)
  `FORMAL_COUNT(n_pair_q, VectorBits, in_valid, seg_ready_i || !seg_valid_o)
  `FORMAL_COUNT(n_due_q, VectorBits, in_valid && closes, seg_ready_i || !seg_valid_o)
  `FORMAL_COUNT(n_out_q, VectorBits, seg_valid_o, seg_ready_i)

  logic [1:0] opened_n_q;  // segments opened on this line, <= Entries
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      open_q     <= '0;
      opened_n_q <= '0;
    end else if (pair) begin
      if (in_eol) begin
        open_q     <= '0;
        opened_n_q <= '0;
      end else begin
        open_q[in_poly] <= !open_q[in_poly];
        if (!open_q[in_poly]) opened_n_q <= opened_n_q + 1'b1;
      end
    end
  end
  always_ff @(posedge clk_i) begin
    if (pair && !in_eol && !open_q[in_poly]) opened_q[in_poly] <= in_value;
    if (pair && closes) begin
      exp_e_q        <= opened_q[in_poly];
      exp_f_q        <= in_value;
      exp_poly_q     <= in_poly;
      exp_material_q <= in_material;
      exp_eol_q      <= in_eol;
    end
  end
  // The open polygons and their count once the pairing and input registers' edges are paired
  // too: what the next edge taken finds.
  logic [Polys-1:0] open_mid, open_after;
  logic [1:0]       opened_n_mid, opened_n_after;
  always_comb begin
    open_mid     = open_q;
    opened_n_mid = opened_n_q;
    if (in_valid) begin
      if (in_eol) begin
        open_mid     = '0;
        opened_n_mid = '0;
      end else begin
        open_mid[in_poly] = !open_q[in_poly];
        if (!open_q[in_poly]) opened_n_mid = opened_n_q + 1'b1;
      end
    end
    open_after     = open_mid;
    opened_n_after = opened_n_mid;
    if (a_valid) begin
      if (a_eol) begin
        open_after     = '0;
        opened_n_after = '0;
      end else begin
        open_after[a_poly] = !open_mid[a_poly];
        if (!open_mid[a_poly]) opened_n_after = opened_n_mid + 1'b1;
      end
    end
  end

  function automatic int unsigned count(logic [Polys-1:0] v);
    count = 0;
    for (int unsigned i = 0; i < Polys; i++) count = count + 32'(v[i]);
  endfunction

  // The table (hierconn wires: flatten connects them to u_dut's registers).
  (* hierconn *) logic [Entries-1:0]          \u_dut.open_q ;
  (* hierconn *) logic [1:0]            \u_dut.used_q ;
  (* hierconn *) logic [Entries:0]            \u_dut.used_oh_q ;
  (* hierconn *) logic [PolyIdBits-1:0] \u_dut.open_poly_q[0] ;
  (* hierconn *) logic [PolyIdBits-1:0] \u_dut.open_poly_q[1] ;
  (* hierconn *) logic [PolyIdBits-1:0] \u_dut.open_poly_q[2] ;
  (* hierconn *) logic [VectorBits-1:0] \u_dut.open_value_q[0] ;
  (* hierconn *) logic [VectorBits-1:0] \u_dut.open_value_q[1] ;
  (* hierconn *) logic [VectorBits-1:0] \u_dut.open_value_q[2] ;
  logic [PolyIdBits-1:0] poly [Entries];
  logic [VectorBits-1:0] value [Entries];
  assign poly[0]  = \u_dut.open_poly_q[0] ;
  assign poly[1]  = \u_dut.open_poly_q[1] ;
  assign poly[2]  = \u_dut.open_poly_q[2] ;
  assign value[0] = \u_dut.open_value_q[0] ;
  assign value[1] = \u_dut.open_value_q[1] ;
  assign value[2] = \u_dut.open_value_q[2] ;

  always_comb begin
    if (edge_valid_i) begin
      assume (edge_value_i == n_in_q);
      // At most Entries segments opened per line.
      assume (edge_eol_i || open_after[edge_poly_i] || opened_n_after < 2'(Entries));
    end
    if (rst_ni) begin
      assert (edge_ready_o == (seg_ready_i || !seg_valid_o));
      // The input and pairing registers hold the last two edges taken until each is paired, once.
      assert (VectorBits'(n_in_q - n_pair_q) == VectorBits'(a_valid) + VectorBits'(in_valid));
      if (a_valid) begin
        assert (a_eol == taken_eol_q && a_poly == taken_poly_q
                && \u_dut.in_material_q == taken_material_q && \u_dut.in_value_q == taken_value_q
                && \u_dut.in_value_q == VectorBits'(n_in_q - 1'b1));
        // The edge ahead is the pairing register's: the same-polygon flag compares with it.
        assert (\u_dut.in_prev_q == (in_valid && !in_eol && in_poly == a_poly));
        // The entries it found on arrival are the open ones of its polygon now.
        if (!a_eol)
          for (int unsigned i = 0; i < Entries; i++)
            assert ((\u_dut.in_same_q [i] && \u_dut.open_q [i]) == (\u_dut.open_q [i] && poly[i] == a_poly));
        // It fits in the table once the edge ahead is paired.
        assert (a_eol || open_mid[a_poly] || opened_n_mid < 2'(Entries));
      end
      if (in_valid) begin
        if (a_valid)
          assert (in_eol == taken2_eol_q && in_poly == taken2_poly_q
                  && in_material == taken2_material_q && in_value == taken2_value_q);
        else
          assert (in_eol == taken_eol_q && in_poly == taken_poly_q
                  && in_material == taken_material_q && in_value == taken_value_q);
        assert (in_value == VectorBits'(n_in_q - 1'b1 - VectorBits'(a_valid)));
        // It fits in the table (the environment's bound, taken when it arrived).
        assert (in_eol || open_q[in_poly] || opened_n_q < 2'(Entries));
        // Its open entry, whether it closes and the entry's index are a search's now.
        if (!in_eol) begin
          assert (\u_dut.pr_closes_q == open_q[in_poly]);
          for (int unsigned i = 0; i < Entries; i++)
            assert (\u_dut.pr_match_q [i] == (\u_dut.open_q [i] && poly[i] == in_poly));
          if (\u_dut.pr_closes_q ) assert (\u_dut.pr_match_q [\u_dut.pr_idx_q ]);
        end
      end
      // Every segment due comes out once, in order, as the reference pairs it.
      assert (VectorBits'(n_due_q - n_out_q) == VectorBits'(seg_valid_o));
      if (seg_valid_o) begin
        assert (seg_f_o == exp_f_q && seg_poly_o == exp_poly_q && seg_material_o == exp_material_q
                && seg_eol_o == exp_eol_q);
        if (!seg_eol_o) assert (seg_e_o == exp_e_q);
      end
      // Induction invariants: the table mirrors the reference.
      assert (count(Polys'(\u_dut.open_q )) == count(open_q));
      assert (\u_dut.used_q == opened_n_q);
      assert (\u_dut.used_oh_q == {{Entries{1'b0}}, 1'b1} << \u_dut.used_q );
      for (int unsigned i = 0; i < Entries; i++) begin
        if (\u_dut.open_q [i]) begin
          assert (i < 32'(\u_dut.used_q ));
          assert (open_q[poly[i]] && value[i] == opened_q[poly[i]]);
          for (int unsigned j = i + 1; j < Entries; j++)
            if (\u_dut.open_q [j]) assert (poly[i] != poly[j]);
        end
      end
    end
  end
endmodule

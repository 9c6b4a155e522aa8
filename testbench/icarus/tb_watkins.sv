// tb_watkins: Icarus Verilog bench for the yosys-elaborated watkins_top (plain Verilog
// written by `yosys ... write_verilog`, as Icarus 11 cannot read the package's packed
// structs). Reads the hex files of watkins_export, streams the edge records with no gaps and
// no back-pressure, checks every pixel against the model, prints cycles and mismatches.
// The sizes are the package's, from the one source of formats (model/twins/formats.hpp):
// scripts/lib/bench/icarus.sh passes each with iverilog -Ptb_watkins.NAME=`watkins_gen_pkg --value NAME`.
//   vvp tb.vvp +dir=<folder of edges.hex, pixels.hex, frame.hex>
`timescale 1ns / 1ps
module tb_watkins #(
  parameter int EdgeRecordBits = 0,  // $bits(watkins_pkg::edge_t)
  parameter int LineBits = 0,        // width_i, height_i
  parameter int UnitBits = 0,        // one component of light_i, eye_i
  parameter int MaterialIdBits = 0,  // material_addr_i
  parameter int MaterialBits = 0,    // material_d_i, material_w_i
  parameter int ShininessBits = 0    // material_n_i
);
  localparam int EdgeBits = EdgeRecordBits;
  localparam int MaxEdges = 1 << 18;
  localparam int MaxPixels = 1 << 20;

  logic                clk = 1'b0;
  logic                rst_n = 1'b0;
  logic [31:0]         frame [0:3];    // width, height, background, edge count
  logic [EdgeBits-1:0] edges [0:MaxEdges-1];
  logic [27:0]         expected [0:MaxPixels-1];

  logic [EdgeBits-1:0] edge_d;
  logic                eof_d, edge_valid;
  wire                 edge_ready;
  wire  [23:0]         rgb;
  wire                 covered, last, pixel_valid, overflow;

  watkins_top dut (
    .clk_i(clk), .rst_ni(rst_n),
    .width_i(frame[0][LineBits-1:0]), .height_i(frame[1][LineBits-1:0]), .background_i(frame[2][23:0]),
    .sparse_i(1'b0),
    .tie_submission_i(1'b0),
    .smooth_w_i(8'd0),
    .eq2_i(1'b0),
    .edge_i(edge_d), .edge_eof_i(eof_d), .edge_valid_i(edge_valid), .edge_ready_o(edge_ready),
    .pixel_rgb_o(rgb), .pixel_covered_o(covered), .pixel_x_o(), .pixel_y_o(), .pixel_last_o(last),
    .pixel_valid_o(pixel_valid), .pixel_ready_i(1'b1), .overflow_o(overflow),
    // Phong inputs: unused by the Gouraud top (Phong = 0) simulated here.
    .light_i({3 * UnitBits{1'b0}}), .eye_i({3 * UnitBits{1'b0}}), .material_we_i(1'b0),
    .material_addr_i({MaterialIdBits{1'b0}}), .material_cp_i(24'd0), .material_d_i({MaterialBits{1'b0}}),
    .material_w_i({MaterialBits{1'b0}}), .material_n_i({ShininessBits{1'b0}}));

  always #5 clk = ~clk;

  string dir;
  int n_edges, n_pixels, sent, received, mismatches;
  longint cycles;

  initial begin
    if (EdgeRecordBits <= 0 || LineBits <= 0 || UnitBits <= 0 || MaterialIdBits <= 0 || MaterialBits <= 0 ||
        ShininessBits <= 0) begin
      $display("tb_watkins: sizes not set (iverilog -Ptb_watkins.NAME=..., see scripts/lib/bench/icarus.sh)");
      $finish;
    end
    if (!$value$plusargs("dir=%s", dir)) dir = ".";
    $readmemh({dir, "/frame.hex"}, frame);
    $readmemh({dir, "/edges.hex"}, edges);
    $readmemh({dir, "/pixels.hex"}, expected);
    n_edges = frame[3];
    n_pixels = frame[0] * frame[1];
    sent = 0; received = 0; mismatches = 0; cycles = 0;
    edge_valid = 1'b0; eof_d = 1'b0; edge_d = '0;
    repeat (4) @(posedge clk);
    rst_n = 1'b1;
  end

  // Source: the next record (or the EOF beat) is presented as soon as the last one was taken.
  always @(posedge clk) begin
    if (rst_n) begin
      cycles <= cycles + 1;
      if (!edge_valid || edge_ready) begin
        if (sent < n_edges) begin
          edge_d <= edges[sent]; eof_d <= 1'b0; edge_valid <= 1'b1; sent <= sent + 1;
        end else if (sent == n_edges) begin
          eof_d <= 1'b1; edge_valid <= 1'b1; sent <= sent + 1;
        end else begin
          edge_valid <= 1'b0;
        end
      end
      if (pixel_valid) begin
        if ({3'b000, covered, rgb} !== expected[received]) begin
          if (mismatches == 0)
            $display("first mismatch: pixel (%0d, %0d) rtl %h covered %0d, model %h",
                     received % frame[0], received / frame[0], rgb, covered, expected[received]);
          mismatches <= mismatches + 1;
        end
        received <= received + 1;
        if (last) begin
          $display("icarus: %0d cycles, %0d pixels, %0d mismatches, overflow %0d",
                   cycles + 1, received + 1, mismatches, overflow);
          $finish;
        end
      end
      if (cycles > 64'd50_000_000) begin
        $display("icarus: watchdog: no last pixel after %0d cycles (%0d pixels)", cycles, received);
        $finish;
      end
    end
  end
endmodule

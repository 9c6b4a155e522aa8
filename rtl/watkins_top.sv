// watkins_top: the Watkins scan-line shading pipeline, edge records in, pixels out.
// From the y-sorted edge-record stream to every pixel of the frame in raster order; twin:
// model/twins/watkins_top.cpp.
// Stages: active_edge_list (+ edge_incrementer) -> segment_former -> segment skid (registered
// ready) -> segment_interpolator (span setup, span_reciprocal, stepper) -> [Phong = 1:
// normalizer -> material table -> phong_shader] -> fragment queue -> scanline_buffer
// [-> smoother] -> pixel skid (registered ready).
// Latency: a frame's first pixel leaves once its first line's fragments are depth-tested and
// the line's marker swaps the line buffers; model/twins/cycle_model.hpp gives a frame's cycles.
// Steady state: one fragment per clock; a line costs max(width, fragments + setup) cycles, the
// active-edge list working on line y+1 while line y is drawn.
// Every stage boundary is valid/ready. Phong = 0 (Gouraud): channels 2..4 are R, G, B shades
// and the fragment's shade goes straight to the depth test. Phong = 1: they are the vertex
// normal; each fragment's interpolated normal is normalized and shaded by Phong's eq. (3) with
// its polygon's material (a 2^MaterialIdBits-entry table written through material_*_i between
// frames) and the frame's light_i / eye_i (sampled with the frame size), adding 58 cycles of
// latency (the normalizer's 16 and the shader's 42), not throughput: still one fragment per
// clock, shaded before the depth test.
// A frame starts with the first beat of its edge stream once the previous frame's last pixel
// has left and its stream has been read up to its EOF beat; width, height and background are
// sampled then (and sparse_i, tie_submission_i).
// Sparse mode (sparse_i = 1 for the frame): the pixel stream carries only the covered pixels, in
// raster order, each with pixel_x_o/pixel_y_o; a line then costs max(1, covered pixels,
// fragments + setup) cycles, plus one for the line buffer's swap when its reader sets the pace.
// pixel_last_o marks the frame's last beat: its last covered pixel when the last line has one,
// otherwise a terminating beat with pixel_covered_o = 0 (background rgb) at (width-1, height-1)
// -- so a frame covering no pixel is exactly that one beat. The consumer keeps the background
// elsewhere (e.g. a framebuffer cleared once). sparse_i = 0: every pixel.
// Smoothing (smooth_w_i != 0 for the frame): Herman & Liu's 3x3 smoother (rtl/smoother.sv) after
// the scanline buffer. It needs the whole raster, so a smoothed frame is emitted in full whatever
// sparse_i says; its last pixel leaves width + 15 clocks after the buffer's last (the flush of
// the last line and the smoother's 14 stages). smooth_w_i = 0: the smoother is bypassed, no
// latency. Smoothing = 0 (Config::smoothing false): a top for scenes that never smooth has no
// smoother at all (its logic and multipliers are saved); smooth_w_i is ignored, a frame must
// start with it 0 (asserted), and the pixel stream comes straight from the scanline buffer.
// Equal depth (tie_submission_i for the frame): 0 keeps the fragment that reached the depth test
// first (segments in closing order); 1 keeps the smaller polygon id, i.e. the first polygon
// submitted when ids follow submission order, as GL's GL_LESS depth test does. Each fragment
// carries its polygon id from the segment former to the scanline buffer for it.
// Built for a configuration (model/twins/config.hpp; `watkins_gen_pkg --params F --shading S`
// prints these parameters): each channel group's word (IntBits, sign included, + FracBits) --
// X, depth, and the attribute slots 2..4 (the shade in a Gouraud top, the normal in a Phong
// top) -- the fragment depth, the id widths and the capacities. The defaults are the default
// configuration (rtl/watkins_pkg.sv); edge_i is laid out as watkins_pkg::edge_bits says.
// EdgeOrder 3 (Config::edge_order): Whitted's curved edges, each a cubic in the scan line stepped
// by forward differences in the active-edge list's incrementer; everything after it is the same.
// HasEq2 = 1 (Config::eq2, Gouraud top only): the shade divider (rtl/shade_divider.sv) after the
// interpolator, adding Eq2RecipBits + 4 cycles of latency to every fragment (20 by default),
// not throughput. eq2_i (sampled with the frame size) picks Gouraud's eq. (2) for the frame: the
// shade slots carry S Z, and each fragment's shade is their quotient by its depth; eq2_i = 0
// keeps the interpolated shade (eq. (1)). HasEq2 = 0: no divider, eq2_i must be 0 at every
// frame start (asserted).
// Compact = 1 (Config::compact): the compact micro-architecture for small parts
// (docs/reference/compact.md): compact_active_edge_list, compact_segment_former,
// compact_segment_interpolator and compact_scanline_buffer in place of their pipelined
// counterparts, the frame control, the parameters, the ports and every value unchanged; only
// the cycles differ. Its glue is the pipelined top's but for one thing: the former's segments go
// straight to the interpolator, in the clock the former offers one and the interpolator's
// seg_ready_o (a flop) is high -- no segment skid. The fragment queue (two entries, latency 1)
// and the pixel skid stay as in the pipelined top. It needs Smoothing = 0 and HasEq2 = 0
// (checked at elaboration) and sparse_i = 0 at every frame start (asserted: the compact buffer
// emits full frames only). With Phong = 1 compact_normalizer and compact_phong_shader take the
// pipelined Phong blocks' places (docs/reference/compact-phong.md): the same shades in the same
// order before the depth test, one fragment per 5 clocks at most through them, latency 33 + 65
// clocks, or 15 + 42 with PhongNarrow = 1 (the narrow formats' blocks, whose cycle twins hold each
// block's figure); the interpolator stalls on the normalizer's ready_o, a flop. The compact shader
// needs L and E stable from 10 clocks before a frame's first pixel reaches it to its last shade:
// the top loads them only at a frame's start (after the previous frame's last pixel, so after its
// last shade), and the frame's first fragment reaches the shader no sooner than the interpolator's
// span setup and the normalizer's latency later (33 clocks, 15 narrow). Lanes = 2 (Config::lanes,
// compact Gouraud only, checked at elaboration): the interpolator's beats carry up to two
// consecutive pixels of a span (fr_pair: lane 1 at x + 1), the fragment queue carries both, and
// the line buffer writes both in one clock; the values and their order are the same, a long span
// takes half the clocks.
`include "watkins_assert.svh"

module watkins_top #(
  parameter int unsigned MaxActiveEdges = watkins_pkg::MaxActiveEdges,
  parameter int unsigned MaxWidth       = watkins_pkg::DefaultMaxWidth,  // line-buffer depth in pixels
  parameter int          Phong          = 0,  // 1: per-pixel Phong shading of normals
  parameter int unsigned XIntBits       = watkins_pkg::ChannelBits - watkins_pkg::FracBits,
  parameter int unsigned XFracBits      = watkins_pkg::FracBits,
  parameter int unsigned DepthIntBits   = watkins_pkg::ChannelBits - watkins_pkg::FracBits,
  parameter int unsigned DepthFracBits  = watkins_pkg::FracBits,
  parameter int unsigned AttrIntBits    = watkins_pkg::ChannelBits - watkins_pkg::FracBits,
  parameter int unsigned AttrFracBits   = watkins_pkg::FracBits,
  parameter int unsigned DepthBits      = watkins_pkg::DepthBits,       // fragment depth word
  parameter int unsigned PolyIdBits     = watkins_pkg::PolyIdBits,
  parameter int unsigned MaterialIdBits = watkins_pkg::MaterialIdBits,
  parameter int unsigned EdgeIdBits     = watkins_pkg::EdgeIdBits,      // records per frame
  parameter int unsigned EdgeOrder      = 1,  // 1: straight edges (slope); 3: cubic edges (d1, d2, d3)
  parameter int          Smoothing      = 1,  // 0: no smoother (smooth_w_i must be 0 at every frame start)
  parameter int          HasEq2         = 0,  // 1 (Gouraud): the eq. (2) shade divider, eq2_i per frame
  /* verilator lint_off UNUSEDPARAM */  // read by the divider only, so unused where HasEq2 = 0
  parameter int unsigned Eq2RecipBits   = watkins_pkg::Eq2RecipBits,  // its 1/depth mantissa
  /* verilator lint_on UNUSEDPARAM */
  parameter int          Compact        = 0,  // 1: the compact blocks (no smoother, full frames)
  parameter int unsigned Lanes          = 1,  // fragments per beat of the compact fragment path: 1 or 2
  parameter int          PhongNarrow    = 0,  // 1 (Compact, Phong): the narrow formats' blocks
  localparam int unsigned XBits    = XIntBits + XFracBits,
  localparam int unsigned ZBits    = DepthIntBits + DepthFracBits,
  localparam int unsigned AttrBits = AttrIntBits + AttrFracBits,
  localparam int unsigned EdgeBits = watkins_pkg::edge_bits(XBits, ZBits, AttrBits, PolyIdBits, MaterialIdBits,
                                                            EdgeOrder)
) (
  input  logic                               clk_i,
  input  logic                               rst_ni,          // active-low synchronous reset
  input  logic [watkins_pkg::LineBits-1:0]   width_i,         // frame size, stable for the whole frame (1..MaxWidth)
  input  logic [watkins_pkg::LineBits-1:0]   height_i,        // 1..4096
  input  watkins_pkg::rgb_t                  background_i,    // shade of pixels no polygon covers
  input  logic                               sparse_i,        // frame configuration: covered pixels only
  input  logic                               tie_submission_i, // frame configuration: a depth tie goes to the smaller polygon id
  input  logic [watkins_pkg::SmoothWBits-1:0] smooth_w_i,     // frame configuration: smoothing weight W (0: off)
  input  logic                               eq2_i,           // frame configuration: Gouraud's eq. (2) (HasEq2)
  input  logic [EdgeBits-1:0]                edge_i,          // edge records, sorted by y0 (ties in stream order)
  input  logic                               edge_eof_i,      // with valid: this beat ends the frame's stream, carries no edge
  input  logic                               edge_valid_i,
  output logic                               edge_ready_o,
  output watkins_pkg::rgb_t                  pixel_rgb_o,     // raster order, every pixel (or covered only)
  output logic                               pixel_covered_o, // some polygon won this pixel
  output logic [watkins_pkg::LineBits-1:0]   pixel_x_o,       // position of the pixel (both modes)
  output logic [watkins_pkg::LineBits-1:0]   pixel_y_o,
  output logic                               pixel_last_o,    // last pixel of the frame
  output logic                               pixel_valid_o,
  input  logic                               pixel_ready_i,
  output logic                               overflow_o,      // sticky until reset: the
                                                              // active-edge list was full
  // Phong only (ignored when Phong = 0). light_i / eye_i: unit vectors towards the light and the
  // eye, {z, y, x} Q2.14, sampled at frame start. Material table: one write per clock, between
  // frames; entry {Cp, d, W (1.0 = 256), n} as model/twins/phong_shader.hpp defines them.
  input  logic [3*watkins_pkg::UnitBits-1:0]       light_i,
  input  logic [3*watkins_pkg::UnitBits-1:0]       eye_i,
  input  logic                                     material_we_i,
  input  logic [MaterialIdBits-1:0]                material_addr_i,
  input  watkins_pkg::rgb_t                        material_cp_i,   // reflectance Cp (255 = 1.0)
  input  logic [watkins_pkg::MaterialBits-1:0]     material_d_i,
  input  logic [watkins_pkg::MaterialBits-1:0]     material_w_i,
  input  logic [watkins_pkg::ShininessBits-1:0]    material_n_i
);
  localparam int unsigned LineBits   = watkins_pkg::LineBits;
  localparam int unsigned VectorBits = watkins_pkg::vector_bits(XBits, ZBits, AttrBits);  // channel
                                                                                          // vector

  // The compact blocks serve the top without the smoother and the eq. (2) divider.
  if (Compact != 0 && (Smoothing != 0 || HasEq2 != 0)) begin : g_compact_unsupported
    $error("watkins_top: Compact = 1 needs Smoothing = 0 and HasEq2 = 0");
  end
  if (Lanes != 1 && (Compact == 0 || Lanes != 2)) begin : g_lanes_unsupported
    $error("watkins_top: Lanes must be 1, or 2 with Compact = 1 (the pipelined blocks take one fragment a clock)");
  end
  if (PhongNarrow != 0 && (Compact == 0 || Phong == 0)) begin : g_narrow_unsupported
    $error("watkins_top: PhongNarrow = 1 needs Compact = 1 and Phong = 1 (the pipelined Phong blocks take the model's formats)");
  end
  if (Lanes != 1 && Phong != 0) begin : g_lanes_phong_unsupported
    $error("watkins_top: Lanes = 2 needs Phong = 0 (the compact Phong blocks shade one fragment a beat)");
  end

  // ------------------------------------------------------------ frame control
  logic                frame_busy_q, ael_busy, start;
  logic [LineBits-1:0] width_q, height_q;
  watkins_pkg::rgb_t   background_q;
  logic                sparse_q, tie_submission_q;
  logic                smooth_on;  // this frame is smoothed (never, without a smoother)
  // The pixel stream before the output skid (u_pixel_skid).
  watkins_pkg::rgb_t   px_rgb;
  logic                px_covered, px_last, px_valid, px_ready;
  logic [LineBits-1:0] px_x, px_y;

  assign start = edge_valid_i && !frame_busy_q && !ael_busy;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      frame_busy_q <= 1'b0;
    end else if (start) begin
      frame_busy_q <= 1'b1;
    end else if (pixel_valid_o && pixel_ready_i && pixel_last_o) begin
      frame_busy_q <= 1'b0;
    end
  end

  always_ff @(posedge clk_i) begin
    if (start) begin
      width_q      <= width_i;
      height_q     <= height_i;
      background_q <= background_i;
      sparse_q     <= sparse_i;
      tie_submission_q <= tie_submission_i;
    end
  end

  // ------------------------------------------------------------ active edges
  // The three internal stage streams are readable from the Verilated model (the co-simulation
  // bench compares them item by item with the model's, testbench/stage_checker.hpp).
  logic [PolyIdBits-1:0]     ae_poly     /*verilator public_flat_rd*/;
  logic [MaterialIdBits-1:0] ae_material /*verilator public_flat_rd*/;
  logic [VectorBits-1:0]     ae_value    /*verilator public_flat_rd*/;
  logic                      ae_eol      /*verilator public_flat_rd*/;
  logic                      ae_valid    /*verilator public_flat_rd*/;
  logic                      ae_ready    /*verilator public_flat_rd*/;

  if (Compact != 0) begin : g_compact_active_edge_list
    compact_active_edge_list #(
      .MaxActiveEdges(MaxActiveEdges),
      .XBits         (XBits),
      .ZBits         (ZBits),
      .AttrBits      (AttrBits),
      .PolyIdBits    (PolyIdBits),
      .MaterialIdBits(MaterialIdBits),
      .EdgeIdBits    (EdgeIdBits),
      .EdgeOrder     (EdgeOrder)
    ) u_active_edge_list (
      .clk_i, .rst_ni,
      .start_i     (start),
      .height_i    (height_q),
      .busy_o      (ael_busy),
      .edge_i,
      .edge_eof_i,
      .edge_valid_i,
      .edge_ready_o,
      .out_poly_o  (ae_poly),
      .out_material_o(ae_material),
      .out_value_o (ae_value),
      .out_eol_o   (ae_eol),
      .out_valid_o (ae_valid),
      .out_ready_i (ae_ready),
      .overflow_o
    );
  end else begin : g_active_edge_list
    active_edge_list #(
      .MaxActiveEdges(MaxActiveEdges),
      .XBits         (XBits),
      .ZBits         (ZBits),
      .AttrBits      (AttrBits),
      .PolyIdBits    (PolyIdBits),
      .MaterialIdBits(MaterialIdBits),
      .EdgeIdBits    (EdgeIdBits),
      .EdgeOrder     (EdgeOrder)
    ) u_active_edge_list (
      .clk_i, .rst_ni,
      .start_i     (start),
      .height_i    (height_q),
      .busy_o      (ael_busy),
      .edge_i,
      .edge_eof_i,
      .edge_valid_i,
      .edge_ready_o,
      .out_poly_o  (ae_poly),
      .out_material_o(ae_material),
      .out_value_o (ae_value),
      .out_eol_o   (ae_eol),
      .out_valid_o (ae_valid),
      .out_ready_i (ae_ready),
      .overflow_o
    );
  end

  // ------------------------------------------------------------ segments
  logic [VectorBits-1:0]     sg_e        /*verilator public_flat_rd*/;
  logic [VectorBits-1:0]     sg_f        /*verilator public_flat_rd*/;
  logic                      sg_eol      /*verilator public_flat_rd*/;
  logic                      sg_valid    /*verilator public_flat_rd*/;
  logic                      sg_ready    /*verilator public_flat_rd*/;
  // The polygon id pairs edges here and breaks depth ties in the scanline buffer.
  logic [PolyIdBits-1:0]     sg_poly     /*verilator public_flat_rd*/;
  logic [MaterialIdBits-1:0] sg_material /*verilator public_flat_rd*/;

  if (Compact != 0) begin : g_compact_segment_former
    compact_segment_former #(
      .MaxActiveEdges(MaxActiveEdges),
      .VectorBits    (VectorBits),
      .PolyIdBits    (PolyIdBits),
      .MaterialIdBits(MaterialIdBits)
    ) u_segment_former (
      .clk_i, .rst_ni,
      .edge_poly_i (ae_poly),
      .edge_material_i(ae_material),
      .edge_value_i(ae_value),
      .edge_eol_i  (ae_eol),
      .edge_valid_i(ae_valid),
      .edge_ready_o(ae_ready),
      .seg_e_o     (sg_e),
      .seg_f_o     (sg_f),
      .seg_poly_o  (sg_poly),
      .seg_material_o(sg_material),
      .seg_eol_o   (sg_eol),
      .seg_valid_o (sg_valid),
      .seg_ready_i (sg_ready)
    );
  end else begin : g_segment_former
    segment_former #(
      .MaxActiveEdges(MaxActiveEdges),
      .VectorBits    (VectorBits),
      .PolyIdBits    (PolyIdBits),
      .MaterialIdBits(MaterialIdBits)
    ) u_segment_former (
      .clk_i, .rst_ni,
      .edge_poly_i (ae_poly),
      .edge_material_i(ae_material),
      .edge_value_i(ae_value),
      .edge_eol_i  (ae_eol),
      .edge_valid_i(ae_valid),
      .edge_ready_o(ae_ready),
      .seg_e_o     (sg_e),
      .seg_f_o     (sg_f),
      .seg_poly_o  (sg_poly),
      .seg_material_o(sg_material),
      .seg_eol_o   (sg_eol),
      .seg_valid_o (sg_valid),
      .seg_ready_i (sg_ready)
    );
  end

  // ------------------------------------------------------------ segment skid
  // A registered ready between the segment former and the interpolator (stream_skid, latency 0):
  // the interpolator's stall (its FIFO's room -> setup stall -> s0) ends at the skid's flops
  // instead of running on through the segment former's enable into the active-edge list's
  // stream advance and body-RAM read address, where it would be the sized Gouraud top's
  // critical path. A segment refused by s0 waits in the skid; the former sees it refused a clock
  // later. The compact top has none: its interpolator's seg_ready_o is a flop.
  logic [VectorBits-1:0]     sk_e, sk_f;
  logic [PolyIdBits-1:0]     sk_poly;
  logic [MaterialIdBits-1:0] sk_material;
  logic                      sk_eol, sk_valid, sk_ready;

  if (Compact != 0) begin : g_no_segment_skid
    assign {sk_e, sk_f, sk_poly, sk_material, sk_eol, sk_valid} =
        {sg_e, sg_f, sg_poly, sg_material, sg_eol, sg_valid};
    assign sg_ready = sk_ready;
  end else begin : g_segment_skid
    localparam int unsigned SkidBits = 2 * VectorBits + PolyIdBits + MaterialIdBits + 1;
    stream_skid #(
      .DataBits(SkidBits)
    ) u_segment_skid (
      .clk_i, .rst_ni,
      .data_i ({sg_e, sg_f, sg_poly, sg_material, sg_eol}),
      .valid_i(sg_valid),
      .ready_o(sg_ready),
      .data_o ({sk_e, sk_f, sk_poly, sk_material, sk_eol}),
      .valid_o(sk_valid),
      .ready_i(sk_ready)
    );
  end

  // ------------------------------------------------------------ fragments
  logic [LineBits-1:0]                    fr_x        /*verilator public_flat_rd*/;
  logic [DepthBits-1:0]                   fr_depth    /*verilator public_flat_rd*/;
  watkins_pkg::rgb_t                      fr_rgb      /*verilator public_flat_rd*/;
  logic [3*watkins_pkg::NormalInBits-1:0] fr_normal   /*verilator public_flat_rd*/;
  logic [3*AttrBits-1:0]                  fr_attr;     // the shade slots' words (HasEq2)
  logic [PolyIdBits-1:0]                  fr_poly     /*verilator public_flat_rd*/;
  logic [MaterialIdBits-1:0]              fr_material /*verilator public_flat_rd*/;
  logic                                   fr_eol      /*verilator public_flat_rd*/;
  logic                                   fr_valid    /*verilator public_flat_rd*/;
  logic                                   fr_ready    /*verilator public_flat_rd*/;
  // Lane 1 (Lanes = 2): the fragment at fr_x + 1 of the same span, after lane 0; 0 otherwise.
  logic                                   fr_pair     /*verilator public_flat_rd*/;
  logic [DepthBits-1:0]                   fr_depth1   /*verilator public_flat_rd*/;
  watkins_pkg::rgb_t                      fr_rgb1     /*verilator public_flat_rd*/;

  if (Compact != 0) begin : g_compact_segment_interpolator
    compact_segment_interpolator #(
      .XBits         (XBits),
      .XFracBits     (XFracBits),
      .ZBits         (ZBits),
      .ZFracBits     (DepthFracBits),
      .AttrBits      (AttrBits),
      .AttrFracBits  (AttrFracBits),
      .DepthBits     (DepthBits),
      .PolyIdBits    (PolyIdBits),
      .MaterialIdBits(MaterialIdBits),
      .AttrOut       (HasEq2 != 0 && Phong == 0),
      .Lanes         (Lanes)
    ) u_segment_interpolator (
      .clk_i, .rst_ni,
      .width_i     (width_q),
      .seg_e_i     (sk_e),
      .seg_f_i     (sk_f),
      .seg_poly_i  (sk_poly),
      .seg_material_i(sk_material),
      .seg_eol_i   (sk_eol),
      .seg_valid_i (sk_valid),
      .seg_ready_o (sk_ready),
      .frag_x_o    (fr_x),
      .frag_depth_o(fr_depth),
      .frag_rgb_o  (fr_rgb),
      .frag_normal_o(fr_normal),
      .frag_attr_o (fr_attr),
      .frag_poly_o (fr_poly),
      .frag_material_o(fr_material),
      .frag_eol_o  (fr_eol),
      .frag_valid_o(fr_valid),
      .frag_ready_i(fr_ready),
      .frag_pair_o (fr_pair),
      .frag_depth1_o(fr_depth1),
      .frag_rgb1_o (fr_rgb1)
    );
  end else begin : g_segment_interpolator
    assign fr_pair   = 1'b0;
    assign fr_depth1 = '0;
    assign fr_rgb1   = '0;
    segment_interpolator #(
      .XBits         (XBits),
      .XFracBits     (XFracBits),
      .ZBits         (ZBits),
      .ZFracBits     (DepthFracBits),
      .AttrBits      (AttrBits),
      .AttrFracBits  (AttrFracBits),
      .DepthBits     (DepthBits),
      .PolyIdBits    (PolyIdBits),
      .MaterialIdBits(MaterialIdBits),
      .AttrOut       (HasEq2 != 0 && Phong == 0)
    ) u_segment_interpolator (
      .clk_i, .rst_ni,
      .width_i     (width_q),
      .seg_e_i     (sk_e),
      .seg_f_i     (sk_f),
      .seg_poly_i  (sk_poly),
      .seg_material_i(sk_material),
      .seg_eol_i   (sk_eol),
      .seg_valid_i (sk_valid),
      .seg_ready_o (sk_ready),
      .frag_x_o    (fr_x),
      .frag_depth_o(fr_depth),
      .frag_rgb_o  (fr_rgb),
      .frag_normal_o(fr_normal),
      .frag_attr_o (fr_attr),
      .frag_poly_o (fr_poly),
      .frag_material_o(fr_material),
      .frag_eol_o  (fr_eol),
      .frag_valid_o(fr_valid),
      .frag_ready_i(fr_ready)
    );
  end

  // ------------------------------------------------------------ shading
  // sh_*: the fragments the depth test receives, shaded (the bench compares them, too).
  logic [LineBits-1:0]   sh_x     /*verilator public_flat_rd*/;
  logic [DepthBits-1:0]  sh_depth /*verilator public_flat_rd*/;
  logic [PolyIdBits-1:0] sh_poly  /*verilator public_flat_rd*/;
  watkins_pkg::rgb_t     sh_rgb   /*verilator public_flat_rd*/;
  logic                  sh_eol   /*verilator public_flat_rd*/;
  logic                  sh_valid /*verilator public_flat_rd*/;
  logic                  sh_ready /*verilator public_flat_rd*/;
  logic                  sh_ready_next;  // sh_ready on the next clock (the Phong pipes' lookahead)
  // Lane 1 (Lanes = 2, Gouraud): the fragment at sh_x + 1, after lane 0; 0 otherwise.
  logic                  sh_pair   /*verilator public_flat_rd*/;
  logic [DepthBits-1:0]  sh_depth1 /*verilator public_flat_rd*/;
  watkins_pkg::rgb_t     sh_rgb1   /*verilator public_flat_rd*/;

  if (Phong != 0) begin : g_phong
    localparam int unsigned UnitBits         = watkins_pkg::UnitBits;
    // {eol, x, depth, poly} rides along
    localparam int unsigned ShadePayloadBits = 1 + LineBits + DepthBits + PolyIdBits;
    logic [3*UnitBits-1:0] light_q, eye_q;
    always_ff @(posedge clk_i) begin
      if (start) begin
        light_q <= light_i;
        eye_q   <= eye_i;
      end
    end

    // Material table: flops (16 x 50 bits), read combinationally at the shader's take (the
    // normalizer's output register holds the material id until then).
    localparam int unsigned EntryBits = watkins_pkg::RgbBits + 2 * watkins_pkg::MaterialBits
                                      + watkins_pkg::ShininessBits;
    logic [EntryBits-1:0] material_q [2**MaterialIdBits];
    always_ff @(posedge clk_i) begin
      if (material_we_i)
        material_q[material_addr_i] <= {material_cp_i, material_d_i, material_w_i, material_n_i};
    end

    logic [3*UnitBits-1:0]       nm_unit;
    logic [MaterialIdBits-1:0]   nm_material;
    logic [ShadePayloadBits-1:0] nm_payload, sh_payload;
    logic                        nm_valid, nm_ready;
    // The shader's and the normalizer's ready are flops loaded a clock ahead (LookAhead):
    // otherwise the fragment queue's ready would cross both pipes into the interpolator's stepper
    // in one clock (the sized Phong top's critical path, most of it routing).
    logic                        nm_ready_next;  // nm_ready on the next clock
    /* verilator lint_off UNUSEDSIGNAL */
    logic                        nm_ready_next_unused;  // the interpolator's stall is not a flop
    /* verilator lint_on UNUSEDSIGNAL */
    logic                        nm_null_unused;  // a null normal already reads as (0,0,0): cos(i) = 0

    watkins_pkg::rgb_t                     m_cp;
    logic [watkins_pkg::MaterialBits-1:0]  m_d, m_w;
    logic [watkins_pkg::ShininessBits-1:0] m_n;
    assign {m_cp, m_d, m_w, m_n} = material_q[nm_material];

    // The compact blocks keep the pipelined ones' ports and handshakes (the header says why L
    // and E are stable for the compact shader).
    if (Compact != 0) begin : g_compact
      // PhongNarrow picks the narrow formats' blocks: the same ports, other values and clocks.
      if (PhongNarrow != 0) begin : g_narrow
        compact_normalizer_narrow #(
          .PayloadBits(MaterialIdBits + ShadePayloadBits),
          .LookAhead  (1'b1)
        ) u_normalizer (
          .clk_i, .rst_ni,
          .normal_i (fr_normal),
          .payload_i({fr_material, fr_eol, fr_x, fr_depth, fr_poly}),
          .valid_i  (fr_valid),
          .ready_o  (fr_ready),
          .ready_next_o(nm_ready_next_unused),
          .unit_o   (nm_unit),
          .null_o   (nm_null_unused),
          .payload_o({nm_material, nm_payload}),
          .valid_o  (nm_valid),
          .ready_i  (nm_ready),
          .ready_next_i(nm_ready_next)
        );

        compact_phong_shader_narrow #(
          .PayloadBits(ShadePayloadBits),
          .LookAhead  (1'b1)
        ) u_phong_shader (
          .clk_i, .rst_ni,
          .light_i    (light_q),
          .eye_i      (eye_q),
          .normal_i   (nm_unit),
          .cp_i       (m_cp),
          .d_i        (m_d),
          .w_i        (m_w),
          .shininess_i(m_n),
          .payload_i  (nm_payload),
          .valid_i    (nm_valid),
          .ready_o    (nm_ready),
          .rgb_o      (sh_rgb),
          .payload_o  (sh_payload),
          .valid_o    (sh_valid),
          .ready_i    (sh_ready),
          .ready_next_i(sh_ready_next),
          .ready_next_o(nm_ready_next)
        );
      end else begin : g_model
        compact_normalizer #(
          .PayloadBits(MaterialIdBits + ShadePayloadBits),
          .LookAhead  (1'b1)
        ) u_normalizer (
          .clk_i, .rst_ni,
          .normal_i (fr_normal),
          .payload_i({fr_material, fr_eol, fr_x, fr_depth, fr_poly}),
          .valid_i  (fr_valid),
          .ready_o  (fr_ready),
          .ready_next_o(nm_ready_next_unused),
          .unit_o   (nm_unit),
          .null_o   (nm_null_unused),
          .payload_o({nm_material, nm_payload}),
          .valid_o  (nm_valid),
          .ready_i  (nm_ready),
          .ready_next_i(nm_ready_next)
        );

        compact_phong_shader #(
          .PayloadBits(ShadePayloadBits),
          .LookAhead  (1'b1)
        ) u_phong_shader (
          .clk_i, .rst_ni,
          .light_i    (light_q),
          .eye_i      (eye_q),
          .normal_i   (nm_unit),
          .cp_i       (m_cp),
          .d_i        (m_d),
          .w_i        (m_w),
          .shininess_i(m_n),
          .payload_i  (nm_payload),
          .valid_i    (nm_valid),
          .ready_o    (nm_ready),
          .rgb_o      (sh_rgb),
          .payload_o  (sh_payload),
          .valid_o    (sh_valid),
          .ready_i    (sh_ready),
          .ready_next_i(sh_ready_next),
          .ready_next_o(nm_ready_next)
        );
      end
    end else begin : g_pipelined
      normalizer #(
        .PayloadBits(MaterialIdBits + ShadePayloadBits),
        .LookAhead  (1'b1)
      ) u_normalizer (
        .clk_i, .rst_ni,
        .normal_i (fr_normal),
        .payload_i({fr_material, fr_eol, fr_x, fr_depth, fr_poly}),
        .valid_i  (fr_valid),
        .ready_o  (fr_ready),
        .ready_next_o(nm_ready_next_unused),
        .unit_o   (nm_unit),
        .null_o   (nm_null_unused),
        .payload_o({nm_material, nm_payload}),
        .valid_o  (nm_valid),
        .ready_i  (nm_ready),
        .ready_next_i(nm_ready_next)
      );

      phong_shader #(
        .PayloadBits(ShadePayloadBits),
        .LookAhead  (1'b1)
      ) u_phong_shader (
        .clk_i, .rst_ni,
        .light_i    (light_q),
        .eye_i      (eye_q),
        .normal_i   (nm_unit),
        .cp_i       (m_cp),
        .d_i        (m_d),
        .w_i        (m_w),
        .shininess_i(m_n),
        .payload_i  (nm_payload),
        .valid_i    (nm_valid),
        .ready_o    (nm_ready),
        .rgb_o      (sh_rgb),
        .payload_o  (sh_payload),
        .valid_o    (sh_valid),
        .ready_i    (sh_ready),
        .ready_next_i(sh_ready_next),
        .ready_next_o(nm_ready_next)
      );
    end
    assign {sh_eol, sh_x, sh_depth, sh_poly} = sh_payload;
    assign {sh_pair, sh_depth1, sh_rgb1} = '0;
    logic unused_eq2;
    assign unused_eq2 = ^{eq2_i, fr_attr, fr_pair, fr_depth1, fr_rgb1};
    `WATKINS_ASSERT(a_phong_no_eq2, start |-> !eq2_i)
  end else if (HasEq2 != 0) begin : g_eq2
    // Gouraud with the eq. (2) divider: every fragment passes through it (the same latency in
    // both modes); eq2_q picks its quotient or the interpolated shade riding along.
    localparam int unsigned DividePayloadBits = 1 + LineBits + DepthBits + PolyIdBits + watkins_pkg::RgbBits;
    logic eq2_q;
    always_ff @(posedge clk_i) begin
      if (start) eq2_q <= eq2_i;
    end
    watkins_pkg::rgb_t dv_rgb, dv_interpolated;
    /* verilator lint_off UNUSEDSIGNAL */
    logic dv_ready_next_unused;  // the interpolator's stall is not a flop
    /* verilator lint_on UNUSEDSIGNAL */
    shade_divider #(
      .DepthBits   (DepthBits),
      .AttrBits    (AttrBits),
      .AttrFracBits(AttrFracBits),
      .RecipBits   (Eq2RecipBits),
      .PayloadBits (DividePayloadBits),
      .LookAhead   (1'b1)
    ) u_shade_divider (
      .clk_i, .rst_ni,
      .depth_i     (fr_depth),
      .num_i       (fr_attr),
      .payload_i   ({fr_eol, fr_x, fr_depth, fr_poly, fr_rgb}),
      .valid_i     (fr_valid),
      .ready_o     (fr_ready),
      .ready_next_o(dv_ready_next_unused),
      .rgb_o       (dv_rgb),
      .payload_o   ({sh_eol, sh_x, sh_depth, sh_poly, dv_interpolated}),
      .valid_o     (sh_valid),
      .ready_i     (sh_ready),
      .ready_next_i(sh_ready_next)
    );
    assign sh_rgb = eq2_q ? dv_rgb : dv_interpolated;
    assign {sh_pair, sh_depth1, sh_rgb1} = '0;
    logic unused_phong;
    assign unused_phong = ^{fr_normal, fr_material, light_i, eye_i, material_we_i, material_addr_i,
                            material_cp_i, material_d_i, material_w_i, material_n_i, fr_pair, fr_depth1,
                            fr_rgb1};
    `WATKINS_COVER(c_eq2_frame, eq2_q && sh_valid && sh_ready && !sh_eol)
  end else begin : g_gouraud
    assign sh_x     = fr_x;
    assign sh_depth = fr_depth;
    assign sh_poly  = fr_poly;
    assign sh_rgb   = fr_rgb;
    assign sh_eol   = fr_eol;
    assign sh_valid = fr_valid;
    assign fr_ready = sh_ready;
    assign sh_pair   = fr_pair;
    assign sh_depth1 = fr_depth1;
    assign sh_rgb1   = fr_rgb1;
    // The normal reading of the channels and the Phong inputs serve Phong = 1 only; the
    // attribute words and eq2_i the divider only.
    logic unused_phong;
    assign unused_phong = ^{fr_normal, fr_material, light_i, eye_i, material_we_i, material_addr_i,
                            material_cp_i, material_d_i, material_w_i, material_n_i, sh_ready_next,
                            fr_attr, eq2_i};
    `WATKINS_ASSERT(a_no_eq2, start |-> !eq2_i)
  end

  // ------------------------------------------------------------ fragment queue
  // Two fragments with a registered ready (stream_fifo): the scanline buffer refuses only a
  // marker waiting on its reader, and that decision (pixel_ready_i included) would otherwise
  // reach every stall enable upstream in one clock. Two entries keep one fragment per clock;
  // latency 1. In the Phong top the queue's next ready (ready_next_o, from the buffer's ready)
  // does reach the shader's and the normalizer's LookAhead enable flops, as their D input:
  // a path into two flops, not through every enable. The compact top keeps it too: there the
  // buffer's ready runs from its reader's column compare, and without the queue it would reach
  // the interpolator's stepper and head in the same clock (on the UP5K a 45.5 ns path: 22.0
  // MHz).
  // At Lanes = 2 an entry is a beat: lane 1's flag, depth and shade ride beside lane 0's.
  localparam int unsigned QueueBits = 1 + LineBits + DepthBits + PolyIdBits
                                    + watkins_pkg::RgbBits;
  watkins_pkg::rgb_t     q_rgb;
  logic [LineBits-1:0]   q_x;
  logic [DepthBits-1:0]  q_depth;
  logic [PolyIdBits-1:0] q_poly;
  logic                  q_eol, q_valid, q_ready;
  logic                  q_pair;
  logic [DepthBits-1:0]  q_depth1;
  watkins_pkg::rgb_t     q_rgb1;

  if (Lanes == 2) begin : g_frag_queue_pairs
    localparam int unsigned LaneBits = 1 + DepthBits + watkins_pkg::RgbBits;
    stream_fifo #(
      .DataBits(QueueBits + LaneBits),
      .Depth   (2)
    ) u_frag_queue (
      .clk_i, .rst_ni,
      .data_i ({sh_pair, sh_depth1, sh_rgb1, sh_eol, sh_x, sh_depth, sh_poly, sh_rgb}),
      .valid_i(sh_valid),
      .ready_o(sh_ready),
      .ready_next_o(sh_ready_next),
      .data_o ({q_pair, q_depth1, q_rgb1, q_eol, q_x, q_depth, q_poly, q_rgb}),
      .valid_o(q_valid),
      .ready_i(q_ready)
    );
  end else begin : g_frag_queue
    stream_fifo #(
      .DataBits(QueueBits),
      .Depth   (2)
    ) u_frag_queue (
      .clk_i, .rst_ni,
      .data_i ({sh_eol, sh_x, sh_depth, sh_poly, sh_rgb}),
      .valid_i(sh_valid),
      .ready_o(sh_ready),
      .ready_next_o(sh_ready_next),
      .data_o ({q_eol, q_x, q_depth, q_poly, q_rgb}),
      .valid_o(q_valid),
      .ready_i(q_ready)
    );
    assign {q_pair, q_depth1, q_rgb1} = '0;
    logic unused_lane1;
    assign unused_lane1 = ^{sh_pair, sh_depth1, sh_rgb1};
  end

  // ------------------------------------------------------------ visibility and pixels
  watkins_pkg::rgb_t   sb_rgb;
  logic                sb_covered, sb_last, sb_valid, sb_ready;
  logic [LineBits-1:0] sb_x, sb_y;

  if (Compact != 0) begin : g_compact_scanline_buffer
    compact_scanline_buffer #(
      .MaxWidth  (MaxWidth),
      .DepthBits (DepthBits),
      .PolyIdBits(PolyIdBits),
      .Lanes     (Lanes)
    ) u_scanline_buffer (
      .clk_i, .rst_ni,
      .width_i        (width_q),
      .height_i       (height_q),
      .background_i   (background_q),
      .sparse_i       (sparse_q && !smooth_on),
      .tie_submission_i(tie_submission_q),
      .frag_x_i       (q_x),
      .frag_depth_i   (q_depth),
      .frag_poly_i    (q_poly),
      .frag_rgb_i     (q_rgb),
      .frag_eol_i     (q_eol),
      .frag_valid_i   (q_valid),
      .frag_ready_o   (q_ready),
      .frag_pair_i    (q_pair),
      .frag_depth1_i  (q_depth1),
      .frag_rgb1_i    (q_rgb1),
      .pixel_rgb_o    (sb_rgb),
      .pixel_covered_o(sb_covered),
      .pixel_x_o      (sb_x),
      .pixel_y_o      (sb_y),
      .pixel_last_o   (sb_last),
      .pixel_valid_o  (sb_valid),
      .pixel_ready_i  (sb_ready)
    );
    `WATKINS_ASSERT(a_compact_full_frames, start |-> !sparse_i)
  end else begin : g_scanline_buffer
    logic unused_lane1_queue;  // Lanes = 1 here: the queue's lane 1 is constant
    assign unused_lane1_queue = ^{q_pair, q_depth1, q_rgb1};
    scanline_buffer #(
      .MaxWidth  (MaxWidth),
      .DepthBits (DepthBits),
      .PolyIdBits(PolyIdBits)
    ) u_scanline_buffer (
      .clk_i, .rst_ni,
      .width_i        (width_q),
      .height_i       (height_q),
      .background_i   (background_q),
      .sparse_i       (sparse_q && !smooth_on),
      .tie_submission_i(tie_submission_q),
      .frag_x_i       (q_x),
      .frag_depth_i   (q_depth),
      .frag_poly_i    (q_poly),
      .frag_rgb_i     (q_rgb),
      .frag_eol_i     (q_eol),
      .frag_valid_i   (q_valid),
      .frag_ready_o   (q_ready),
      .pixel_rgb_o    (sb_rgb),
      .pixel_covered_o(sb_covered),
      .pixel_x_o      (sb_x),
      .pixel_y_o      (sb_y),
      .pixel_last_o   (sb_last),
      .pixel_valid_o  (sb_valid),
      .pixel_ready_i  (sb_ready)
    );
  end

  // ------------------------------------------------------------ smoothing (per frame)
  if (Smoothing != 0) begin : g_smoother
    logic [watkins_pkg::SmoothWBits-1:0] smooth_w_q;
    always_ff @(posedge clk_i) begin
      if (start) smooth_w_q <= smooth_w_i;
    end
    assign smooth_on  = smooth_w_q != '0;

    watkins_pkg::rgb_t   sm_rgb;
    logic                sm_covered, sm_last, sm_valid, sm_ready;
    logic [LineBits-1:0] sm_x, sm_y;

    smoother #(
      .MaxWidth(MaxWidth)
    ) u_smoother (
      .clk_i, .rst_ni,
      .width_i  (width_q),
      .height_i (height_q),
      .w_i      (smooth_w_q),
      .rgb_i    (sb_rgb),
      .covered_i(sb_covered),
      .last_i   (sb_last),
      .valid_i  (sb_valid && smooth_on),
      .ready_o  (sm_ready),
      .rgb_o    (sm_rgb),
      .covered_o(sm_covered),
      .x_o      (sm_x),
      .y_o      (sm_y),
      .last_o   (sm_last),
      .valid_o  (sm_valid),
      .ready_i  (px_ready)
    );

    assign sb_ready   = smooth_on ? sm_ready : px_ready;
    assign px_rgb     = smooth_on ? sm_rgb : sb_rgb;
    assign px_covered = smooth_on ? sm_covered : sb_covered;
    assign px_x       = smooth_on ? sm_x : sb_x;
    assign px_y       = smooth_on ? sm_y : sb_y;
    assign px_last    = smooth_on ? sm_last : sb_last;
    assign px_valid   = smooth_on ? sm_valid : sb_valid;

    // The smoother is empty between frames: a frame without smoothing never sees its output.
    `WATKINS_ASSERT(a_smooth_idle, !smooth_on |-> !sm_valid)
    `WATKINS_COVER(c_smoothed_frame, smooth_on && px_valid && px_ready && px_last)
  end else begin : g_no_smoother
    assign smooth_on  = 1'b0;
    assign sb_ready   = px_ready;
    assign px_rgb     = sb_rgb;
    assign px_covered = sb_covered;
    assign px_x       = sb_x;
    assign px_y       = sb_y;
    assign px_last    = sb_last;
    assign px_valid   = sb_valid;
    // Nothing here could smooth the frame: its driver must not ask (the benches refuse first).
    logic unused_smooth_w;
    assign unused_smooth_w = ^smooth_w_i;
    `WATKINS_ASSERT(a_no_smoother, start |-> smooth_w_i == '0)
  end

  // ------------------------------------------------------------ pixel skid
  // A registered ready at the pixel output (stream_skid, latency 0): the consumer's ready ends
  // at the skid's flops instead of reaching the scanline buffer's read step and its fan-out (the
  // reader's word registers' enables: pixel_ready_i -> rd_step -> rx_word_q, mostly routing, a
  // critical path of the sized Phong top). A pixel refused waits
  // in the skid; the buffer sees it refused a clock later. With pixel_ready_i high it never
  // fills: no cycle changes (model/twins/cycle_model.hpp assumes no output stalls).
  localparam int unsigned PixelBits = watkins_pkg::RgbBits + 2 + 2 * LineBits;

  stream_skid #(
    .DataBits(PixelBits)
  ) u_pixel_skid (
    .clk_i, .rst_ni,
    .data_i ({px_rgb, px_covered, px_x, px_y, px_last}),
    .valid_i(px_valid),
    .ready_o(px_ready),
    .data_o ({pixel_rgb_o, pixel_covered_o, pixel_x_o, pixel_y_o, pixel_last_o}),
    .valid_o(pixel_valid_o),
    .ready_i(pixel_ready_i)
  );

  `WATKINS_ASSERT_HOLD(a_edge_hold, edge_valid_i, edge_ready_o, {edge_i, edge_eof_i})
  `WATKINS_ASSERT_HOLD(a_pixel_hold, pixel_valid_o, pixel_ready_i, {pixel_rgb_o, pixel_covered_o,
    pixel_last_o, pixel_x_o, pixel_y_o})
  `WATKINS_ASSERT(a_frame_size, start |-> width_i != '0 && width_i <= LineBits'(MaxWidth)
    && height_i != '0 && height_i <= LineBits'(watkins_pkg::MaxScreen))
  `WATKINS_ASSERT(a_overflow_sticky, overflow_o |=> overflow_o)
  `WATKINS_ASSERT(a_material_between_frames, material_we_i |-> !frame_busy_q)
  `WATKINS_COVER(c_frame_done, pixel_valid_o && pixel_ready_i && pixel_last_o)
endmodule

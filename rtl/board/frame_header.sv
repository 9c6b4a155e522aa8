// frame_header: a scene bank's header and material words into the frame pins and the material
// table's write port (docs/reference/board.md, "Scene banks"), for a frame player that reads the
// bank's words 0 .. 7 + 2^MaterialIdBits in order. In a clock with load_i, data_i is word step_i:
// words 0 .. 7 load their fields into registers on the clock edge (each field in the word's low
// bits: N, width, height, background, flags, light, eye, M); a material word (step_i >= 8) is
// written to table slot step_i - 8 in that clock when the slot is below M. Latency: a header
// field is on its output the clock after its word; the material port is combinational on the
// inputs. Registered: n_o, m_o and the frame pins.

module frame_header #(
  parameter int unsigned CountBits      = 10,  // N's bits
  parameter int unsigned StepBits       = 4,   // holds 8 + 2^MaterialIdBits - 1
  parameter int unsigned MaterialIdBits = 1,
  localparam int unsigned MBits    = MaterialIdBits + 1,
  localparam int unsigned LineBits = watkins_pkg::LineBits,
  localparam int unsigned UnitBits = watkins_pkg::UnitBits
) (
  input  logic                                  clk_i,
  input  logic                                  load_i,   // data_i is a header or material word
  input  logic [StepBits-1:0]                   step_i,   // which
  /* verilator lint_off UNUSEDSIGNAL */  // the bits above the widest field
  input  logic [63:0]                           data_i,   // the word's low 64 bits
  /* verilator lint_on UNUSEDSIGNAL */
  output logic [CountBits-1:0]                  n_o,      // edge records
  output logic [MBits-1:0]                      m_o,      // materials
  output logic [LineBits-1:0]                   width_o,
  output logic [LineBits-1:0]                   height_o,
  output watkins_pkg::rgb_t                     background_o,
  output logic                                  tie_submission_o,
  output logic                                  eq2_o,
  output logic [watkins_pkg::SmoothWBits-1:0]   smooth_w_o,
  output logic [3*UnitBits-1:0]                 light_o,
  output logic [3*UnitBits-1:0]                 eye_o,
  output logic                                  material_we_o,
  output logic [MaterialIdBits-1:0]             material_addr_o,
  output watkins_pkg::rgb_t                     material_cp_o,
  output logic [watkins_pkg::MaterialBits-1:0]  material_d_o,
  output logic [watkins_pkg::MaterialBits-1:0]  material_w_o,
  output logic [watkins_pkg::ShininessBits-1:0] material_n_o
);
  localparam int unsigned HeaderWords   = 8;
  localparam int unsigned RgbBits       = watkins_pkg::RgbBits;
  localparam int unsigned MaterialBits  = watkins_pkg::MaterialBits;
  localparam int unsigned ShininessBits = watkins_pkg::ShininessBits;

  always_ff @(posedge clk_i) begin
    if (load_i) begin
      unique case (step_i)
        StepBits'(0): n_o <= data_i[CountBits-1:0];
        StepBits'(1): width_o <= data_i[LineBits-1:0];
        StepBits'(2): height_o <= data_i[LineBits-1:0];
        StepBits'(3): background_o <= data_i[RgbBits-1:0];
        StepBits'(4): begin
          tie_submission_o <= data_i[0];
          eq2_o            <= data_i[1];
          smooth_w_o       <= data_i[8 +: watkins_pkg::SmoothWBits];
        end
        StepBits'(5): light_o <= data_i[3*UnitBits-1:0];
        StepBits'(6): eye_o <= data_i[3*UnitBits-1:0];
        StepBits'(7): m_o <= data_i[MBits-1:0];
        default: ;
      endcase
    end
  end

  // Material slot i (word 8 + i): {n, w, d, cp}, cp lowest; written when i < M.
  logic [StepBits-1:0] material_slot;
  assign material_slot   = step_i - StepBits'(HeaderWords);
  assign material_we_o   = load_i && step_i >= StepBits'(HeaderWords) && StepBits'(m_o) > material_slot;
  assign material_addr_o = material_slot[MaterialIdBits-1:0];
  assign material_cp_o   = data_i[RgbBits-1:0];
  assign material_d_o    = data_i[RgbBits +: MaterialBits];
  assign material_w_o    = data_i[RgbBits + MaterialBits +: MaterialBits];
  assign material_n_o    = data_i[RgbBits + 2 * MaterialBits +: ShininessBits];

  if (CountBits > 64) begin : g_check_count_bits
    $error("frame_header: CountBits must fit the word's low 64 bits");
  end
endmodule

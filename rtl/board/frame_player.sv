// frame_player: replays the active scene bank into watkins_top once per start pulse
// (docs/reference/board.md, "The frame schedule" and "Scene banks").
// On start_i (or a start that waited) it reads the bank's header (words 0..7) and 2^MaterialIdBits
// material words (8..), writing the first M of them to the material table, then offers the N edge
// records (words 8 + M ..) back to back and the EOF beat. StartToFirstBeat = 11 +
// 2^MaterialIdBits: a start pulse high in clock c offers the first edge beat (edge_valid_o high)
// in clock c + StartToFirstBeat (13 at MaterialIdBits 1). A start that comes while the previous
// frame is still in the pipeline (its stream not yet at EOF or frame_done_i not yet seen) waits
// until it has left, then runs the same fixed sequence. The edge records pass a 3-entry FIFO fed
// a read ahead, so edge_valid_o never drops between the first beat and the EOF beat (the FIFO
// holds at most 3 words read or in flight: it refills one per clock while the top takes one).
// Registered: the bank address, the frame pins (width_o .. eye_o, frame_header), the FIFO;
// edge_valid_o is a compare of registers; the material port is the bank's read register with a
// compare.

module frame_player #(
  parameter int unsigned BankWords      = 512,
  parameter int unsigned EdgeBits       = 64,  // the top's edge record, at least 64
  parameter int unsigned MaterialIdBits = 1,   // at least 1
  localparam int unsigned AddrBits = $clog2(BankWords),
  localparam int unsigned LineBits = watkins_pkg::LineBits,
  localparam int unsigned UnitBits = watkins_pkg::UnitBits
) (
  input  logic                                 clk_i,         // clk_pipe
  input  logic                                 rst_ni,        // active-low synchronous reset
  input  logic                                 start_i,       // one clock: play a frame
  input  logic                                 frame_done_i,  // the frame's last pixel was taken
  output logic                                 begin_o,       // one clock: a frame's sequence starts
  // The bank's read port (latency 1).
  output logic                                 rd_en_o,
  output logic [AddrBits-1:0]                  rd_addr_o,
  input  logic [EdgeBits-1:0]                  rd_data_i,
  // The frame pins, from the header.
  output logic [LineBits-1:0]                  width_o,
  output logic [LineBits-1:0]                  height_o,
  output watkins_pkg::rgb_t                    background_o,
  output logic                                 tie_submission_o,
  output logic                                 eq2_o,
  output logic [watkins_pkg::SmoothWBits-1:0]  smooth_w_o,
  output logic [3*UnitBits-1:0]                light_o,
  output logic [3*UnitBits-1:0]                eye_o,
  // The material table's write port.
  output logic                                 material_we_o,
  output logic [MaterialIdBits-1:0]            material_addr_o,
  output watkins_pkg::rgb_t                    material_cp_o,
  output logic [watkins_pkg::MaterialBits-1:0] material_d_o,
  output logic [watkins_pkg::MaterialBits-1:0] material_w_o,
  output logic [watkins_pkg::ShininessBits-1:0] material_n_o,
  // The edge stream.
  output logic [EdgeBits-1:0]                  edge_o,
  output logic                                 edge_eof_o,
  output logic                                 edge_valid_o,
  input  logic                                 edge_ready_i
);
  localparam int unsigned HeaderWords = 8;
  localparam int unsigned Materials   = 2 ** MaterialIdBits;
  localparam int unsigned LoadWords   = HeaderWords + Materials;  // header, then material slots
  localparam int unsigned CountBits   = AddrBits + 1;
  localparam int unsigned StepBits    = $clog2(LoadWords + 1);
  localparam int unsigned MBits       = MaterialIdBits + 1;
  localparam int unsigned FifoDepth   = 3;

  typedef enum logic [1:0] {Idle, Load, Edges} state_e;
  state_e state_q;

  logic                 pending_q;    // a start waits for the previous frame to leave
  logic                 in_flight_q;  // a frame is in the pipeline (from its start to its last pixel)
  logic [AddrBits-1:0]  addr_q;
  logic [StepBits-1:0]  step_q;       // load word being addressed
  logic                 go;

  // The read in flight: what rd_data_i holds this clock.
  logic                 rd_load_q;    // a header or material word
  logic [StepBits-1:0]  rd_step_q;    // which
  logic                 rd_edge_q;    // an edge record (pushed into the FIFO)

  // The header (frame_header).
  logic [CountBits-1:0] n_q;  // edge records
  logic [MBits-1:0]     m_q;  // materials

  // Edge records issued and taken, and the FIFO.
  logic [CountBits-1:0] issued_q, taken_q;
  logic [EdgeBits-1:0]  fifo_q [FifoDepth];
  logic [1:0]           wr_q, rd_q, cnt_q;
  logic                 issue, push, pop, eof_beat;

  assign go      = state_q == Idle && (start_i || pending_q) && !in_flight_q;
  assign begin_o = go;

  // Edge phase: read ahead while the FIFO has room for everything in flight.
  assign issue = state_q == Edges && issued_q != n_q &&
                 ({1'b0, cnt_q} + {2'b0, rd_edge_q}) < 3'(FifoDepth);
  assign rd_en_o   = state_q == Load || issue;
  assign rd_addr_o = addr_q;

  assign push     = rd_edge_q;
  assign eof_beat = state_q == Edges && taken_q == n_q && cnt_q == 2'd0;
  assign edge_valid_o = (state_q == Edges && cnt_q != 2'd0) || eof_beat;
  assign edge_eof_o   = eof_beat;
  assign edge_o       = fifo_q[rd_q];
  assign pop          = edge_valid_o && edge_ready_i && !eof_beat;

  function automatic logic [1:0] next_slot(logic [1:0] p);
    next_slot = (p == 2'(FifoDepth - 1)) ? 2'd0 : p + 2'd1;
  endfunction

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q     <= Idle;
      pending_q   <= 1'b0;
      in_flight_q <= 1'b0;
      rd_load_q   <= 1'b0;
      rd_edge_q   <= 1'b0;
      wr_q        <= '0;
      rd_q        <= '0;
      cnt_q       <= '0;
    end else begin
      if (start_i && !go) pending_q <= 1'b1;
      else if (go) pending_q <= 1'b0;
      if (go) in_flight_q <= 1'b1;
      else if (frame_done_i) in_flight_q <= 1'b0;

      rd_load_q <= state_q == Load;
      rd_edge_q <= issue;
      unique case (state_q)
        Idle: if (go) state_q <= Load;
        // The last load address goes out in clock LoadWords of the sequence; m_q (word 7) is
        // loaded by clock 10, so with LoadWords >= 10 the first edge address 8 + M is ready.
        Load: if (step_q == StepBits'(LoadWords - 1)) state_q <= Edges;
        Edges: if (eof_beat && edge_ready_i) state_q <= Idle;
        default: state_q <= Idle;
      endcase

      if (push) wr_q <= next_slot(wr_q);
      if (pop) rd_q <= next_slot(rd_q);
      cnt_q <= cnt_q + {1'b0, push} - {1'b0, pop};
    end
  end

  always_ff @(posedge clk_i) begin
    rd_step_q <= step_q;
    if (go) begin
      addr_q   <= '0;
      step_q   <= '0;
      issued_q <= '0;
      taken_q  <= '0;
    end else if (state_q == Load) begin
      step_q <= step_q + 1'b1;
      addr_q <= (step_q == StepBits'(LoadWords - 1)) ? AddrBits'(HeaderWords) + AddrBits'(m_q) : addr_q + 1'b1;
    end else if (issue) begin
      addr_q   <= addr_q + 1'b1;
      issued_q <= issued_q + 1'b1;
    end
    if (pop) taken_q <= taken_q + 1'b1;
    if (push) fifo_q[wr_q] <= rd_data_i;
  end

  // The header's fields and the material port.
  frame_header #(.CountBits(CountBits), .StepBits(StepBits), .MaterialIdBits(MaterialIdBits)) u_header (
    .clk_i           (clk_i),
    .load_i          (rd_load_q),
    .step_i          (rd_step_q),
    .data_i          (rd_data_i[63:0]),
    .n_o             (n_q),
    .m_o             (m_q),
    .width_o         (width_o),
    .height_o        (height_o),
    .background_o    (background_o),
    .tie_submission_o(tie_submission_o),
    .eq2_o           (eq2_o),
    .smooth_w_o      (smooth_w_o),
    .light_o         (light_o),
    .eye_o           (eye_o),
    .material_we_o   (material_we_o),
    .material_addr_o (material_addr_o),
    .material_cp_o   (material_cp_o),
    .material_d_o    (material_d_o),
    .material_w_o    (material_w_o),
    .material_n_o    (material_n_o)
  );

  // Elaboration checks: the fields fit the word, and the load is long enough for M.
  if (EdgeBits < 64) begin : g_check_edge_bits
    $error("frame_player: EdgeBits < 64 cannot hold the header's words");
  end
  if (MaterialIdBits < 1) begin : g_check_material_bits
    $error("frame_player: MaterialIdBits must be at least 1");
  end
endmodule

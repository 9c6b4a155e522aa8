// spram_frame_player: replays the iCEBreaker's scene bank (spram_scene_bank: 64 bits a read) into
// watkins_top once per start pulse (docs/reference/board.md, "iCEBreaker"). Bank word k (the
// layout of "Scene banks") is SPRAM words Parts k .. Parts k + Parts - 1, Parts = ceil(EdgeBits /
// 64), its low 64 bits first. On start_i (or a start that waited) it reads the header (words
// 0 .. 7) and the 2^MaterialIdBits material words (8 ..), writing the first M to the material
// table (frame_header), then offers the N edge records (words 8 + M ..) and the EOF beat. A beat
// is fetched (Parts reads, the EOF beat none but the same clocks) into an output register while
// the one before it is offered: beat k + 1 is offered from clock max(O_k + Parts, T_k + 2) on, O_k
// the clock beat k is first offered and T_k the clock it is taken, and held until taken; the first
// beat at StartToFirstBeat = 10 + 2^MaterialIdBits + Parts clocks after the start pulse (15 at
// MaterialIdBits 1 and Parts 3). A start that comes while the previous frame is still in the
// pipeline (its stream not yet at EOF or frame_done_i not yet seen) waits until it has left, then
// runs the same sequence. Registered: the read address and enable's inputs, the frame pins,
// edge_o, edge_eof_o and edge_valid_o; the material port is the read data with a compare.
// edge_ready_i reaches the state and valid_q only, as their last logic (one pick of two).

module spram_frame_player #(
  parameter int unsigned BankWords      = 512,  // bank words the SPRAMs hold, a power of two
  parameter int unsigned EdgeBits       = 64,   // the top's edge record, at least 64
  parameter int unsigned MaterialIdBits = 1,    // at least 1
  localparam int unsigned SpramAddrBits = 14,
  localparam int unsigned LineBits      = watkins_pkg::LineBits,
  localparam int unsigned UnitBits      = watkins_pkg::UnitBits
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,        // active-low synchronous reset
  input  logic                                 start_i,       // one clock: play a frame
  input  logic                                 frame_done_i,  // the frame's last pixel was taken
  output logic                                 begin_o,       // one clock: a frame's sequence starts
  // The bank's read port (latency 1, holding between reads).
  output logic                                 rd_en_o,
  output logic [SpramAddrBits-1:0]             rd_addr_o,
  input  logic [63:0]                          rd_data_i,
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
  localparam int unsigned Parts       = (EdgeBits + 63) / 64;
  localparam int unsigned HeaderWords = 8;
  localparam int unsigned Materials   = 2 ** MaterialIdBits;
  localparam int unsigned LoadWords   = HeaderWords + Materials;  // header, then material slots
  localparam int unsigned CountBits   = $clog2(BankWords) + 1;
  localparam int unsigned StepBits    = $clog2(LoadWords + 1);
  localparam int unsigned MBits       = MaterialIdBits + 1;
  localparam int unsigned PartBits    = $clog2(Parts + 1);
  localparam int unsigned AsmBits     = Parts > 1 ? 64 * (Parts - 1) : 1;
  localparam logic        FirstNotLast = Parts > 1;  // a record's first read is not its last

  typedef enum logic [1:0] {Idle, Load, Edges} state_e;
  // A plain word so the next state can be picked by AND and OR (yosys 0.23 has no enum casts).
  logic [1:0] state_q;

  logic                     pending_q;    // a start waits for the previous frame to leave
  logic                     in_flight_q;  // a frame is in the pipeline (from its start to its last pixel)
  logic [SpramAddrBits-1:0] addr_q;
  logic [StepBits-1:0]      step_q;       // load word being addressed
  logic                     go;

  // The read in flight: what rd_data_i holds this clock.
  logic                     rd_load_q;    // a header or material word
  logic [StepBits-1:0]      rd_step_q;    // which
  logic                     rd_shift_q;   // a record's part other than its last

  logic [CountBits-1:0]     n_q;          // edge records
  logic [MBits-1:0]         m_q;          // materials

  // The fetch: the beat being fetched, its reads still to issue, its parts so far.
  logic                     fresh_q;      // the first clock of the edge phase
  logic [CountBits-1:0]     left_q;       // records whose fetch has not begun
  logic                     over_q;       // the EOF beat's fetch has begun: nothing more to fetch
  logic                     feof_q;       // the beat being fetched is the EOF beat
  logic [PartBits-1:0]      reads_q;      // its reads after the first still to issue
  logic                     have_q;       // it is complete: its last part on rd_data_i
  logic [AsmBits-1:0]       asm_q;        // its parts before the last, the first lowest
  // The beat offered.
  logic                     valid_q, eof_q;
  logic [EdgeBits-1:0]      edge_q;
  logic                     fetch, load, record_read;
  /* verilator lint_off UNUSEDSIGNAL */  // the bits past the record in its last part
  logic [64*Parts-1:0]      whole;        // the fetched beat: its last part on rd_data_i
  /* verilator lint_on UNUSEDSIGNAL */

  assign go      = state_q == Idle && (start_i || pending_q) && !in_flight_q;
  assign begin_o = go;

  // A beat's fetch begins in the edge phase's first clock and in the clock the beat before it
  // moves into the output register (its parts left the assembly register and rd_data_i).
  assign load        = state_q == Edges && have_q && !valid_q;
  assign fetch       = state_q == Edges && !over_q && (fresh_q || load);
  assign record_read = (fetch && left_q != '0) || (reads_q != '0 && !feof_q);
  assign rd_en_o     = state_q == Load || record_read;
  assign rd_addr_o   = addr_q;

  // The registers edge_ready_i decides (the state and valid_q) get their next value for either
  // value of it (r1: ready, r0: not) from registers, and edge_ready_i picks one as their last
  // logic: the compact active-edge list's ready is combinational, from its key compare. The pairs
  // are kept as nets and picked by AND and OR, so synthesis neither folds the pick into their
  // earlier levels nor makes edge_ready_i a flip-flop enable.
  (* keep *) logic [1:0] state_r0, state_r1;
  (* keep *) logic       valid_r0, valid_r1;
  always_comb begin
    state_r0 = state_q;
    unique case (state_q)
      Idle: if (go) state_r0 = Load;
      // The last load address goes out in clock LoadWords of the sequence; m_q (word 7) is
      // loaded by clock 10, so with LoadWords >= 10 the first record's address is ready.
      Load: if (step_q == StepBits'(LoadWords - 1)) state_r0 = Edges;
      Edges: ;
      default: state_r0 = Idle;
    endcase
    // Taken, the EOF beat ends the sequence.
    state_r1 = (state_q == Edges && valid_q && eof_q) ? Idle : state_r0;
    valid_r0 = load || valid_q;
    valid_r1 = load;  // loads only when empty; an offered beat is taken
  end

  if (Parts > 1) begin : g_parts
    assign whole = {rd_data_i, asm_q};
  end else begin : g_one_part
    /* verilator lint_off UNUSEDSIGNAL */
    logic unused_asm;
    /* verilator lint_on UNUSEDSIGNAL */
    assign unused_asm = ^asm_q;
    assign whole = rd_data_i;
  end

  // The records start at bank word 8 + M: SPRAM word Parts (8 + M).
  function automatic logic [SpramAddrBits-1:0] record_base(logic [MBits-1:0] m);
    record_base = SpramAddrBits'(Parts * HeaderWords);
    for (int i = 0; i < Parts; i++) record_base = record_base + SpramAddrBits'(m);
  endfunction

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q     <= Idle;
      pending_q   <= 1'b0;
      in_flight_q <= 1'b0;
      rd_load_q   <= 1'b0;
      rd_shift_q  <= 1'b0;
      fresh_q     <= 1'b0;
      over_q      <= 1'b0;
      reads_q     <= '0;
      have_q      <= 1'b0;
      valid_q     <= 1'b0;
    end else begin
      if (start_i && !go) pending_q <= 1'b1;
      else if (go) pending_q <= 1'b0;
      if (go) in_flight_q <= 1'b1;
      else if (frame_done_i) in_flight_q <= 1'b0;

      rd_load_q  <= state_q == Load;
      rd_shift_q <= record_read && (fetch ? FirstNotLast : reads_q != PartBits'(1));
      fresh_q    <= state_q == Load && step_q == StepBits'(LoadWords - 1);
      state_q <= ({2{edge_ready_i}} & state_r1) | ({2{!edge_ready_i}} & state_r0);

      if (go) over_q <= 1'b0;
      else if (fetch && left_q == '0) over_q <= 1'b1;
      if (fetch) reads_q <= PartBits'(Parts - 1);
      else if (reads_q != '0) reads_q <= reads_q - 1'b1;
      if (load) have_q <= 1'b0;
      else if (fetch ? !FirstNotLast : reads_q == PartBits'(1)) have_q <= 1'b1;
      valid_q <= (edge_ready_i && valid_r1) || (!edge_ready_i && valid_r0);
    end
  end

  always_ff @(posedge clk_i) begin
    rd_step_q <= step_q;
    if (go) begin
      addr_q <= '0;
      step_q <= '0;
    end else if (state_q == Load) begin
      step_q <= step_q + 1'b1;
      addr_q <= (step_q == StepBits'(LoadWords - 1)) ? record_base(m_q) : addr_q + SpramAddrBits'(Parts);
    end else if (record_read) begin
      addr_q <= addr_q + 1'b1;
    end
    if (state_q == Load) left_q <= n_q;  // N is loaded by the load's third clock
    if (fetch) begin
      feof_q <= left_q == '0;
      if (left_q != '0) left_q <= left_q - 1'b1;
    end
    if (rd_shift_q) asm_q <= Parts > 1 ? AsmBits'({rd_data_i, asm_q} >> 64) : asm_q;
    if (load) begin
      edge_q <= whole[EdgeBits-1:0];
      eof_q  <= feof_q;
    end
  end

  assign edge_o       = edge_q;
  assign edge_eof_o   = eof_q;
  assign edge_valid_o = valid_q;

  frame_header #(.CountBits(CountBits), .StepBits(StepBits), .MaterialIdBits(MaterialIdBits)) u_header (
    .clk_i           (clk_i),
    .load_i          (rd_load_q),
    .step_i          (rd_step_q),
    .data_i          (rd_data_i),
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

  // Elaboration checks: the fields fit the word, the bank fits the SPRAMs, the load is long enough.
  if (EdgeBits < 64) begin : g_check_edge_bits
    $error("spram_frame_player: EdgeBits < 64 cannot hold the header's words");
  end
  if (MaterialIdBits < 1) begin : g_check_material_bits
    $error("spram_frame_player: MaterialIdBits must be at least 1");
  end
  if (BankWords * Parts > 16384) begin : g_check_bank_words
    $error("spram_frame_player: BankWords * ceil(EdgeBits / 64) must be at most 16,384 SPRAM words");
  end
endmodule

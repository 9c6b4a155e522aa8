// formal_stream.svh: the handshake rules every formal harness of tests/formal states, written
// once. Read by yosys 0.23 (`read_verilog -sv -formal`) only: immediate assert/assume in clocked
// and combinational blocks; scripts/formal runs the proofs (sat -tempinduct).
// A harness declares `logic past_q` (0 in the first clock, then 1) with FORMAL_PAST, resets its
// DUT in the first clock, and leaves rst_ni free afterwards: a reset may come at any clock.
`ifndef FORMAL_STREAM_SVH
`define FORMAL_STREAM_SVH

// past_q: a previous clock exists, so $past is meaningful; the first clock is a reset.
`define FORMAL_PAST \
  logic past_q; \
  initial past_q = 1'b0; \
  always_ff @(posedge clk_i) past_q <= 1'b1; \
  always_comb if (!past_q) assume (!rst_ni);

// A LookAhead consumer (stall_pipe's LookAhead = 1): ready_i is what ready_next_i said a clock
// before. ahead: the harness's LookAhead parameter (0: ready_next_i is unconstrained and unread).
`define FORMAL_READY_AHEAD(ahead) \
  logic ready_next_q; \
  always_ff @(posedge clk_i) ready_next_q <= ready_next_i; \
  always_comb if ((ahead) && past_q) assume (ready_i == ready_next_q);

// The environment obeys valid/ready on an input stream: a beat offered and not taken is offered
// again the next clock, unchanged (unless a reset came in between). Written with explicit
// registers and an immediate assume in always_comb, so it constrains the same clock it speaks of:
// yosys samples an assume inside a clocked block one clock late, which would leave the last step
// of every base case unconstrained. name prefixes the two registers.
`define FORMAL_ASSUME_HOLD(name, valid, ready, data) \
  logic name``_held_q; \
  logic [$bits(data)-1:0] name``_data_q; \
  always_ff @(posedge clk_i) begin \
    name``_held_q <= rst_ni && (valid) && !(ready); \
    name``_data_q <= data; \
  end \
  always_comb if (past_q && name``_held_q) assume ((valid) && (data) == name``_data_q);

// The stage obeys valid/ready on its output stream, whatever the back-pressure: a beat offered
// and not taken is offered again the next clock, unchanged.
`define FORMAL_ASSERT_HOLD(name, valid, ready, data) \
  logic name``_held_q; \
  logic [$bits(data)-1:0] name``_data_q; \
  always_ff @(posedge clk_i) begin \
    name``_held_q <= rst_ni && (valid) && !(ready); \
    name``_data_q <= data; \
  end \
  always_comb if (past_q && name``_held_q) assert ((valid) && (data) == name``_data_q);

// Beats taken on a stream since the last reset, modulo 2^bits: the sequence number the next beat
// carries (the harnesses tag each input beat with it, and expect it back at the output).
`define FORMAL_COUNT(name, bits, valid, ready) \
  logic [(bits)-1:0] name; \
  always_ff @(posedge clk_i) \
    if (!rst_ni) name <= '0; \
    else if ((valid) && (ready)) name <= name + 1'b1;

// A probe of word k of a register array or RAM inside the harness's DUT: a hierconn wire (flatten
// connects it to the register of that name, e.g. \u_dut.g_ram.mem[3] ), packed into vec.
`define FORMAL_WORD(vec, bits, k, name) \
  (* hierconn *) logic [(bits)-1:0] name ; \
  assign vec[(k)*(bits) +: (bits)] = name ;

// A stage that passes a payload through untouched, checked with tags: the environment tags each
// input beat with its sequence number (payload_i == n_in_q); each output beat must carry the next
// one expected (nothing dropped, duplicated or reordered), ready_o = ready_i || !valid_o, and the
// beats inside stay within capacity. Names: valid_i, ready_o, payload_i, valid_o, ready_i,
// payload_o, n_in_q, n_out_q (FORMAL_COUNT), PayloadBits.
`define FORMAL_TAGGED_STAGE(capacity) \
  always_comb begin \
    if (valid_i) assume (payload_i == n_in_q); \
    if (rst_ni) begin \
      if (valid_o) assert (payload_o == n_out_q); \
      assert (ready_o == (ready_i || !valid_o)); \
      assert (PayloadBits'(n_in_q - n_out_q) <= PayloadBits'(capacity)); \
    end \
  end

// The probes of a DUT whose payload rides a stall_pipe with PayloadRam (u_dut.u_pipe) and the
// stall u_dut.en: declares the hierconn wires and the packed `mem` that FORMAL_WORD fills with the
// RAM's Depth words (one line per word: yosys names each word's register apart).
`define FORMAL_RAM_PIPE_PROBES \
  (* hierconn *) logic                   \u_dut.en ; \
  (* hierconn *) logic [Stages-1:0]      \u_dut.u_pipe.valid_q ; \
  (* hierconn *) logic [PointerBits-1:0] \u_dut.u_pipe.g_ram.wr_q ; \
  (* hierconn *) logic [PointerBits-1:0] \u_dut.u_pipe.g_ram.rd_q ; \
  (* hierconn *) logic [PointerBits-1:0] \u_dut.u_pipe.g_ram.rd_inc_q ; \
  (* hierconn *) logic [PayloadBits-1:0] \u_dut.u_pipe.g_ram.out_q ; \
  logic [Depth*PayloadBits-1:0] mem;

// stall_pipe_checker over those probes: the tags in flight, stage by stage. rd_inc_q = rd_q + 1
// (as stall_pipe_formal states it): without it the read address a clock ahead is free in the
// induction step, which then needs length 2 (twice the SAT problem).
`define FORMAL_RAM_PIPE_CHECK \
  always_comb if (rst_ni) assert (\u_dut.u_pipe.g_ram.rd_inc_q == \u_dut.u_pipe.g_ram.rd_q + 1'b1); \
  stall_pipe_checker #(.Stages(Stages), .PayloadBits(PayloadBits), .PayloadRam(1'b1)) u_check ( \
    .clk_i, \
    .rst_ni, \
    .en_i        (\u_dut.en ), \
    .n_in_i      (n_in_q), \
    .n_out_i     (n_out_q), \
    .valid_q_i   (\u_dut.u_pipe.valid_q ), \
    .shift_q_i   ('0), \
    .wr_q_i      (\u_dut.u_pipe.g_ram.wr_q ), \
    .rd_q_i      (\u_dut.u_pipe.g_ram.rd_q ), \
    .mem_i       (mem), \
    .out_q_i     (\u_dut.u_pipe.g_ram.out_q ) \
  );

// The RAM's words into `mem`, for Depth = 16 (words 0..15) and 32 (then 16..31 as well): one
// probe per word, since yosys names each word's register apart.
`define FORMAL_RAM_PIPE_WORDS_16 \
  `FORMAL_WORD(mem, PayloadBits, 0, \u_dut.u_pipe.g_ram.mem[0] ) \
  `FORMAL_WORD(mem, PayloadBits, 1, \u_dut.u_pipe.g_ram.mem[1] ) \
  `FORMAL_WORD(mem, PayloadBits, 2, \u_dut.u_pipe.g_ram.mem[2] ) \
  `FORMAL_WORD(mem, PayloadBits, 3, \u_dut.u_pipe.g_ram.mem[3] ) \
  `FORMAL_WORD(mem, PayloadBits, 4, \u_dut.u_pipe.g_ram.mem[4] ) \
  `FORMAL_WORD(mem, PayloadBits, 5, \u_dut.u_pipe.g_ram.mem[5] ) \
  `FORMAL_WORD(mem, PayloadBits, 6, \u_dut.u_pipe.g_ram.mem[6] ) \
  `FORMAL_WORD(mem, PayloadBits, 7, \u_dut.u_pipe.g_ram.mem[7] ) \
  `FORMAL_WORD(mem, PayloadBits, 8, \u_dut.u_pipe.g_ram.mem[8] ) \
  `FORMAL_WORD(mem, PayloadBits, 9, \u_dut.u_pipe.g_ram.mem[9] ) \
  `FORMAL_WORD(mem, PayloadBits, 10, \u_dut.u_pipe.g_ram.mem[10] ) \
  `FORMAL_WORD(mem, PayloadBits, 11, \u_dut.u_pipe.g_ram.mem[11] ) \
  `FORMAL_WORD(mem, PayloadBits, 12, \u_dut.u_pipe.g_ram.mem[12] ) \
  `FORMAL_WORD(mem, PayloadBits, 13, \u_dut.u_pipe.g_ram.mem[13] ) \
  `FORMAL_WORD(mem, PayloadBits, 14, \u_dut.u_pipe.g_ram.mem[14] ) \
  `FORMAL_WORD(mem, PayloadBits, 15, \u_dut.u_pipe.g_ram.mem[15] )

`define FORMAL_RAM_PIPE_WORDS_32 \
  `FORMAL_RAM_PIPE_WORDS_16 \
  `FORMAL_WORD(mem, PayloadBits, 16, \u_dut.u_pipe.g_ram.mem[16] ) \
  `FORMAL_WORD(mem, PayloadBits, 17, \u_dut.u_pipe.g_ram.mem[17] ) \
  `FORMAL_WORD(mem, PayloadBits, 18, \u_dut.u_pipe.g_ram.mem[18] ) \
  `FORMAL_WORD(mem, PayloadBits, 19, \u_dut.u_pipe.g_ram.mem[19] ) \
  `FORMAL_WORD(mem, PayloadBits, 20, \u_dut.u_pipe.g_ram.mem[20] ) \
  `FORMAL_WORD(mem, PayloadBits, 21, \u_dut.u_pipe.g_ram.mem[21] ) \
  `FORMAL_WORD(mem, PayloadBits, 22, \u_dut.u_pipe.g_ram.mem[22] ) \
  `FORMAL_WORD(mem, PayloadBits, 23, \u_dut.u_pipe.g_ram.mem[23] ) \
  `FORMAL_WORD(mem, PayloadBits, 24, \u_dut.u_pipe.g_ram.mem[24] ) \
  `FORMAL_WORD(mem, PayloadBits, 25, \u_dut.u_pipe.g_ram.mem[25] ) \
  `FORMAL_WORD(mem, PayloadBits, 26, \u_dut.u_pipe.g_ram.mem[26] ) \
  `FORMAL_WORD(mem, PayloadBits, 27, \u_dut.u_pipe.g_ram.mem[27] ) \
  `FORMAL_WORD(mem, PayloadBits, 28, \u_dut.u_pipe.g_ram.mem[28] ) \
  `FORMAL_WORD(mem, PayloadBits, 29, \u_dut.u_pipe.g_ram.mem[29] ) \
  `FORMAL_WORD(mem, PayloadBits, 30, \u_dut.u_pipe.g_ram.mem[30] ) \
  `FORMAL_WORD(mem, PayloadBits, 31, \u_dut.u_pipe.g_ram.mem[31] )

// Depth = 64 (a pipe of 32 to 63 stages): words 32..63 as well.
`define FORMAL_RAM_PIPE_WORDS_64 \
  `FORMAL_RAM_PIPE_WORDS_32 \
  `FORMAL_WORD(mem, PayloadBits, 32, \u_dut.u_pipe.g_ram.mem[32] ) \
  `FORMAL_WORD(mem, PayloadBits, 33, \u_dut.u_pipe.g_ram.mem[33] ) \
  `FORMAL_WORD(mem, PayloadBits, 34, \u_dut.u_pipe.g_ram.mem[34] ) \
  `FORMAL_WORD(mem, PayloadBits, 35, \u_dut.u_pipe.g_ram.mem[35] ) \
  `FORMAL_WORD(mem, PayloadBits, 36, \u_dut.u_pipe.g_ram.mem[36] ) \
  `FORMAL_WORD(mem, PayloadBits, 37, \u_dut.u_pipe.g_ram.mem[37] ) \
  `FORMAL_WORD(mem, PayloadBits, 38, \u_dut.u_pipe.g_ram.mem[38] ) \
  `FORMAL_WORD(mem, PayloadBits, 39, \u_dut.u_pipe.g_ram.mem[39] ) \
  `FORMAL_WORD(mem, PayloadBits, 40, \u_dut.u_pipe.g_ram.mem[40] ) \
  `FORMAL_WORD(mem, PayloadBits, 41, \u_dut.u_pipe.g_ram.mem[41] ) \
  `FORMAL_WORD(mem, PayloadBits, 42, \u_dut.u_pipe.g_ram.mem[42] ) \
  `FORMAL_WORD(mem, PayloadBits, 43, \u_dut.u_pipe.g_ram.mem[43] ) \
  `FORMAL_WORD(mem, PayloadBits, 44, \u_dut.u_pipe.g_ram.mem[44] ) \
  `FORMAL_WORD(mem, PayloadBits, 45, \u_dut.u_pipe.g_ram.mem[45] ) \
  `FORMAL_WORD(mem, PayloadBits, 46, \u_dut.u_pipe.g_ram.mem[46] ) \
  `FORMAL_WORD(mem, PayloadBits, 47, \u_dut.u_pipe.g_ram.mem[47] ) \
  `FORMAL_WORD(mem, PayloadBits, 48, \u_dut.u_pipe.g_ram.mem[48] ) \
  `FORMAL_WORD(mem, PayloadBits, 49, \u_dut.u_pipe.g_ram.mem[49] ) \
  `FORMAL_WORD(mem, PayloadBits, 50, \u_dut.u_pipe.g_ram.mem[50] ) \
  `FORMAL_WORD(mem, PayloadBits, 51, \u_dut.u_pipe.g_ram.mem[51] ) \
  `FORMAL_WORD(mem, PayloadBits, 52, \u_dut.u_pipe.g_ram.mem[52] ) \
  `FORMAL_WORD(mem, PayloadBits, 53, \u_dut.u_pipe.g_ram.mem[53] ) \
  `FORMAL_WORD(mem, PayloadBits, 54, \u_dut.u_pipe.g_ram.mem[54] ) \
  `FORMAL_WORD(mem, PayloadBits, 55, \u_dut.u_pipe.g_ram.mem[55] ) \
  `FORMAL_WORD(mem, PayloadBits, 56, \u_dut.u_pipe.g_ram.mem[56] ) \
  `FORMAL_WORD(mem, PayloadBits, 57, \u_dut.u_pipe.g_ram.mem[57] ) \
  `FORMAL_WORD(mem, PayloadBits, 58, \u_dut.u_pipe.g_ram.mem[58] ) \
  `FORMAL_WORD(mem, PayloadBits, 59, \u_dut.u_pipe.g_ram.mem[59] ) \
  `FORMAL_WORD(mem, PayloadBits, 60, \u_dut.u_pipe.g_ram.mem[60] ) \
  `FORMAL_WORD(mem, PayloadBits, 61, \u_dut.u_pipe.g_ram.mem[61] ) \
  `FORMAL_WORD(mem, PayloadBits, 62, \u_dut.u_pipe.g_ram.mem[62] ) \
  `FORMAL_WORD(mem, PayloadBits, 63, \u_dut.u_pipe.g_ram.mem[63] )

`endif

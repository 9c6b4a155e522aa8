// watkins_assert.svh: the assertion macros of every rtl/ module, so the valid/ready rule is
// written once. Each expands to a named, clocked SVA statement on the module's clk_i, disabled
// while rst_ni is low. Under SYNTHESIS they expand to nothing: yosys 0.23 reads no clocked SVA;
// under WATKINS_NO_ASSERT too (the Verilated speed build: no --assert, so no assertion-only
// probes evaluated every clock either).
// Consumers find this file through an include path on rtl/ (Verilator -Irtl; yosys looks next to
// the including file).
`ifndef WATKINS_ASSERT_SVH
`define WATKINS_ASSERT_SVH

`ifndef SYNTHESIS
`ifndef WATKINS_NO_ASSERT

// Defined where the assertions are: modules keep their assertion-only probes behind it.
`define WATKINS_ASSERT_ON

// prop holds on every clock out of reset.
`define WATKINS_ASSERT(name, prop) \
  name: assert property (@(posedge clk_i) disable iff (!rst_ni) prop);

// prop happens at least once (a scenario the benches should reach).
`define WATKINS_COVER(name, prop) \
  name: cover property (@(posedge clk_i) disable iff (!rst_ni) prop);

// The valid/ready rule of one stream: a beat offered and not taken (valid, not ready) is offered
// again the next clock, unchanged. data is every payload signal of the stream, e.g. {x, y}.
`define WATKINS_ASSERT_HOLD(name, valid, ready, data) \
  `WATKINS_ASSERT(name, (valid) && !(ready) |=> (valid) && $stable(data))

`endif
`endif

`ifndef WATKINS_ASSERT_ON
`define WATKINS_ASSERT(name, prop)
`define WATKINS_COVER(name, prop)
`define WATKINS_ASSERT_HOLD(name, valid, ready, data)
`endif
`endif

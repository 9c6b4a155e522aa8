// Co-simulation of the Phong top (watkins_top with Phong = 1: normalizer + phong_shader after the
// segment interpolator) against the bit-exact model, under random input gaps and back-pressure.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pipeline.hpp"
#include "prepare.hpp"
#include "rtl_bench.hpp"
#include "scene.hpp"

using namespace watkins;
using namespace watkins::tb;

namespace {

std::string report(const std::string& what, const RtlOptions& o, const RtlResult& r) {
  return what + " (seed " + std::to_string(o.seed) + ", gap " + std::to_string(o.gap) + ", stall " +
         std::to_string(o.stall) + ", stall burst " + std::to_string(o.stall_burst) + "):\n" + r.summary();
}

// A Gouraud-prepared scene turned into Phong records without scene preparation: each shade
// channel s (0..255 levels) becomes a normal component (s - 127.5) / 128 in [-1, 1), so the
// records are arbitrary (not unit, interpolating through zero) and test the datapath alone.
PreparedScene as_phong_records(PreparedScene p) {
  for (EdgeRecord& e : p.edges) {
    for (int c = fmt::ChanNx; c <= fmt::ChanNz; ++c) {
      e.value[c] = floor_shift(e.value[c] - (i64{255} << (fmt::FracBits - 1)), 7);
      e.slope[c] = floor_shift(e.slope[c], 7);
    }
    e.material = e.poly % 3;
  }
  p.shading = ShadingMode::Phong;
  p.materials = {QuantizedMaterial{{200, 120, 60}, 50, 200, 20}, QuantizedMaterial{{60, 200, 90}, 30, 128, 128},
                 QuantizedMaterial{{255, 255, 255}, 256, 511, 0}};
  p.light = {4000, 6000, -14000};  // roughly unit, towards the viewer, up and right
  p.eye = {0, 0, -16384};
  return p;
}

TEST(PhongCosim, DatapathOnArbitraryNormalRecords) {
  const PreparedScene p = as_phong_records(prepare(load_scene_or_default("")));
  const Image want = Pipeline().render(p);
  for (int k = 0; k < 4; ++k) {
    RtlOptions o;
    o.seed = 11 + k;
    o.gap = 0.15 * k;
    o.stall = 0.2 * k;
    o.stall_burst = k == 3 ? 100 : 1;
    o.sparse = k % 2;
    const RtlResult r = run_rtl(p, o, &want);
    EXPECT_TRUE(r.ok()) << report("default scene as Phong records", o, r);
    EXPECT_GT(r.stage_items, 0);
  }
}

}  // namespace

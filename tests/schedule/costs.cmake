# The tests that run 8 s or more, with their time in seconds (ctest's record of a run on this
# project's 2-core machine, Testing/Temporary/CTestCostData.txt), costliest first: ctest -j starts
# them in this order before the short ones. A test's time from an earlier run in the same build
# folder takes precedence over these.
set(_watkins_costs
  synth_seeds 127
  CosimConfigs.HermanLiuAtThePapersResolution 77
  icebreaker_board_build 93
  CosimDepthTie.ShippedScenesSubmissionOrder 38
  synth_smoke 28
  synth_options 25
  CosimSmoother.OverdrawPhong 19
  CosimHarness.PlainAndSystemCBenchesAgreeOnEveryCycle 18
  formal_self_test 16
  PhongCosim.DatapathOnArbitraryNormalRecords 11
  formal_proofs 9
  Size.CurvesConfigurationCoversTheShippedPatchScenes 9
  CosimConfigs.ShippedPatchScenesByCurves 9
  CycleModelStalled.SmoothedSphereTakesEqualRtl 8)
while(_watkins_costs)
  list(POP_FRONT _watkins_costs _name _cost)
  set_tests_properties(${_name} PROPERTIES COST ${_cost})
endwhile()

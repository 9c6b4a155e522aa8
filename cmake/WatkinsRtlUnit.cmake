# watkins_rtl_unit(<bench> TOP <module> SOURCES <rtl files...> [PARAMS Name=value ...] [LINK libs...]
#                  [BENCH <source.cpp>])
# Every discovered test carries the label "rtl" (one label: CMake 3.25's gtest_discover_tests
# writes a list of labels unquoted, so only the first of several would arrive).
# One GoogleTest bench around one Verilated RTL unit (--cc, -O3, --assert), linked with the
# bit-exact model so the bench compares the unit with its twin (tests/rtl); one Verilated model
# per unit top. SOURCES are relative to rtl/ unless absolute (simulation stand-ins of device
# primitives live in testbench/). Verilator searches rtl/ (-y) for the includes
# (watkins_assert.svh) and for any module SOURCES does not list (e.g. stall_pipe).
#
# PARAMS is the one source of the unit's parameter overrides: each Name=value goes to Verilator
# as -GName=value and to the bench's C++ as the definition WATKINS_RTL_PARAM_Name=value, so a
# bench sizes itself from what the model was built with (e.g.
# `constexpr int MaxWidth = WATKINS_RTL_PARAM_MaxWidth;`). A leading -G is accepted and dropped.
# BENCH: the bench's source when it is not <bench>.cpp -- one bench built again for another
# configuration of its unit (its tests are then named <bench>.<Suite>.<Test>, so the two do not clash).
find_package(verilator HINTS $ENV{VERILATOR_ROOT} /usr/share/verilator)
find_package(GTest REQUIRED)
include(GoogleTest)
include(${CMAKE_CURRENT_LIST_DIR}/WatkinsVerilated.cmake)

# The Verilator runtime every unit bench links, compiled once: the benches' models are all plain
# --cc models without tracing or SystemC, so they take the same runtime objects (verilate() would
# compile verilated.cpp and verilated_threads.cpp again for each bench, 7 s of the 18 s a small
# unit's build takes).
if(NOT TARGET watkins_rtl_unit_runtime)
  add_library(watkins_rtl_unit_runtime STATIC ${VERILATOR_ROOT}/include/verilated.cpp
              ${VERILATOR_ROOT}/include/verilated_threads.cpp ${VERILATOR_ROOT}/include/verilated_dpi.cpp)
  target_include_directories(watkins_rtl_unit_runtime PUBLIC ${VERILATOR_ROOT}/include ${VERILATOR_ROOT}/include/vltstd)
  target_compile_definitions(watkins_rtl_unit_runtime PUBLIC
    VM_COVERAGE=0 VM_SC=0 VM_TRACE=0 VM_TRACE_FST=0 VM_TRACE_VCD=0)
  target_compile_options(watkins_rtl_unit_runtime PRIVATE -O3)
  target_link_libraries(watkins_rtl_unit_runtime PUBLIC Threads::Threads)
endif()

function(watkins_rtl_unit bench)
  cmake_parse_arguments(U "" "TOP;BENCH" "SOURCES;PARAMS;LINK" ${ARGN})
  set(prefix "")
  if(U_BENCH)
    set(prefix "${bench}.")
  else()
    set(U_BENCH ${bench}.cpp)
  endif()
  add_executable(${bench} ${CMAKE_CURRENT_SOURCE_DIR}/${U_BENCH})
  target_include_directories(${bench} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_SOURCE_DIR}/tests/rtl
                             ${CMAKE_SOURCE_DIR}/testbench)
  target_link_libraries(${bench} PRIVATE ${U_LINK} watkins_prepare GTest::gtest_main)
  target_compile_options(${bench} PRIVATE -O3)
  set(vparams "")
  foreach(p ${U_PARAMS})
    string(REGEX REPLACE "^-G" "" p "${p}")
    if(NOT p MATCHES "^([A-Za-z_][A-Za-z0-9_]*)=(.+)$")
      message(FATAL_ERROR "watkins_rtl_unit(${bench}): PARAMS expects Name=value, got '${p}'")
    endif()
    list(APPEND vparams -G${p})
    target_compile_definitions(${bench} PRIVATE WATKINS_RTL_PARAM_${CMAKE_MATCH_1}=${CMAKE_MATCH_2})
  endforeach()
  set(srcs ${CMAKE_SOURCE_DIR}/rtl/watkins_pkg.sv)
  foreach(s ${U_SOURCES})
    if(IS_ABSOLUTE "${s}")
      list(APPEND srcs ${s})
    else()
      list(APPEND srcs ${CMAKE_SOURCE_DIR}/rtl/${s})
    endif()
  endforeach()
  watkins_verilate(${bench}
    SOURCES ${srcs}
    TOP_MODULE ${U_TOP}
    PREFIX V${U_TOP}
    OPT_FAST -O3
    VERILATOR_ARGS -O3 --x-assign fast --x-initial fast --assert -Wno-fatal -y ${CMAKE_SOURCE_DIR}/rtl
                   ${vparams})
  # The runtime from watkins_rtl_unit_runtime instead of the copy verilate() adds.
  get_target_property(bench_sources ${bench} SOURCES)
  list(FILTER bench_sources EXCLUDE REGEX "^${VERILATOR_ROOT}/include/.*\\.cpp$")
  set_property(TARGET ${bench} PROPERTY SOURCES ${bench_sources})
  target_link_libraries(${bench} PRIVATE watkins_rtl_unit_runtime)
  gtest_discover_tests(${bench} TEST_PREFIX "${prefix}" DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600 LABELS rtl)
endfunction()

# watkins_rtl_unit(<bench> TOP <module> SOURCES <rtl files...> [PARAMS -Gx=y ...] [LABELS l...])
# One GoogleTest bench around one Verilated RTL unit (--cc, -O3, --assert), linked with the
# bit-exact model so the bench compares the unit with its twin. Shared by tests/rtl and
# tests/phong; one Verilated model per unit top. Verilator searches rtl/ (-y) for the includes
# (watkins_assert.svh) and for any module SOURCES does not list (e.g. stall_pipe).
find_package(verilator HINTS $ENV{VERILATOR_ROOT} /usr/share/verilator)
find_package(GTest REQUIRED)
include(GoogleTest)

function(watkins_rtl_unit bench)
  cmake_parse_arguments(U "" "TOP" "SOURCES;PARAMS;LABELS" ${ARGN})
  add_executable(${bench} ${CMAKE_CURRENT_SOURCE_DIR}/${bench}.cpp)
  target_include_directories(${bench} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_SOURCE_DIR}/tests/rtl
                             ${CMAKE_SOURCE_DIR}/testbench)
  target_link_libraries(${bench} PRIVATE watkins_model GTest::gtest_main)
  target_compile_options(${bench} PRIVATE -O3)
  set(srcs ${CMAKE_SOURCE_DIR}/rtl/watkins_pkg.sv)
  foreach(s ${U_SOURCES})
    list(APPEND srcs ${CMAKE_SOURCE_DIR}/rtl/${s})
  endforeach()
  verilate(${bench}
    SOURCES ${srcs}
    TOP_MODULE ${U_TOP}
    PREFIX V${U_TOP}
    OPT_FAST -O3
    VERILATOR_ARGS -O3 --x-assign fast --x-initial fast --assert -Wno-fatal -y ${CMAKE_SOURCE_DIR}/rtl
                   ${U_PARAMS})
  if(NOT U_LABELS)
    set(U_LABELS rtl)
  endif()
  gtest_discover_tests(${bench} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600 LABELS "${U_LABELS}")
endfunction()

# Compiler flags shared by every yardsim target. One C++ standard and one -march setting for
# every translation unit: mixing them breaks Eigen's alignment assumptions.
add_library(yardsim_flags INTERFACE)
target_compile_features(yardsim_flags INTERFACE cxx_std_20)
target_compile_options(yardsim_flags INTERFACE
  $<BUILD_INTERFACE:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wconversion -Wno-sign-conversion>
  $<BUILD_INTERFACE:$<$<BOOL:${YARDSIM_WERROR}>:-Werror>>
  # GCC 12 reports false -Wrestrict positives inside std::string concatenation at -O3 (GCC bug 105329)
  $<BUILD_INTERFACE:$<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>>
  # Through a precompiled header GCC 12 no longer treats libstdc++'s inlined string code as a
  # system header's and reports its known false -Warray-bounds / -Wstringop-overflow inside
  # std::string in about 15 files; clang's -Warray-bounds and ASan (CI's fuzz build) remain
  $<BUILD_INTERFACE:$<$<AND:$<CXX_COMPILER_ID:GNU>,$<BOOL:${YARDSIM_PCH}>>:-Wno-array-bounds;-Wno-stringop-overflow>>)
if(YARDSIM_NATIVE)
  target_compile_options(yardsim_flags INTERFACE -march=native)
endif()
if(YARDSIM_SANITIZE)
  # ASan + UBSan; with YARDSIM_FUZZ also libFuzzer's coverage (clang only; the fuzz targets add
  # -fsanitize=fuzzer in tests/fuzz), so one instrumented build serves the tests and the fuzzer.
  # YARDSIM_NO_FLATTEN: no [[gnu::flatten]] (dynamics/flatten.hpp), whose inlining makes the
  # instrumented kernels slow to compile and no faster to run.
  if(YARDSIM_FUZZ AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "YARDSIM_FUZZ needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++-14")
  endif()
  target_compile_options(yardsim_flags INTERFACE
    $<BUILD_INTERFACE:-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all>
    $<BUILD_INTERFACE:$<$<BOOL:${YARDSIM_FUZZ}>:-fsanitize=fuzzer-no-link>>)
  target_compile_definitions(yardsim_flags INTERFACE $<BUILD_INTERFACE:YARDSIM_NO_FLATTEN>)
  target_link_options(yardsim_flags INTERFACE
    $<BUILD_INTERFACE:-fsanitize=address,undefined>)
endif()
install(TARGETS yardsim_flags EXPORT yardsimTargets)

# The standard headers most translation units include, precompiled with Eigen per layer and with
# Catch2 for the tests (YARDSIM_PCH): parsing was most of a test file's time (docs/robustness.md
# "CI time"). Only headers whose meaning no macro of ours changes belong here.
set(YARDSIM_PCH_STD_HEADERS <algorithm> <array> <cmath> <cstddef> <functional> <map> <memory>
  <optional> <sstream> <stdexcept> <string> <utility> <vector>)

# yardsim_layer(NAME SOURCES... [DEPENDS targets...])
# One library per layer folder, exported as yardsim::NAME. Headers sit next to the sources and
# are included as "NAME/file.hpp" (build tree: the source root; install tree: include/yardsim).
function(yardsim_layer name)
  cmake_parse_arguments(L "" "" "SOURCES;DEPENDS" ${ARGN})
  if(L_SOURCES)
    add_library(yardsim_${name} ${L_SOURCES})
    set(scope PUBLIC)
  else()
    add_library(yardsim_${name} INTERFACE)
    set(scope INTERFACE)
  endif()
  add_library(yardsim::${name} ALIAS yardsim_${name})
  set_target_properties(yardsim_${name} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(yardsim_${name} ${scope}
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:include/yardsim>)
  target_link_libraries(yardsim_${name} ${scope} yardsim_flags ${L_DEPENDS})
  # (layer) => its precompiled header: the standard library, and Eigen above devs and dtss
  if(YARDSIM_PCH AND L_SOURCES)
    set(pch ${YARDSIM_PCH_STD_HEADERS})
    if(NOT name MATCHES "^(devs|dtss)$")
      list(APPEND pch <Eigen/Dense>)
    endif()
    target_precompile_headers(yardsim_${name} PRIVATE ${pch})
  endif()
  install(TARGETS yardsim_${name} EXPORT yardsimTargets
    ARCHIVE DESTINATION lib LIBRARY DESTINATION lib)
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION include/yardsim/${name}
    FILES_MATCHING PATTERN "*.hpp")
endfunction()

# yardsim_module(NAME OWNER SOURCE DEFINE LIBS...) — a heavy dependency kept out of start-up: in
# a shared build SOURCE is the module libyardsim_NAME.so, built beside OWNER's library, installed
# beside it and opened by OWNER when first needed (output/module_loader.hpp); in a static build
# SOURCE is compiled into OWNER with DEFINE and LIBS linked in.
function(yardsim_module name owner source define)
  if(BUILD_SHARED_LIBS)
    add_library(yardsim_${name} MODULE ${source})
    target_link_libraries(yardsim_${name} PRIVATE yardsim_flags ${ARGN})
    target_include_directories(yardsim_${name} PRIVATE ${PROJECT_SOURCE_DIR})
    if(NOT YARDSIM_SANITIZE)
      target_link_options(yardsim_${name} PRIVATE -Wl,--no-undefined)
    endif()
    add_dependencies(${owner} yardsim_${name})
    install(TARGETS yardsim_${name} LIBRARY DESTINATION lib)
  else()
    target_sources(${owner} PRIVATE ${source})
    target_link_libraries(${owner} PRIVATE ${ARGN})
    target_compile_definitions(${owner} PRIVATE ${define})
  endif()
endfunction()

# yardsim_test_flags(TARGET) — what every test translation unit is compiled with: the tests'
# folder on the include path, the source and build folders (yardsim_test_paths: compiled into
# one library, not into each test file's flags, so that the files compile to the same objects in
# any checkout and .ci/run's compiler cache serves them), and -O1 in a Release build (the test
# code asserts; the layers it drives stay at -O3: about a third less compile time per test file)
function(yardsim_test_flags name)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_link_libraries(${name} PRIVATE yardsim_test_paths)
  target_compile_options(${name} PRIVATE $<$<CONFIG:Release>:-O1>)
endfunction()

# yardsim_test(NAME SOURCE... LIBS...) — one Catch2 executable per test file.
function(yardsim_test name)
  cmake_parse_arguments(T "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBS} Catch2::Catch2WithMain)
  yardsim_test_flags(${name})
  # Catch2, Eigen and the standard library parsed once for all tests, with the scene's headers
  # for those that link yardsim::studies (tests/CMakeLists.txt)
  if(TARGET yardsim_test_pch_scene AND "yardsim::studies" IN_LIST T_LIBS)
    target_precompile_headers(${name} REUSE_FROM yardsim_test_pch_scene)
  elseif(TARGET yardsim_test_pch)
    target_precompile_headers(${name} REUSE_FROM yardsim_test_pch)
  endif()
  # The sanitizer build registers every test but the long integration runs tagged [long] (whole
  # example operations, restarts, long lumped-line and panel runs: 20-100 times slower there;
  # the Release suite runs them all). docs/robustness.md
  set(spec)
  if(YARDSIM_SANITIZE)
    set(spec TEST_SPEC "~[long]")
  endif()
  # --warn NoTests: a test whose name Catch cannot match fails instead of passing empty
  catch_discover_tests(${name} ${spec} EXTRA_ARGS --warn NoTests PROPERTIES TIMEOUT 300)
endfunction()

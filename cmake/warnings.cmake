# Project-wide compile options, applied to every target by linking rkpm_options.
add_library(rkpm_options INTERFACE)
# The warnings are the project's own: a program built against the installed library
# does not inherit them.
target_compile_options(rkpm_options INTERFACE
  $<BUILD_INTERFACE:-Wall -Wextra -Wpedantic $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local> -Wnon-virtual-dtor>)
# GCC notes that a function returning a 32-byte generic vector (rk/row_lanes.hpp) has
# another ABI with AVX than without. Those functions are inline and never cross a
# library boundary, so the note is noise.
target_compile_options(rkpm_options INTERFACE $<BUILD_INTERFACE:$<$<CXX_COMPILER_ID:GNU>:-Wno-psabi>>)
if(RKPM_NATIVE)
  target_compile_options(rkpm_options INTERFACE $<BUILD_INTERFACE:-march=native>)
endif()
# No fused multiply-adds made by the compiler: a sum must round the same whether a
# contribution is added where it is computed or recorded and added later (the ordered
# scatter, rk/row_scatter.hpp), which is what makes runs on any thread and rank count
# give the same bits. Only matters where the target has FMA (RKPM_NATIVE).
target_compile_options(rkpm_options INTERFACE $<BUILD_INTERFACE:-ffp-contract=off>)
if(RKPM_SANITIZE)
  # -O1 keeps the sanitized Debug build (assertions and debug information on) fast
  # enough to run the whole suite, which includes 30,000-particle clouds.
  target_compile_options(rkpm_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                         -fno-sanitize-recover=undefined -O1)
  target_link_options(rkpm_options INTERFACE -fsanitize=address,undefined)
endif()
if(RKPM_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "RKPM_FUZZ=ON needs clang (CXX=clang++): libFuzzer is part of clang")
  endif()
  # Coverage instrumentation for libFuzzer on every library; the fuzz programs
  # add -fsanitize=fuzzer (libFuzzer's main) when they link.
  target_compile_options(rkpm_options INTERFACE -fsanitize=fuzzer-no-link,address,undefined
                         -fno-omit-frame-pointer -fno-sanitize-recover=undefined -g)
  target_link_options(rkpm_options INTERFACE -fsanitize=address,undefined)
endif()
target_link_libraries(rkpm_options INTERFACE OpenMP::OpenMP_CXX Eigen3::Eigen fmt::fmt)

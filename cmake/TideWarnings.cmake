# Compiler flags shared by every TideSPH target.
add_library(tide_warnings INTERFACE)
target_compile_options(tide_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic>
  $<$<AND:$<BOOL:${TIDE_WERROR}>,$<CXX_COMPILER_ID:GNU,Clang>>:-Werror>)
if(TIDE_SANITIZE)
  target_compile_options(tide_warnings INTERFACE
    -fsanitize=${TIDE_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  target_link_options(tide_warnings INTERFACE -fsanitize=${TIDE_SANITIZE})
endif()

# std::sqrt without errno: otherwise every square root carries a test and a call for negative
# arguments, which also stops the pair loops from vectorising. TideSPH never reads errno.
# -fno-trapping-math: TideSPH never unmasks floating-point exceptions, so the compiler may turn a
# choice between computed values (a kernel's pieces) into a blend; without it GCC keeps the
# branch and the pair loop does not vectorise. Neither flag changes a rounded result.
target_compile_options(tide_warnings INTERFACE $<$<CXX_COMPILER_ID:GNU,Clang>:-fno-math-errno -fno-trapping-math>)

# RelWithDebInfo is the profiling build: Release's -O3 with debug information and frame pointers,
# so that `perf record -g` unwinds through the passes cheaply (docs/performance.md, "Profiling").
target_compile_options(tide_warnings INTERFACE
  $<$<AND:$<CONFIG:RelWithDebInfo>,$<CXX_COMPILER_ID:GNU,Clang>>:-O3 -fno-omit-frame-pointer -mno-omit-leaf-frame-pointer>)

# Instruction set of the hot loops: empty keeps the compiler's default (x86-64: SSE2); e.g.
# "native" or "x86-64-v3" (AVX2) lets the vectorised loops use wider registers. Without
# contraction into fused multiply-adds (which GCC would otherwise do where FMA exists), every
# expression rounds as in the default build, so the choice changes speed, not results.
set(TIDE_ARCH "" CACHE STRING "Passed as -march= to every TideSPH target (empty: the compiler's default)")
if(TIDE_ARCH)
  target_compile_options(tide_warnings INTERFACE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-march=${TIDE_ARCH} -ffp-contract=off>)
endif()

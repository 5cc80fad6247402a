# Sanitizer and fuzzer builds (docs/robustness.md).
#
# VISCOR_SANITIZE=ON compiles and links everything with AddressSanitizer and
# UndefinedBehaviorSanitizer; -fno-sanitize-recover=all makes the first report end
# the program (the test fails) instead of printing and going on. Meant for its own
# build folder (tools/sanitizer_suite.sh uses build-sanitize), never for a release.
#
# VISCOR_BUILD_FUZZERS=ON builds the libFuzzer targets of tests/fuzz/ (clang only:
# -fsanitize=fuzzer is clang's), themselves with ASan and UBSan.
option(VISCOR_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer (halt on the first report)" OFF)
option(VISCOR_BUILD_FUZZERS "Build the libFuzzer targets of tests/fuzz (needs clang)" OFF)

set(VISCOR_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
if(VISCOR_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "VISCOR_SANITIZE=ON needs GCC or clang (got ${CMAKE_CXX_COMPILER_ID})")
  endif()
  add_compile_options(${VISCOR_SANITIZE_FLAGS})
  add_link_options(${VISCOR_SANITIZE_FLAGS})
  # -O0 after the build type's -O3 (the last one counts): instrumented, GCC compiles
  # the library's templates in 2.2 times the normal -O3 time at -O0, 4.1 times at
  # -O1, while a solve runs only about 2 times slower at -O0 than at -O1
  # (docs/robustness.md). NDEBUG off: the library's assertions are checks too.
  add_compile_options(-O0 -UNDEBUG)
endif()
if(VISCOR_BUILD_FUZZERS AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "VISCOR_BUILD_FUZZERS=ON needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++ "
                      "(Debian: apt-get install clang libclang-rt-14-dev)")
endif()

# rockfall::options: language standard and warnings, linked PRIVATE by every target.
add_library(rockfall_options INTERFACE)
add_library(rockfall::options ALIAS rockfall_options)
target_compile_features(rockfall_options INTERFACE cxx_std_20)
target_compile_options(rockfall_options INTERFACE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
    $<$<BOOL:${ROCKFALL_WERROR}>:-Werror>)

# ROCKFALL_SANITIZE: every object and executable built with AddressSanitizer (with its leak
# checker) and UndefinedBehaviorSanitizer, and any finding made fatal, so that a test that
# touches freed memory or overflows fails rather than passing by luck. Set for the whole build
# rather than on rockfall::options because the tests, benchmarks and the program must all be
# instrumented and linked with the sanitizer runtimes. Slow (about 3x): use a build directory
# of its own; scripts/sanitize.sh builds and runs the suite this way (docs/sanitizers.md).
if(ROCKFALL_SANITIZE)
    add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
        -fno-omit-frame-pointer)
    add_link_options(-fsanitize=address,undefined)
endif()

# ROCKFALL_FUZZ: coverage instrumentation for libFuzzer on every object, so that the fuzz
# targets in fuzz/ are guided through the readers and everything they call; the targets link
# libFuzzer itself. clang only (Debian: clang and libclang-rt-14-dev). ROCKFALL_FUZZ_SANITIZE
# adds sanitizers to the same build, e.g. "address,undefined" (slower, finds more).
set(ROCKFALL_FUZZ_SANITIZE "" CACHE STRING
    "Sanitizers for the fuzz build (-fsanitize= list, e.g. address,undefined); empty: none")
if(ROCKFALL_FUZZ)
    if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
        message(FATAL_ERROR "ROCKFALL_FUZZ=ON needs clang (libFuzzer): configure with "
            "-DCMAKE_CXX_COMPILER=clang++ (scripts/fuzz.sh does)")
    endif()
    add_compile_options(-fsanitize=fuzzer-no-link -fno-omit-frame-pointer)
    if(ROCKFALL_FUZZ_SANITIZE)
        add_compile_options(-fsanitize=${ROCKFALL_FUZZ_SANITIZE} -fno-sanitize-recover=all)
        add_link_options(-fsanitize=${ROCKFALL_FUZZ_SANITIZE})
    endif()
endif()

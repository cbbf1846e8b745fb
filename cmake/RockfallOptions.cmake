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

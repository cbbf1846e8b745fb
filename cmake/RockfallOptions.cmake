# rockfall::options: language standard and warnings, linked PRIVATE by every target.
add_library(rockfall_options INTERFACE)
add_library(rockfall::options ALIAS rockfall_options)
target_compile_features(rockfall_options INTERFACE cxx_std_20)
target_compile_options(rockfall_options INTERFACE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
    $<$<BOOL:${ROCKFALL_WERROR}>:-Werror>)

# STC_BUILD_FUZZERS: every target of this build is compiled with libFuzzer's coverage hooks,
# AddressSanitizer and UndefinedBehaviorSanitizer (the fuzz targets of tests/fuzz link libFuzzer's
# main), so the fuzzer is guided by, and checks, the library code it drives. Included before the
# targets are defined; meant for a build folder of its own (scripts/fuzz.sh).
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "STC_BUILD_FUZZERS needs clang and libFuzzer: install the Debian packages "
                      "clang-14 and libclang-rt-14-dev and configure with "
                      "-DCMAKE_CXX_COMPILER=clang++-14")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer)
add_link_options(-fsanitize=address,undefined)

# Debian's toml++ is a shared library built without these hooks, which would leave the TOML parser
# dark to the fuzzer: compile it header-only into this build instead (TOML_HEADER_ONLY=1 replaces
# the package's -DTOML_HEADER_ONLY=0 -DTOML_SHARED_LIB=1; the library, still linked, goes unused).
set_target_properties(tomlplusplus::tomlplusplus PROPERTIES
                      INTERFACE_COMPILE_OPTIONS "-DTOML_HEADER_ONLY=1")

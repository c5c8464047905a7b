# Included by the top-level CMakeLists.txt before any target when AVC_FUZZ_ENABLED is ON: the
# whole build gets libFuzzer coverage, ASan and UBSan, so a bug in any library a parser calls is
# reported, not only in the fuzz targets themselves. Only the targets in fuzz/ link libFuzzer.
foreach(lang C CXX)
  if(NOT CMAKE_${lang}_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR
      "AVC_FUZZ_ENABLED needs clang (libFuzzer), but the ${lang} compiler is "
      "${CMAKE_${lang}_COMPILER_ID} ${CMAKE_${lang}_COMPILER}. Configure a separate build with\n"
      "  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14\n"
      "(scripts/fuzz does; apt-get install clang-14 libclang-rt-14-dev).")
  endif()
endforeach()

set(AVC_FUZZ_SANITIZERS address,undefined)
# -fno-sanitize-recover: UBSan aborts at the first report, so libFuzzer records it as a crash.
# Line tables only: symbolised stack traces without the cost of full debug info.
add_compile_options(-fsanitize=fuzzer-no-link,${AVC_FUZZ_SANITIZERS}
                    -fno-sanitize-recover=undefined -fno-omit-frame-pointer -gline-tables-only)
add_link_options(-fsanitize=${AVC_FUZZ_SANITIZERS})

# Run as `cmake -DFILE=<generated .hpp> -P AvcLcmBoundArrays.cmake` after lcm-gen.
# lcm-gen 1.3.1's decode resizes every variable-length array to the count it read before it
# checks that the bytes are there, so a message of a few bytes claiming 2^31 elements makes a
# receiver allocate and zero gigabytes (found by fuzz/lcm_messages). Every element takes at
# least one encoded byte, so a count above the bytes left cannot be valid: such a message is
# refused (-1) before anything is allocated. Likewise a string's length (which counts its NUL,
# so it is at least 1): lcm-gen checks only its upper bound, and a length of INT_MIN made
# `len - 1` overflow (undefined behaviour, also found by fuzz/lcm_messages). Valid messages
# decode exactly as before.
file(READ "${FILE}" text)
string(REGEX REPLACE
  "this->([A-Za-z0-9_]+)\\.resize\\(this->([A-Za-z0-9_]+)\\);"
  "if (this->\\2 < 0 || this->\\2 > maxlen - pos) return -1; this->\\1.resize(this->\\2);"
  bounded "${text}")
string(REGEX REPLACE
  "if\\((__[A-Za-z0-9_]+) > maxlen - pos\\) return -1;"
  "if(\\1 <= 0 || \\1 > maxlen - pos) return -1;"
  bounded "${bounded}")
if(bounded STREQUAL text AND text MATCHES "\\.resize\\(")
  message(FATAL_ERROR "${FILE}: lcm-gen's array decode changed; AvcLcmBoundArrays.cmake no "
                      "longer recognises it")
endif()
file(WRITE "${FILE}" "${bounded}")

# Strict warnings for rrc's own targets only (generated glad code and third-party headers are exempt).
# -Wmissing-field-initializers is off because GCC 12 flags C++20 designated initialisers that
# leave defaulted members out, which is exactly how rrc's descriptor structs are meant to be used.
function(rrc_strict_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Werror -Wno-missing-field-initializers)
endfunction()

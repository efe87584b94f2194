# Warnings are on everywhere and kept clean.
function(phasebox_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()

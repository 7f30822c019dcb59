# SPDX-License-Identifier: MIT
# `flange demo` end to end through the real executable: it must exit 0 and print the numbers the
# README promises (the comparison with the thesis's chain and its ratio, the aliasing of the
# wheelset's lateral mode at 6 Hz against sampling faster and decimating, the blind diagnosis,
# the float-to-RTL gap, the whole locomotive's worst wheel, the fleet's wear table). Run as:
# cmake -DFLANGE=<flange> -DOUT=<folder> -P check_demo.cmake
execute_process(COMMAND ${FLANGE} demo --out ${OUT}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "flange demo exited ${status}\n${out}\n${err}")
endif()
set(expected
    "ratio thesis / this project after filtering: [0-9]+\\.[0-9]+"
    "MAE before +MAE after"
    "lateral mode of the wheelset: [0-9]+\\.[0-9]+ Hz"
    "sampled at 6 Hz it aliases to [0-9]+\\.[0-9]+ Hz"
    "RMS [0-9]+\\.[0-9]+ mm \\([0-9]+\\.[0-9]+ times smaller\\)"
    "verdict: explained by temp_offset_drift"
    "== 8\\. The gap one layer down"
    "rtl checked against the model on every channel: 0 mismatches"
    "worst wheel: channel [0-9]+ \\(axle [1-6] (left|right)\\)"
    "wear: 24 wheels from sqlite:")
foreach(pattern IN LISTS expected)
  if(NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "flange demo output lacks /${pattern}/:\n${out}")
  endif()
endforeach()
message(STATUS "flange demo: exit 0, every expected figure printed")

# ctest driver: DEMO in a GLFW window under xvfb-run (XVFB_RUN), mode MODE, 3 frames; checks the
# exit code and the --json report ("windowed": true, "gl_errors": 0).
if(NOT XVFB_RUN)
  message("SKIPPED: no xvfb-run (install xvfb)")
  return()
endif()
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 640x480x24" ${DEMO} --backend glfw --size 320x240 --frames 3
                        --warmup 1 --mode ${MODE} --json
                OUTPUT_VARIABLE report ERROR_VARIABLE log RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${DEMO} --mode ${MODE} in a window exited with ${rc}:\n${log}")
endif()
string(JSON windowed ERROR_VARIABLE error GET "${report}" windowed)
if(error OR NOT windowed)
  message(FATAL_ERROR "${DEMO}: not windowed (${error}); report: ${report}")
endif()
string(JSON errors GET "${report}" gl_errors)
string(JSON frames GET "${report}" gui_frames)
if(NOT errors EQUAL 0 OR frames LESS 3)
  message(FATAL_ERROR "${DEMO}: ${errors} GL errors, ${frames} overlay frames; report: ${report}")
endif()
message("${DEMO} --mode ${MODE}: windowed, ${frames} frames with the overlay, no GL error")

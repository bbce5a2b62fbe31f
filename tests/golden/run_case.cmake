# ctest driver of one golden-frame case: render with the demo into WORK, compare with REFERENCE.
# Variables: DEMO (executable), ARGS (;-list), IMAGES (,-list of files the demo writes),
# REFERENCE (folder of the references), COMPARE (rrc-golden-compare), WORK (scratch folder, kept
# for inspection), BACKEND. Every image is compared, then the test fails if any differed.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${DEMO} --backend ${BACKEND} --out ${WORK} ${ARGS} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "golden: ${DEMO} ${ARGS} exited with ${rc}")
endif()
string(REPLACE "," ";" images "${IMAGES}")
get_filename_component(case ${REFERENCE} NAME)
set(failed "")
foreach(image IN LISTS images)
  if(NOT EXISTS ${REFERENCE}/${image})
    message(SEND_ERROR "golden: no reference ${REFERENCE}/${image}; review ${WORK}/${image}, then scripts/update-golden ${case}")
    continue()
  endif()
  get_filename_component(stem ${image} NAME_WE)
  execute_process(COMMAND ${COMPARE} ${REFERENCE}/${image} ${WORK}/${image} --diff ${WORK}/${stem}_diff.png
    RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    list(APPEND failed ${image})
  endif()
endforeach()
if(failed)
  message(FATAL_ERROR "golden: ${case} on ${BACKEND}: ${failed} differ from the references (frames and difference images in ${WORK})")
endif()

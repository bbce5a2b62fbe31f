# rrc_extract_doc_code(MARKDOWN OUT_DIR GLSL_VAR): at configure time, writes the ```cpp blocks of
# MARKDOWN into OUT_DIR/doc_example.cpp and each ```glsl block into its named file (see
# scripts/extract-doc-code.py), so documentation code is compiled and tested. Re-runs whenever
# the markdown changes.
function(rrc_extract_doc_code markdown out_dir glsl_var)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${markdown})
  execute_process(
    COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/extract-doc-code.py ${markdown} ${out_dir}
    OUTPUT_VARIABLE files RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "extracting code from ${markdown} failed: ${err}")
  endif()
  string(STRIP "${files}" files)
  string(REPLACE "\n" ";" files "${files}")
  set(${glsl_var} ${files} PARENT_SCOPE)
endfunction()

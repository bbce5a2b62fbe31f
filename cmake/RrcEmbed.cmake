# rrc_embed_files(TARGET target FUNCTION ns::name BASE dir FILES f1 f2 ...)
# Compiles the files into `target` as a function `std::span<const rrc::EmbeddedFile> ns::name()`;
# each file is named by its path relative to BASE, so composer includes and error messages use
# the real file names.
set(RRC_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/RrcEmbedScript.cmake)

function(rrc_embed_files)
  cmake_parse_arguments(E "" "TARGET;FUNCTION;BASE" "FILES" ${ARGN})
  string(MAKE_C_IDENTIFIER "${E_FUNCTION}" id)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/embedded_${id}.cpp)
  set(abs_files)
  foreach(f IN LISTS E_FILES)
    get_filename_component(a ${f} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    list(APPEND abs_files ${a})
  endforeach()
  string(REPLACE ";" "|" joined "${abs_files}")
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DFUNCTION=${E_FUNCTION} -DBASE=${E_BASE} "-DFILES=${joined}"
            -P ${RRC_EMBED_SCRIPT}
    DEPENDS ${abs_files} ${RRC_EMBED_SCRIPT}
    COMMENT "Embedding ${E_FUNCTION}"
    VERBATIM)
  target_sources(${E_TARGET} PRIVATE ${out})
endfunction()

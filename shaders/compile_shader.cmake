# cmake -P helper: glslangValidator with warnings treated as errors, output as a C header.
# glslangValidator neither creates the output's folder nor fails when it cannot write the file
# (it prints ERROR and exits 0), so make the folder and treat ERROR as a failure too.
get_filename_component(output_dir ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${output_dir})
execute_process(
  COMMAND ${GLSLANG} --target-env vulkan1.2 -I${INCLUDE_DIR} --depfile ${DEPFILE} --vn ${VARIABLE}
          -o ${OUTPUT} ${SOURCE}
  RESULT_VARIABLE result
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
if(NOT result EQUAL 0 OR out MATCHES "WARNING|ERROR" OR err MATCHES "WARNING|ERROR")
  file(REMOVE ${OUTPUT})
  message(FATAL_ERROR "${out}${err}")
endif()

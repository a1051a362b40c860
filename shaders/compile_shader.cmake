# cmake -P helper: glslangValidator with warnings treated as errors, output as a C header.
execute_process(
  COMMAND ${GLSLANG} --target-env vulkan1.2 -I${INCLUDE_DIR} --depfile ${DEPFILE} --vn ${VARIABLE}
          -o ${OUTPUT} ${SOURCE}
  RESULT_VARIABLE result
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
if(NOT result EQUAL 0 OR out MATCHES "WARNING" OR err MATCHES "WARNING")
  file(REMOVE ${OUTPUT})
  message(FATAL_ERROR "${out}${err}")
endif()

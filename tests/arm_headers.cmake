# Compiles every public header on its own for a Cortex-M0+, the way firmware would build it.
file(MAKE_DIRECTORY ${OUT_DIR})
set(failed 0)
foreach(h IN LISTS HEADERS)
  string(MAKE_C_IDENTIFIER ${h} name)
  file(WRITE ${OUT_DIR}/${name}.cpp "#include <${h}>\n")
  execute_process(
    COMMAND ${CXX} -std=c++20 -mcpu=cortex-m0plus -mthumb -Os -fno-exceptions -fno-rtti
            -Wall -Wextra -Wpedantic -Werror -I${INCLUDE_DIR} -c ${OUT_DIR}/${name}.cpp
            -o ${OUT_DIR}/${name}.o
    RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(SEND_ERROR "arm-none-eabi-g++ failed on ${h}")
    set(failed 1)
  endif()
endforeach()
list(LENGTH HEADERS n)
if(failed)
  message(FATAL_ERROR "some headers do not compile for cortex-m0plus")
endif()
message(STATUS "${n} headers compile for cortex-m0plus")

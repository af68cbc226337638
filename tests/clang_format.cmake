# Fails when a C++ file of ours is not formatted with the root .clang-format.
file(GLOB_RECURSE files ${ROOT}/include/*.hpp ${ROOT}/tests/*.cpp ${ROOT}/tests/*.hpp
  ${ROOT}/examples/*.cpp ${ROOT}/examples/*.hpp ${ROOT}/tools/*.cpp ${ROOT}/tools/*.hpp ${ROOT}/bench/*.cpp ${ROOT}/fuzz/*.cpp ${ROOT}/fuzz/*.hpp
  ${ROOT}/wireshark/*.cpp ${ROOT}/wireshark/*.hpp ${ROOT}/python/*.cpp)
execute_process(COMMAND ${CLANG_FORMAT} --dry-run -Werror ${files} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "files above are not clang-formatted: run scripts/format.sh")
endif()

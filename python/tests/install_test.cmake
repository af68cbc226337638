# ctest python_install: the documented install (docs/python.md) into a scratch prefix, then the
# installed package alone (PYTHONPATH = its directory only, run from an empty directory) imports,
# decodes a frame and encodes one.
#   cmake -DBUILD_DIR=... -DPREFIX=... -DPYTHON=... -DINSTALL_DIR=... -P install_test.cmake
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --component python --prefix ${PREFIX}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install --component python failed")
endif()
if(IS_ABSOLUTE "${INSTALL_DIR}")
  set(site ${INSTALL_DIR})
else()
  set(site ${PREFIX}/${INSTALL_DIR})
endif()
file(MAKE_DIRECTORY ${PREFIX}/empty)
set(check [=[
import sys, powerkey
assert powerkey.__file__.startswith(sys.argv[1]), powerkey.__file__
m = powerkey.decode(0x195, bytes.fromhex("040000002A"), model="pkp2400")
f = powerkey.encode("led_on", model="pkp2400", green=m.pressed_keys())
print(powerkey.__file__, m.kind, m.to_dict(), hex(f.arbitration_id), bytes(f.data).hex())
]=])
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} PYTHONDONTWRITEBYTECODE=1
    ${PYTHON} -c "${check}" ${site}
  WORKING_DIRECTORY ${PREFIX}/empty RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed powerkey package does not import from ${site}")
endif()

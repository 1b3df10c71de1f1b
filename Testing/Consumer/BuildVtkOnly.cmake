# cmake -P script: configure, build and install the VTK-only mode of this
# source tree (the fixture of the consumer test when the plugin build was
# not given an installed VTK-only module through OSM_VTK_ONLY_PREFIX).
#   -DSOURCE_DIR=... -DBINARY_DIR=... -DINSTALL_PREFIX=... -DVTK_DIR=...
#   -DGENERATOR=... [-DMAKE_PROGRAM=...] [-DBUILD_TYPE=...]
foreach (var IN ITEMS SOURCE_DIR BINARY_DIR INSTALL_PREFIX VTK_DIR GENERATOR)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "BuildVtkOnly.cmake needs -D${var}=...")
  endif ()
endforeach ()
if (NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif ()
set(make_program_arg)
if (MAKE_PROGRAM)
  set(make_program_arg "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif ()

function (run)
  string(REPLACE ";" " " printable "${ARGN}")
  message(STATUS "${printable}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if (NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${printable}")
  endif ()
endfunction ()

run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${BINARY_DIR}" -G "${GENERATOR}"
  ${make_program_arg}
  "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
  -DOSM_BUILD_PARAVIEW_PLUGIN=OFF
  -DBUILD_TESTING=OFF
  "-DVTK_DIR=${VTK_DIR}"
  "-DCMAKE_INSTALL_PREFIX=${INSTALL_PREFIX}")
run("${CMAKE_COMMAND}" --build "${BINARY_DIR}" --parallel 2)
run("${CMAKE_COMMAND}" --install "${BINARY_DIR}")

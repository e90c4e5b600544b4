# Installs the library into a fresh prefix, builds the consumer project against it
# with find_package (shared and static), with pkg-config, and with -lOpenCRG, and
# runs each program.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
    if(rc)
        message(FATAL_ERROR "failed (${rc}): ${ARGN}")
    endif()
endfunction()
run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/lib-build" -DBUILD_TESTING=OFF -DCMAKE_INSTALL_PREFIX=${prefix})
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/lib-build")
run("${CMAKE_COMMAND}" --install "${WORK_DIR}/lib-build")
run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/c-tests/consumer" -B "${WORK_DIR}/consumer-build" -DCMAKE_PREFIX_PATH=${prefix})
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/consumer-build")
run("${WORK_DIR}/consumer-build/consumer_shared" "${ROAD}")
run("${WORK_DIR}/consumer-build/consumer_static" "${ROAD}")
# pkg-config and the reference library's link name
find_program(PKG_CONFIG pkg-config)
if(PKG_CONFIG)
    execute_process(COMMAND "${CMAKE_COMMAND}" -E env PKG_CONFIG_PATH=${prefix}/lib/pkgconfig "${PKG_CONFIG}" --cflags --libs opencrg
        OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
    if(rc)
        message(FATAL_ERROR "pkg-config does not know opencrg")
    endif()
    separate_arguments(flags UNIX_COMMAND "${flags}")
    run(cc "${SOURCE_DIR}/c-tests/consumer/main.c" ${flags} -lm -Wl,-rpath,${prefix}/lib -o "${WORK_DIR}/consumer_pkgconfig")
    run("${WORK_DIR}/consumer_pkgconfig" "${ROAD}")
endif()
run(cc "${SOURCE_DIR}/c-tests/consumer/main.c" -I${prefix}/include -L${prefix}/lib -lOpenCRG -lm -Wl,-rpath,${prefix}/lib
    -o "${WORK_DIR}/consumer_lOpenCRG")
run("${WORK_DIR}/consumer_lOpenCRG" "${ROAD}")
message(STATUS "consumer: find_package (shared, static), pkg-config and -lOpenCRG all built and ran")

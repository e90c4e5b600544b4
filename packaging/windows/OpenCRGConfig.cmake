# CMake package of the OpenCRG library for Windows (classic C API, header crgBaseLib.h),
# as the Windows zip lays it out: bin/opencrg.dll, lib/opencrg.lib (MSVC's linker),
# lib/libopencrg.dll.a and lib/libopencrg.a (MinGW), include/.
#
#   find_package(OpenCRG 2.0 REQUIRED)
#   target_link_libraries(app PRIVATE OpenCRG::OpenCRG)          # opencrg.dll
#   target_link_libraries(app PRIVATE OpenCRG::OpenCRG_static)   # MinGW only
#
# Windows looks for the DLL beside the program first: copy bin/opencrg.dll there, or
# put bin/ on PATH.
get_filename_component(_opencrg_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
set(OpenCRG_INCLUDE_DIR "${_opencrg_prefix}/include")
set(OpenCRG_LIBRARY_DIR "${_opencrg_prefix}/lib")
set(OpenCRG_DLL "${_opencrg_prefix}/bin/opencrg.dll")

if(NOT TARGET OpenCRG::OpenCRG)
    add_library(OpenCRG::OpenCRG SHARED IMPORTED)
    if(MSVC)
        set(_opencrg_implib "${OpenCRG_LIBRARY_DIR}/opencrg.lib")
    else()
        set(_opencrg_implib "${OpenCRG_LIBRARY_DIR}/libopencrg.dll.a")
    endif()
    set_target_properties(OpenCRG::OpenCRG PROPERTIES
        IMPORTED_LOCATION "${OpenCRG_DLL}"
        IMPORTED_IMPLIB "${_opencrg_implib}"
        INTERFACE_INCLUDE_DIRECTORIES "${OpenCRG_INCLUDE_DIR}")
endif()
# The static library is built with MinGW's runtime: for MinGW programs only.
if(NOT MSVC AND NOT TARGET OpenCRG::OpenCRG_static)
    add_library(OpenCRG::OpenCRG_static STATIC IMPORTED)
    set_target_properties(OpenCRG::OpenCRG_static PROPERTIES
        IMPORTED_LOCATION "${OpenCRG_LIBRARY_DIR}/libopencrg.a"
        INTERFACE_INCLUDE_DIRECTORIES "${OpenCRG_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "kernel32;ntdll;userenv;ws2_32;dbghelp")
endif()
set(OpenCRG_LIBRARIES OpenCRG::OpenCRG)
foreach(_opencrg_file "${OpenCRG_DLL}" "${_opencrg_implib}" "${OpenCRG_INCLUDE_DIR}/crgBaseLib.h")
    if(NOT EXISTS "${_opencrg_file}")
        set(OpenCRG_FOUND FALSE)
        set(OpenCRG_NOT_FOUND_MESSAGE "missing: ${_opencrg_file}")
    endif()
endforeach()

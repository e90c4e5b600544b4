# Writes OpenCRGConfigVersion.cmake for the Windows zip (same major version accepted).
#   cmake -DVERSION=2.0.1 -DCMAKE_SIZEOF_VOID_P=8 -DOUT=dir/OpenCRGConfigVersion.cmake -P version.cmake
# (the size of a pointer: a 32-bit project is told this 64-bit package does not fit).
include(CMakePackageConfigHelpers)
write_basic_package_version_file("${OUT}" VERSION "${VERSION}" COMPATIBILITY SameMajorVersion)

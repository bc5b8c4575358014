# The engine-free libraries (the layers are listed in CMakeLists.txt). A library sees the headers
# of the folders it owns and of the libraries it links, and no others: each folder is exposed
# through a directory of its own in the build tree holding one link to it, so `#include
# "renderers/..."` does not even resolve inside the core.

function(haptics_expose target scope folder)
  set(root "${CMAKE_BINARY_DIR}/include/${folder}")
  file(MAKE_DIRECTORY "${root}")
  # Made at every configure: a build tree reused after the sources moved follows them.
  file(CREATE_LINK "${CMAKE_CURRENT_SOURCE_DIR}/src/${folder}" "${root}/${folder}" SYMBOLIC)
  target_include_directories(${target} ${scope} "${root}")
endfunction()

# One static library per folder of src/, linking the libraries below it.
function(haptics_library target folder)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS src/${folder}/*.cpp)
  haptics_platform_filter(sources)
  add_library(${target} STATIC ${sources})
  haptics_expose(${target} PUBLIC ${folder})
  target_link_libraries(${target} PUBLIC ${ARGN})
endfunction()

haptics_library(haptics_core core Threads::Threads ${CMAKE_DL_LIBS} ${HAPTICS_CORE_SYSTEM_LIBS})
if(DBUS_FOUND)
  target_include_directories(haptics_core SYSTEM PRIVATE ${DBUS_INCLUDE_DIRS})
endif()
haptics_library(haptics_renderers renderers haptics_core)
# ${CMAKE_DL_LIBS}: the OpenHaptics backend dlopens the user's libHD at run time.
haptics_library(haptics_devices devices haptics_core ${HAPTICS_HIDAPI} ${HAPTICS_LIBUSB} ${CMAKE_DL_LIBS})
haptics_library(haptics_storage storage haptics_core)
haptics_library(haptics_system system haptics_core haptics_renderers haptics_devices)
if(HAPTICS_DEV_TOOLS OR HAPTICS_BUILD_TESTS OR HAPTICS_BUILD_BENCH)
  haptics_library(haptics_scripted dev_tools haptics_system haptics_devices)
endif()

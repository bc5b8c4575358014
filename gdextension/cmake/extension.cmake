# The Godot extension: the binding (src/binding) over the HapticsSystem, built into the addon's bin/.

# The binding compiles against the header of the very engine that will load it; it is
# dumped into the build tree at configure time and never committed.
set(GODOT_INTERFACE_DIR "${CMAKE_CURRENT_BINARY_DIR}/godot-interface")
set(GODOT_INTERFACE_HEADER "${GODOT_INTERFACE_DIR}/gdextension_interface.h")
if(NOT EXISTS "${GODOT_INTERFACE_HEADER}")
  file(MAKE_DIRECTORY "${GODOT_INTERFACE_DIR}")
  execute_process(
    COMMAND "${GODOT_RUNNER}" --headless --dump-gdextension-interface
    WORKING_DIRECTORY "${GODOT_INTERFACE_DIR}"
    RESULT_VARIABLE dump_result OUTPUT_QUIET ERROR_QUIET)
  if(NOT EXISTS "${GODOT_INTERFACE_HEADER}")
    message(FATAL_ERROR "Could not dump gdextension_interface.h with ${GODOT_RUNNER} "
      "(exit ${dump_result}). Configure with -DGODOT=/path/to/godot (a Godot 4.5+ binary), or with "
      "-DHAPTICS_BUILD_EXTENSION=OFF to build only the core and its tests.")
  endif()
endif()

# The class reference for the editor's help, embedded from doc_classes/*.xml.
file(GLOB HAPTICS_DOC_CLASSES CONFIGURE_DEPENDS doc_classes/*.xml)
set(HAPTICS_DOC_SOURCE "${CMAKE_CURRENT_BINARY_DIR}/doc_data.gen.cpp")
add_custom_command(
  OUTPUT "${HAPTICS_DOC_SOURCE}"
  COMMAND "${CMAKE_COMMAND}" -DDOC_DIR=${CMAKE_CURRENT_SOURCE_DIR}/doc_classes
    -DOUTPUT=${HAPTICS_DOC_SOURCE} -P ${CMAKE_CURRENT_SOURCE_DIR}/cmake/embed_docs.cmake
  DEPENDS ${HAPTICS_DOC_CLASSES} cmake/embed_docs.cmake
  COMMENT "Embedding the class reference (doc_classes)")

file(GLOB HAPTICS_BINDING_SOURCES CONFIGURE_DEPENDS src/binding/*.cpp)
add_library(haptics SHARED ${HAPTICS_BINDING_SOURCES} "${HAPTICS_DOC_SOURCE}")
haptics_expose(haptics PRIVATE binding)
target_include_directories(haptics PRIVATE "${GODOT_INTERFACE_DIR}")
target_link_libraries(haptics PRIVATE haptics_system haptics_storage)
# Development builds add the software device models at initialisation (register_types.cpp).
if(HAPTICS_DEV_TOOLS)
  target_link_libraries(haptics PRIVATE haptics_scripted)
  target_compile_definitions(haptics PRIVATE HAPTICS_DEV_TOOLS=1)
endif()
file(STRINGS "${HAPTICS_ADDON_DIR}/plugin.cfg" HAPTICS_VERSION_LINE REGEX "^version=")
string(REGEX REPLACE "^version=\"([^\"]+)\"$" "\\1" HAPTICS_VERSION "${HAPTICS_VERSION_LINE}")
if(NOT HAPTICS_VERSION MATCHES "^[0-9]+\\.[0-9]+\\.[0-9]+$")
  message(FATAL_ERROR "No version=\"X.Y.Z\" line in ${HAPTICS_ADDON_DIR}/plugin.cfg")
endif()
target_compile_definitions(haptics PRIVATE HAPTICS_VERSION="${HAPTICS_VERSION}")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${HAPTICS_ADDON_DIR}/plugin.cfg")
target_link_options(haptics PRIVATE -static-libstdc++ -static-libgcc -Wl,--no-undefined)
# A DLL is a runtime artefact to CMake, its import library an archive (kept out of the addon).
set_target_properties(haptics PROPERTIES
  OUTPUT_NAME "haptics.${HAPTICS_PLATFORM}.${HAPTICS_TARGET}.x86_64"
  PREFIX "lib"
  LIBRARY_OUTPUT_DIRECTORY "${HAPTICS_ADDON_DIR}/bin"
  RUNTIME_OUTPUT_DIRECTORY "${HAPTICS_ADDON_DIR}/bin"
  ARCHIVE_OUTPUT_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")

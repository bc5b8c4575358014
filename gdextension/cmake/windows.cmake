# The Windows build (cross-compiled with MinGW-w64, cmake/mingw-w64.cmake): hidapi, libusb and
# SDL 3 from Debian's source packages, built static by tools/windows/build-deps.sh into one
# install prefix, and the C++ and C runtimes linked in, so that the DLL needs nothing beside
# Windows' own DLLs (tools/windows/check-imports.sh checks its import table).
set(HAPTICS_WINDOWS_DEPS "" CACHE PATH "Prefix holding the static hidapi, libusb and SDL 3 for Windows")
foreach(library IN ITEMS hidapi usb-1.0)
  if(NOT EXISTS "${HAPTICS_WINDOWS_DEPS}/lib/lib${library}.a")
    message(FATAL_ERROR "No ${HAPTICS_WINDOWS_DEPS}/lib/lib${library}.a: configure with "
      "-DHAPTICS_WINDOWS_DEPS=<prefix> built by tools/windows/build-deps.sh (make build-windows)")
  endif()
endforeach()
add_library(haptics_windows_hidapi STATIC IMPORTED)
set_target_properties(haptics_windows_hidapi PROPERTIES
  IMPORTED_LOCATION "${HAPTICS_WINDOWS_DEPS}/lib/libhidapi.a"
  INTERFACE_INCLUDE_DIRECTORIES "${HAPTICS_WINDOWS_DEPS}/include/hidapi")
add_library(haptics_windows_libusb STATIC IMPORTED)
set_target_properties(haptics_windows_libusb PROPERTIES
  IMPORTED_LOCATION "${HAPTICS_WINDOWS_DEPS}/lib/libusb-1.0.a"
  INTERFACE_INCLUDE_DIRECTORIES "${HAPTICS_WINDOWS_DEPS}/include/libusb-1.0")
# SDL 3 (the SDL backend, devices/sdl: linked in here, sdl_library_windows.cpp), when the
# prefix has it; the Windows libraries its static archive needs are Windows' own (SDL's
# sdl3.pc lists them; dinput8's import library also holds DirectInput's data formats).
if(EXISTS "${HAPTICS_WINDOWS_DEPS}/lib/libSDL3.a")
  add_library(haptics_windows_sdl3 STATIC IMPORTED)
  set_target_properties(haptics_windows_sdl3 PROPERTIES
    IMPORTED_LOCATION "${HAPTICS_WINDOWS_DEPS}/lib/libSDL3.a"
    INTERFACE_LINK_LIBRARIES "kernel32;user32;gdi32;winmm;imm32;ole32;oleaut32;version;uuid;advapi32;setupapi;shell32;dinput8")
  set(HAPTICS_WINDOWS_SDL3_INCLUDES "${HAPTICS_WINDOWS_DEPS}/include")
endif()
set(HAPTICS_HIDAPI haptics_windows_hidapi)
set(HAPTICS_LIBUSB haptics_windows_libusb)
# The servo thread's timer and scheduling (realtime_windows.cpp): avrt for the multimedia
# class scheduler; winmm is not needed (the waitable timer is high-resolution by itself).
set(HAPTICS_CORE_SYSTEM_LIBS avrt)
# libstdc++, libgcc and winpthread (std::thread) inside every binary: no MinGW DLL to ship.
add_link_options(-static -static-libgcc -static-libstdc++)
# windows.h without its min/max macros (they break std::min) and its rarely used parts.
add_compile_definitions(NOMINMAX WIN32_LEAN_AND_MEAN)
# C99 printf (%zu, %lld) from MinGW rather than the old Microsoft runtime's.
add_compile_definitions(__USE_MINGW_ANSI_STDIO=1)
# Windows 10 and later: the high-resolution waitable timer and the thread stack limits
# (realtime_windows.cpp) are from its API.
add_compile_definitions(_WIN32_WINNT=0x0A00)

# Which sources each platform builds: the one place that decides it. Platform code lives in
# files named after their platform (foo_linux.cpp, foo_posix.cpp, foo_windows.cpp) and in the
# folders of Linux-only backends and tools (the evdev backend and its model, the kernel device
# makers: uhid, uinput, USB gadgets). haptics_platform_filter() drops the other platforms'
# sources from a list.
set(HAPTICS_LINUX_ONLY_PATTERN "/(devices|dev_tools)/evdev/|/dev_tools/(gadget|uhid|uinput)/|_(linux|posix)\\.cpp$")
set(HAPTICS_WINDOWS_ONLY_PATTERN "_windows\\.cpp$")
# HAPTICS_EVDEV: the evdev backend is built (the development tools' table of scripted
# devices lists its model only then).
if(WIN32)
  set(HAPTICS_PLATFORM_EXCLUDED "${HAPTICS_LINUX_ONLY_PATTERN}")
  set(HAPTICS_PLATFORM windows)
  add_compile_definitions(HAPTICS_EVDEV=0)
else()
  set(HAPTICS_PLATFORM_EXCLUDED "${HAPTICS_WINDOWS_ONLY_PATTERN}")
  set(HAPTICS_PLATFORM linux)
  add_compile_definitions(HAPTICS_EVDEV=1)
endif()

function(haptics_platform_filter list_var)
  set(kept ${${list_var}})
  list(FILTER kept EXCLUDE REGEX "${HAPTICS_PLATFORM_EXCLUDED}")
  set(${list_var} ${kept} PARENT_SCOPE)
endfunction()

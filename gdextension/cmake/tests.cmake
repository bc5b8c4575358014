# The doctest suite and the benchmarks, with the fake OpenHaptics runtime they load.

# A fake OpenHaptics runtime (libHD's C functions over a scripted device) that the tests
# and the device bench load through the backend's real dlopen path; a second build lacks
# hdScheduleAsynchronous for the missing-symbol path. Outside tests/ so the doctest glob
# does not compile it into haptics_tests.
file(GLOB FAKE_HD_SOURCES CONFIGURE_DEPENDS tests_support/fake_hd/*.cpp)
add_library(fake_hd SHARED ${FAKE_HD_SOURCES})
target_link_libraries(fake_hd PRIVATE Threads::Threads)
add_library(fake_hd_no_async SHARED ${FAKE_HD_SOURCES})
target_compile_definitions(fake_hd_no_async PRIVATE FAKE_HD_WITHOUT_SCHEDULE_ASYNCHRONOUS)
target_link_libraries(fake_hd_no_async PRIVATE Threads::Threads)
set(FAKE_HD_DEFINITIONS HAPTICS_FAKE_HD_PATH="$<TARGET_FILE:fake_hd>"
  HAPTICS_FAKE_HD_NO_ASYNC_PATH="$<TARGET_FILE:fake_hd_no_async>")

if(HAPTICS_BUILD_TESTS)
  if(CMAKE_CROSSCOMPILING)
    # doctest is one header; the host's package would add all of /usr/include to a foreign
    # build, so only its folder is exposed (a link in the build tree).
    find_path(HAPTICS_DOCTEST_INCLUDE doctest/doctest.h PATHS /usr/include NO_CMAKE_FIND_ROOT_PATH REQUIRED)
    file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/doctest-include")
    file(CREATE_LINK "${HAPTICS_DOCTEST_INCLUDE}/doctest" "${CMAKE_BINARY_DIR}/doctest-include/doctest" SYMBOLIC)
    add_library(doctest::doctest INTERFACE IMPORTED)
    set_target_properties(doctest::doctest PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${CMAKE_BINARY_DIR}/doctest-include")
  else()
    find_package(doctest REQUIRED)
    include(CTest)
    include(doctest)
  endif()
  file(GLOB_RECURSE HAPTICS_TEST_SOURCES CONFIGURE_DEPENDS tests/*.cpp)
  # Linux-only tests are the files named *_linux.cpp (cmake/platform.cmake): left out of the
  # Windows build, and listed from the Linux build (doctest's --source-file filter) to count
  # them (tools/windows/test.sh).
  haptics_platform_filter(HAPTICS_TEST_SOURCES)
  add_executable(haptics_tests ${HAPTICS_TEST_SOURCES})
  # The suites' own files are half of a build's compile time and gain nothing from the
  # optimiser or debug records: the libraries they test keep the build type's flags.
  if(NOT MSVC)
    target_compile_options(haptics_tests PRIVATE $<$<NOT:$<CONFIG:Debug>>:-O0 -g0>)
  endif()
  # Also reaches the binding's engine-free headers (src/binding/call_check.h).
  target_include_directories(haptics_tests PRIVATE tests)
  haptics_expose(haptics_tests PRIVATE binding)
  target_link_libraries(haptics_tests PRIVATE haptics_system haptics_storage haptics_scripted doctest::doctest)
  # Loaded at run time by path, not linked.
  add_dependencies(haptics_tests fake_hd fake_hd_no_async)
  target_include_directories(haptics_tests PRIVATE tests_support)
  target_compile_definitions(haptics_tests PRIVATE ${FAKE_HD_DEFINITIONS})
  # A cross-built suite cannot run here at build time (doctest_discover_tests runs it): the
  # Windows one is run under Wine by tools/windows/test.sh instead of CTest.
  if(NOT CMAKE_CROSSCOMPILING)
    # Every doctest runs with TMPDIR in the build tree (so a forgotten file never reaches /tmp)
    # and the fixture around them fails if anything was left there (cmake/check_scratch.cmake).
    set(HAPTICS_TEST_TMPDIR "${CMAKE_CURRENT_BINARY_DIR}/test-tmp")
    set(CHECK_SCRATCH ${CMAKE_CURRENT_SOURCE_DIR}/cmake/check_scratch.cmake)
    add_test(NAME scratch_setup COMMAND ${CMAKE_COMMAND} -DMODE=setup -DDIR=${HAPTICS_TEST_TMPDIR} -P ${CHECK_SCRATCH})
    add_test(NAME scratch_left_nothing COMMAND ${CMAKE_COMMAND} -DMODE=check -DDIR=${HAPTICS_TEST_TMPDIR} -P ${CHECK_SCRATCH})
    set_tests_properties(scratch_setup PROPERTIES FIXTURES_SETUP scratch)
    set_tests_properties(scratch_left_nothing PROPERTIES FIXTURES_CLEANUP scratch)
    add_test(NAME scratch_failing_test_cleans_up COMMAND ${CMAKE_COMMAND} -DMODE=failing
      -DDIR=${HAPTICS_TEST_TMPDIR}-failing -DTEST_BINARY=$<TARGET_FILE:haptics_tests> -P ${CHECK_SCRATCH})
    # A test whose name CTest cannot pass back to doctest (a ';' splits it) would run no case and
    # pass: running no case fails.
    doctest_discover_tests(haptics_tests PROPERTIES ENVIRONMENT "TMPDIR=${HAPTICS_TEST_TMPDIR}" FIXTURES_REQUIRED scratch
      FAIL_REGULAR_EXPRESSION "test cases: *0 [|]")
  endif()

  # Windows: a minimal GDExtension host that loads the DLL (tools/windows/test.sh).
  if(WIN32 AND HAPTICS_BUILD_EXTENSION)
    add_executable(haptics_load_host tests_support/load_host/load_host_windows.cpp)
    target_include_directories(haptics_load_host PRIVATE "${GODOT_INTERFACE_DIR}")
  endif()
  if(NOT WIN32)
    # The program the kernel tests boot a VM for (tools/kernel/run.sh): our device stack against
    # the VM's real drivers, the device models speaking through uhid, uinput and gadgets.
    file(GLOB HAPTICS_VM_TEST_SOURCES CONFIGURE_DEPENDS vm_tests/*.cpp)
    haptics_platform_filter(HAPTICS_VM_TEST_SOURCES)
    add_executable(haptics_vm_tests ${HAPTICS_VM_TEST_SOURCES})
    target_link_libraries(haptics_vm_tests PRIVATE haptics_system haptics_scripted)

    # What an unprivileged player's servo thread gets, with and without RealtimeKit
    # (tools/rt/test-rtkit.sh).
    add_executable(haptics_rt_probe rt_probe/rt_probe.cpp)
    target_link_libraries(haptics_rt_probe PRIVATE haptics_system)
  endif()
endif()

if(HAPTICS_BUILD_BENCH)
  file(GLOB HAPTICS_BENCH_SOURCES CONFIGURE_DEPENDS bench/*.cpp)
  if(HAPTICS_BENCH_SOURCES)
    add_executable(haptics_bench ${HAPTICS_BENCH_SOURCES})
    target_link_libraries(haptics_bench PRIVATE haptics_system)
  endif()
  # The servo next to cyclictest under idle, CPU and rendering load (bench/rt), on the same
  # workload as haptics_bench (servo_workload.cpp).
  file(GLOB HAPTICS_RT_BENCH_SOURCES CONFIGURE_DEPENDS bench/rt/*.cpp)
  add_executable(haptics_rt_bench ${HAPTICS_RT_BENCH_SOURCES} bench/servo_workload.cpp)
  target_link_libraries(haptics_rt_bench PRIVATE haptics_system)
  # One bench_<backend>.cpp per device backend, registered with HAPTICS_DEVICE_BENCH, on the
  # software models the doctests use.
  file(GLOB HAPTICS_DEVICE_BENCH_SOURCES CONFIGURE_DEPENDS bench/devices/*.cpp)
  add_executable(haptics_device_bench ${HAPTICS_DEVICE_BENCH_SOURCES})
  target_include_directories(haptics_device_bench PRIVATE tests)
  target_link_libraries(haptics_device_bench PRIVATE haptics_system haptics_scripted)
  add_dependencies(haptics_device_bench fake_hd)
  target_include_directories(haptics_device_bench PRIVATE tests_support)
  target_compile_definitions(haptics_device_bench PRIVATE ${FAKE_HD_DEFINITIONS})
endif()
